#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Instruction-count budgets of the core's step paths (docs/performance.md).

Runs kestrel-instr-count under valgrind --tool=callgrind, which dumps the
instructions of each measured path (collection is on only around the
measured calls), prints instructions per step for every filter and path
class, and fails when a path exceeds its budget in instruction_budgets.json
by more than the recorded tolerance (2 %). Counts are deterministic for a
given binary; they depend on the compiler and flags, so the budgets are
recorded per compiler (instruction_budgets.json: g++, host-release-gcc;
instruction_budgets.clang.json: clang, host-release; -O2 -DNDEBUG, no debug info).

  check_instruction_budgets.py --exe build/host-release/host_sim/bench/kestrel-instr-count
  ... --update          rewrite the budgets with the measured counts
  ... --filter TEXT     only paths containing TEXT (no budget check of the rest)

Exit status: 0 pass, 1 over budget or a measurement failed, 77 valgrind
absent (CTest reports the test as skipped).
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

SKIP = 77


def run_callgrind(exe, path_filter, workdir):
    out = os.path.join(workdir, "callgrind.out")
    cmd = ["valgrind", "--tool=callgrind", "--collect-atstart=no", "--callgrind-out-file=" + out, exe]
    if path_filter:
        cmd += ["--filter", path_filter]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        sys.stderr.write(proc.stdout + proc.stderr)
        raise RuntimeError("%s exited with status %d" % (" ".join(cmd), proc.returncode))
    counts = {}
    for name in os.listdir(workdir):
        if not name.startswith("callgrind.out"):
            continue
        label, total = None, None
        with open(os.path.join(workdir, name)) as f:
            for line in f:
                if line.startswith("desc: Trigger: Client Request: "):
                    label = line[len("desc: Trigger: Client Request: "):].strip()
                elif line.startswith("totals:") or (total is None and line.startswith("summary:")):
                    total = int(line.split()[1])
        if label is None:
            continue  # the final dump at exit: nothing is collected there
        m = re.fullmatch(r"(\S+) steps=(\d+)", label)
        if not m:
            raise RuntimeError("unexpected dump label %r" % label)
        path, steps = m.group(1), int(m.group(2))
        if steps == 0:
            raise RuntimeError("%s: no measured steps" % path)
        counts[path] = (total or 0) / steps
    return counts


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True, help="kestrel-instr-count binary")
    ap.add_argument("--budgets", default=os.path.join(here, "instruction_budgets.json"))
    ap.add_argument("--filter", default=None, help="only paths containing this text")
    ap.add_argument("--update", action="store_true", help="write the measured counts as the new budgets")
    args = ap.parse_args()

    if shutil.which("valgrind") is None:
        print("SKIP: valgrind not found (Debian: apt-get install valgrind); instruction budgets not checked")
        return SKIP

    with open(args.budgets) as f:
        doc = json.load(f)
    budgets = doc.get("budgets", {})
    tolerance = float(doc.get("tolerance", 0.02))

    with tempfile.TemporaryDirectory(prefix="kestrel-callgrind-") as tmp:
        try:
            counts = run_callgrind(args.exe, args.filter, tmp)
        except RuntimeError as e:
            print("FAIL: %s" % e)
            return 1

    failures = []
    width = max(len(p) for p in counts) if counts else 10
    print("%-*s %12s %12s %8s" % (width, "path", "instr/step", "budget", "ratio"))
    for path in sorted(counts):
        n = counts[path]
        b = budgets.get(path)
        if b is None:
            print("%-*s %12.0f %12s %8s  (no budget)" % (width, path, n, "-", "-"))
            continue
        ratio = n / b
        note = ""
        if ratio > 1.0 + tolerance:
            note = "  OVER BUDGET"
            failures.append(path)
        elif ratio < 1.0 - tolerance:
            note = "  (under: --update to lock the gain in)"
        print("%-*s %12.0f %12d %8.3f%s" % (width, path, n, b, ratio, note))

    if args.filter is None:
        missing = sorted(set(budgets) - set(counts))
        for path in missing:
            print("FAIL: budget recorded for %s but the path was not measured" % path)
        if not args.update:
            failures += missing

    if args.update:
        if args.filter is None:
            doc["budgets"] = {p: int(round(counts[p])) for p in sorted(counts)}
        else:
            doc["budgets"].update({p: int(round(counts[p])) for p in counts})
            doc["budgets"] = dict(sorted(doc["budgets"].items()))
        with open(args.budgets, "w") as f:
            json.dump(doc, f, indent=2)
            f.write("\n")
        print("budgets written to %s" % args.budgets)
        return 0

    if failures:
        print("FAIL: %d path(s) over budget by more than %.0f %% or missing: %s"
              % (len(failures), tolerance * 100, ", ".join(failures)))
        return 1
    print("OK: %d paths within %.0f %% of their budgets" % (len(counts), tolerance * 100))
    return 0


if __name__ == "__main__":
    sys.exit(main())
