#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Regenerate the evidence tables of docs/footprint.md from the JSON that
each board build writes to build/<board>/evidence/ (size_report.cmake and
stack_report.py, run after every link by kestrel_board_evidence).

  footprint_table.py --doc docs/footprint.md [--check] [--host-instructions FILE] DIR...

--check leaves the document alone and exits 1, printing a diff, when its
tables differ from what the JSON says (CTest footprint_doc_matches_build,
label boards: the committed tables cannot go stale silently).

The tables go between marker comments in the document, which is otherwise
left alone:
  <!-- evidence:sizes -->  ...  <!-- /evidence:sizes -->   size and stack per image
  <!-- evidence:chains -->  ... <!-- /evidence:chains -->  deepest chain of step per image
  <!-- evidence:host -->  ...   <!-- /evidence:host -->    host instruction counts (only
                                                          rewritten with --host-instructions)
targets/evidence.sh calls it, and so does that CTest (which, run with
KESTREL_UPDATE_FOOTPRINT=1, rewrites the document instead of checking it).
"""

import argparse
import difflib
import glob
import json
import os
import re
import sys

ORDER = ["cortex-m4f", "cortex-m7", "cortex-m0plus", "riscv64-linux"]


def load(dirs):
    rows = []
    for d in dirs:
        for path in sorted(glob.glob(os.path.join(d, "*.size.json"))):
            with open(path) as f:
                size = json.load(f)
            stack_path = path[: -len(".size.json")] + ".stack.json"
            stack = None
            if os.path.exists(stack_path):
                with open(stack_path) as f:
                    stack = json.load(f)
            rows.append((size, stack))
    rows.sort(key=lambda r: (ORDER.index(r[0]["board"]) if r[0]["board"] in ORDER else 99, r[0]["label"]))
    return rows


def fmt_budget(value, budget):
    return "%d / %d" % (value, budget) if budget is not None else str(value)


def sizes_table(rows):
    out = ["| board | image | build | text (budget) | data (budget) | bss (budget) | flash = text + data "
           "| RAM = data + bss | stack of step (budget) | main stack (budget) | largest frame |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    for size, stack in rows:
        b = size.get("budget", {})
        step = "-" if not stack else fmt_budget(stack["step_bytes"], stack.get("budget"))
        main = "-" if not stack or not stack.get("main_stack") else \
            fmt_budget(stack["main_stack"]["bytes"], stack.get("main_budget"))
        frame = "-" if not stack else str(stack.get("max_frame", "-"))
        out.append("| %s | `%s` | %s | %s | %s | %s | %d | %d | %s | %s | %s |" % (
            size["board"], size["elf"], size["build_type"], fmt_budget(size["text"], b.get("text")),
            fmt_budget(size["data"], b.get("data")), fmt_budget(size["bss"], b.get("bss")),
            size["text"] + size["data"], size["data"] + size["bss"], step, main, frame))
    return "\n".join(out)


def chains_table(rows):
    out = []
    for size, stack in rows:
        if not stack:
            continue
        step = [r for r in stack["roots"] if "Tracker<>::step" in r["root"]]
        if not step:
            continue
        worst = max(step, key=lambda r: r["bytes"])
        out.append("%s (`%s`), %d bytes:\n" % (size["board"], size["elf"], worst["bytes"]))
        out.append("```")
        for c in worst["chain"]:
            out.append("%6d  %s" % (c["frame"], c["function"]))
        out.append("```\n")
        main = stack.get("main_stack")
        if main:
            out.append("Main stack %d bytes: thread chain from `%s` %d, then per handler one exception "
                       "entry of %d bytes (%s) and its chain:\n" % (
                           main["bytes"], main["thread_root"], main["thread"], main["exception_entry"],
                           main["rule"]))
            for h in main["handlers"]:
                named = ""
                if h["aliases"]:
                    named = ", also " + ", ".join("`%s`" % a for a in h["aliases"] if not a.startswith("_"))
                    if h["vectors"] > len(h["aliases"]) + 1:
                        named += " and the unused IRQs"
                out.append("- `%s` (%d vectors%s): %d + %d = %d" % (
                    h["handler"], h["vectors"], named, h["entry"], h["chain"], h["bytes"]))
            out.append("")
    return "\n".join(out).rstrip()


def replace(doc, name, body):
    pattern = re.compile(r"(<!-- evidence:%s -->\n).*?(<!-- /evidence:%s -->)" % (name, name), re.S)
    if not pattern.search(doc):
        raise SystemExit("footprint_table: markers <!-- evidence:%s --> ... <!-- /evidence:%s --> not found"
                         % (name, name))
    return pattern.sub(lambda m: m.group(1) + body + "\n" + m.group(2), doc)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--doc", required=True)
    ap.add_argument("--check", action="store_true", help="compare instead of rewrite; exit 1 on a difference")
    ap.add_argument("--host-instructions", help="output of host_sim/bench/check_instruction_budgets.py")
    ap.add_argument("dirs", nargs="+", help="build/<board>/evidence directories")
    args = ap.parse_args()
    rows = load(args.dirs)
    if not rows:
        raise SystemExit("footprint_table: no *.size.json in " + " ".join(args.dirs))
    with open(args.doc) as f:
        committed = f.read()
    doc = replace(committed, "sizes", sizes_table(rows))
    doc = replace(doc, "chains", chains_table(rows))
    if args.host_instructions:
        with open(args.host_instructions) as f:
            doc = replace(doc, "host", "```\n" + f.read().rstrip() + "\n```")
    if args.check:
        if doc == committed:
            print("footprint_table: the tables of %s match the build (%s)" % (args.doc, " ".join(args.dirs)))
            return 0
        sys.stdout.writelines(difflib.unified_diff(committed.splitlines(True), doc.splitlines(True),
                                                   args.doc + " (committed)", args.doc + " (this build)"))
        print("footprint_table: %s is stale. Rewrite it from this build with\n"
              "  KESTREL_UPDATE_FOOTPRINT=1 ctest --preset host-release -L boards\n"
              "(or targets/evidence.sh), then commit it with the change that moved the figures." % args.doc)
        return 1
    with open(args.doc, "w") as f:
        f.write(doc)
    return 0


if __name__ == "__main__":
    sys.exit(main())
