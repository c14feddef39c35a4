#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Put an SPDX licence line at the top of every source file Kestrel owns.

    python3 tools/spdx.py            insert the line where it is missing
    python3 tools/spdx.py --check    list files without it; exit 1 if any
    python3 tools/spdx.py --self-test

Source files are C/C++ (.hpp .cpp .h .c .cc, comment //), linker scripts
(.ld, /* */), CMake (CMakeLists.txt, .cmake, #), Python (.py, #)
and shell (.sh, or no extension with a sh/bash shebang, #); a configure_file
template (name.in) counts as the file it makes. Data, docs and
generated files (a "GENERATED" or "do not edit" note in their first lines:
the generator owns their text) are left alone. The line goes first, after a
shebang and a Python coding line when there are any. A file that already has
an SPDX-License-Identifier in its first lines is not touched, so running the
script again changes nothing.

Files are those git knows (tracked, plus untracked ones not ignored); outside
a git checkout every file under the root except build*/, results/ and
.git/. Standard library only.
"""
from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

LICENSE = "Apache-2.0"
TAG = "SPDX-License-Identifier:"
HEAD_LINES = 5  # where an existing SPDX line or a generated-file note is looked for

C_EXT = {".hpp", ".cpp", ".h", ".c", ".cc", ".hh", ".cxx", ".ipp", ".inl"}
HASH_EXT = {".py", ".sh", ".cmake"}
SKIP_DIRS = {".git", "results", "__pycache__"}

GENERATED = re.compile(r"\bGENERATED\b|(?i:do not edit)")
CODING = re.compile(r"^[ \t\f]*#.*?coding[:=][ \t]*[-_.a-zA-Z0-9]+")
SHELL_SHEBANG = re.compile(r"^#!.*\b(sh|bash|dash|python3?)\b")


def comment_for(path: Path, first_line: str) -> str | None:
    """The SPDX line for this file, or None if it is not a source file."""
    name = path.name
    if name.endswith(".in"):  # a configure_file template: as the file it makes
        path = path.with_suffix("")
        name = path.name
    if name == "CMakeLists.txt":
        return f"# {TAG} {LICENSE}"
    ext = path.suffix
    if ext in C_EXT:
        return f"// {TAG} {LICENSE}"
    if ext == ".ld":
        return f"/* {TAG} {LICENSE} */"
    if ext in HASH_EXT:
        return f"# {TAG} {LICENSE}"
    if ext == "" and SHELL_SHEBANG.match(first_line):
        return f"# {TAG} {LICENSE}"
    return None


def candidate_files(root: Path) -> list[Path]:
    try:
        out = subprocess.run(
            ["git", "-C", str(root), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
            check=True, capture_output=True).stdout
        names = sorted({n for n in out.decode().split("\0") if n})
        return [root / n for n in names if (root / n).is_file()]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for dirpath, dirnames, filenames in os.walk(root):
            dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and not d.startswith("build"))
            files += [Path(dirpath) / f for f in sorted(filenames)]
        return files


def read_text(path: Path) -> str | None:
    try:
        return path.read_bytes().decode("utf-8")
    except (UnicodeDecodeError, OSError):
        return None  # binary or unreadable: not a source file


def classify(path: Path) -> tuple[str, str | None, str]:
    """(state, spdx line, text) with state one of: skip, generated, ok, missing."""
    text = read_text(path)
    if text is None:
        return "skip", None, ""
    lines = text.splitlines(keepends=True)
    line = comment_for(path, lines[0] if lines else "")
    if line is None:
        return "skip", None, text
    head = "".join(lines[:HEAD_LINES])
    if TAG in head:
        return "ok", line, text
    if GENERATED.search(head):
        return "generated", line, text
    return "missing", line, text


def insert(text: str, line: str) -> str:
    lines = text.splitlines(keepends=True)
    newline = "\r\n" if lines and lines[0].endswith("\r\n") else "\n"
    at = 0
    if lines and lines[0].startswith("#!"):
        at = 1
    # PEP 263: a coding declaration must stay on line 1 or 2.
    if at < len(lines) and at <= 1 and CODING.match(lines[at]):
        at += 1
    if at > 0 and not lines[at - 1].endswith(("\n", "\r")):
        lines[at - 1] += newline
    lines.insert(at, line + newline)
    return "".join(lines)


def run(root: Path, check: bool, quiet: bool = False) -> int:
    missing = []
    for path in candidate_files(root):
        state, line, text = classify(path)
        if state != "missing":
            continue
        rel = path.relative_to(root)
        missing.append(rel)
        if not check:
            # Keep the file's mode (scripts stay executable): rewrite in place.
            with open(path, "w", encoding="utf-8", newline="") as f:
                f.write(insert(text, line))
            if not quiet:
                print(f"spdx: added to {rel}")
    if check and not quiet:
        for rel in missing:
            print(f"spdx: missing {TAG} in {rel}", file=sys.stderr)
        if missing:
            print(f"spdx: {len(missing)} file(s) without an SPDX line; run python3 tools/spdx.py", file=sys.stderr)
        else:
            print("spdx: every source file has its SPDX line")
    return 1 if check and missing else 0


def self_test() -> int:
    """Insert into a scratch tree of every case, then check, then re-run."""
    cases = {
        "a.hpp": ("// Header paragraph.\n#pragma once\n", f"// {TAG} {LICENSE}\n// Header paragraph.\n"),
        "b.py": ("#!/usr/bin/env python3\n# -*- coding: utf-8 -*-\nx = 1\n",
                 f"#!/usr/bin/env python3\n# -*- coding: utf-8 -*-\n# {TAG} {LICENSE}\nx = 1\n"),
        "run": ("#!/bin/sh\necho hi\n", f"#!/bin/sh\n# {TAG} {LICENSE}\necho hi\n"),
        "CMakeLists.txt": ("project(x)\n", f"# {TAG} {LICENSE}\nproject(x)\n"),
        "m.ld": ("MEMORY {}\n", f"/* {TAG} {LICENSE} */\nMEMORY {{}}\n"),
        "t.cmake": ("", f"# {TAG} {LICENSE}\n"),
        "v.hpp.in": ("#define V @V@\n", f"// {TAG} {LICENSE}\n#define V @V@\n"),
        "pc.cmake.in": ("@PACKAGE_INIT@\n", f"# {TAG} {LICENSE}\n@PACKAGE_INIT@\n"),
        "gen.hpp": ("// GENERATED by gen.py; do not edit.\n", "// GENERATED by gen.py; do not edit.\n"),
        "has.cpp": (f"// {TAG} MIT\nint x;\n", f"// {TAG} MIT\nint x;\n"),
        "data.csv": ("a,b\n", "a,b\n"),
        "notes.txt": ("hello\n", "hello\n"),
    }
    failures = []
    with tempfile.TemporaryDirectory() as d:
        root = Path(d)
        for name, (before, _) in cases.items():
            (root / name).write_text(before)
        if run(root, check=True, quiet=True) != 1:
            failures.append("--check passed on a tree with missing lines")
        run(root, check=False, quiet=True)
        for name, (_, after) in cases.items():
            got = (root / name).read_text()
            if not got.startswith(after):
                failures.append(f"{name}: got {got!r}, want it to start with {after!r}")
        if run(root, check=True, quiet=True) != 0:
            failures.append("--check failed after insertion")
        snapshot = {n: (root / n).read_text() for n in cases}
        run(root, check=False, quiet=True)
        if snapshot != {n: (root / n).read_text() for n in cases}:
            failures.append("a second run changed files (not idempotent)")
    for f in failures:
        print(f"spdx self-test: {f}", file=sys.stderr)
    print("spdx self-test: " + ("FAILED" if failures else "passed"))
    return 1 if failures else 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="list files without the line; exit 1 if any")
    ap.add_argument("--self-test", action="store_true", help="test the script on a scratch tree")
    ap.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent,
                    help="tree to process (default: the Kestrel checkout holding this script)")
    args = ap.parse_args()
    if args.self_test:
        return self_test()
    return run(args.root.resolve(), args.check)


if __name__ == "__main__":
    sys.exit(main())
