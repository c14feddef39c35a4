#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Instruction budget of the worst-case frame at a board's capacity
(docs/performance.md, "Worst-case frame per board").

Builds kestrel-worst-frame in the board's tree (configured by the board's
image test), runs it under QEMU Linux user mode with the counting plugin
(insn_count/qemu_insn_count.cpp), and checks, for the worst of its counted
frames, adapter + Tracker::step instructions against the board's budget in
targets/frame_budgets.json: more than the file's tolerance (2 %) over fails.
It also checks that each counted frame took the worst-case path and that
the frames are the host's, bit for bit (frames_hash, which
`kestrel-sim timing --worst-case <board>` prints too).

  frame_budget.py --board cortex-m4f --tree <board tree> --plugin <plugin .so>
  ... --update      record the measured counts as the board's budget
                    (or KESTREL_UPDATE_FRAME_BUDGETS=1 in the environment, so that
                    `KESTREL_UPDATE_FRAME_BUDGETS=1 ctest --preset host-release
                    -R cortex_m0plus_frame_budget` re-records from CI's own tree)
  frame_budget.py --table     the docs table from the recorded budgets

Exit status: 0 pass, 1 fail, 77 skip (emulator absent, tree not configured).
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_BUDGETS = os.path.normpath(os.path.join(HERE, "..", "..", "targets", "frame_budgets.json"))


def load(path):
    with open(path) as f:
        return json.load(f)


def save(path, data):
    with open(path, "w") as f:
        json.dump(data, f, indent=2)
        f.write("\n")


def measure(args, board):
    emulator = board["emulator"]
    if shutil.which(emulator) is None:
        print("SKIP: %s not found (Debian: qemu-user)" % emulator)
        sys.exit(SKIP)
    if not os.path.isfile(os.path.join(args.tree, "CMakeCache.txt")):
        print("SKIP: %s is not configured (no cross compiler?)" % args.tree)
        sys.exit(SKIP)
    build = subprocess.run([args.cmake, "--build", args.tree, "--target", "kestrel-worst-frame", "-j", "2"])
    if build.returncode != 0:
        sys.exit("FAIL: building kestrel-worst-frame in %s failed" % args.tree)
    program = None
    for root, _, files in os.walk(os.path.join(args.tree, "targets")):
        if "kestrel-worst-frame" in files:
            program = os.path.join(root, "kestrel-worst-frame")
    if program is None:
        sys.exit("FAIL: kestrel-worst-frame not found under %s/targets" % args.tree)
    if not os.path.isfile(args.plugin):
        sys.exit("FAIL: the counting plugin %s does not exist" % args.plugin)
    cmd = [emulator, "-d", "plugin", "-plugin", args.plugin + ",marker=kestrel_count_mark", program]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    sys.stdout.write(proc.stdout)
    # A QEMU built without plugin support refuses the option: skip. A plugin
    # it cannot load (missing, or another plugin ABI) is a failure.
    if ("kestrel-insn-count" not in proc.stderr and "plugin" in proc.stderr
            and "Could not load plugin" not in proc.stderr):
        sys.stderr.write(proc.stderr)
        print("SKIP: %s cannot load the counting plugin (built without TCG plugins?)" % emulator)
        sys.exit(SKIP)
    if proc.returncode != 0:
        sys.stderr.write(proc.stderr)
        sys.exit("FAIL: %s exited with status %d (1: a counted frame was not the worst case)"
                 % (" ".join(cmd), proc.returncode))
    intervals = [int(m.group(1)) for m in re.finditer(r"kestrel-insn-count: interval \d+ (\d+)", proc.stderr)]
    frames = re.findall(r"^frame (\d+) worst_case", proc.stdout, re.M)
    hashes = re.findall(r"^frames_hash (\d+)", proc.stdout, re.M)
    shape = re.search(r"^board \S+ tracks (\d+) plots (\d+)", proc.stdout, re.M)
    # Three marks per counted frame: before the adapter, before step, after step.
    if not frames or len(intervals) != 3 * len(frames) or len(hashes) != 1 or shape is None:
        sys.stderr.write(proc.stderr)
        sys.exit("FAIL: expected 3 counted intervals per frame line, got %d for %d frames"
                 % (len(intervals), len(frames)))
    per_frame = [(intervals[3 * j + 1], intervals[3 * j + 2]) for j in range(len(frames))]
    convert, step = max(per_frame, key=lambda cs: cs[0] + cs[1])
    return {"instructions": convert + step, "convert": convert, "step": step,
            "frames": [c + s for c, s in per_frame], "frames_hash": hashes[0],
            "tracks": int(shape.group(1)), "plots": int(shape.group(2))}


def timing(board, instructions):
    lo, hi = board["cpi_range"]
    hz = board["clock_hz"]
    return (lo * instructions, hi * instructions, board["cpi_plan"] * instructions / hz)


def table(data):
    rows = ["| board | capacity | instructions (adapter + step) | cycles (CPI range) | time at the clock | "
            "at CPI plan: share of the frame period | target | met |", "|---|---|---:|---:|---:|---:|---|---|"]
    for name, b in data["boards"].items():
        if "instructions" not in b:
            continue
        cyc_lo, cyc_hi, t = timing(b, b["instructions"])
        mhz = b["clock_hz"] / 1e6
        limit = b["target_fraction"] * b["frame_period_s"]
        rows.append("| %s | %d x %d | %s | %s - %s (%s - %s) | %.3f - %.3f ms at %g MHz | %.3f ms (CPI %s), %.2f %% of %g s "
                    "| <= %g ms (%g %%) | %s |" % (
                        name, b["tracks"], b["plots"], format(b["instructions"], ","), format(int(cyc_lo), ","),
                        format(int(cyc_hi), ","), b["cpi_range"][0], b["cpi_range"][1], cyc_lo / b["clock_hz"] * 1e3,
                        cyc_hi / b["clock_hz"] * 1e3, mhz, t * 1e3, b["cpi_plan"], 100.0 * t / b["frame_period_s"],
                        b["frame_period_s"], limit * 1e3, 100.0 * b["target_fraction"],
                        "yes" if t <= limit else "**no** (%.2fx the target)" % (t / limit)))
    return "\n".join(rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--board")
    ap.add_argument("--tree", help="the board's build tree")
    ap.add_argument("--plugin", help="libkestrel-qemu-insn-count.so")
    ap.add_argument("--cmake", default="cmake")
    ap.add_argument("--budgets", default=DEFAULT_BUDGETS)
    ap.add_argument("--update", action="store_true", help="record the measurement as the budget")
    ap.add_argument("--table", action="store_true", help="print the docs table and exit")
    args = ap.parse_args()
    data = load(args.budgets)
    if args.table:
        print(table(data))
        return 0
    if not (args.board and args.tree and args.plugin):
        ap.error("--board, --tree and --plugin are required")
    board = data["boards"][args.board]
    m = measure(args, board)
    cyc_lo, cyc_hi, t = timing(board, m["instructions"])
    print("%s: worst-case frame %d tracks x %d plots: %d instructions (adapter %d + step %d; frames %s)"
          % (args.board, m["tracks"], m["plots"], m["instructions"], m["convert"], m["step"], m["frames"]))
    print("  cycles %d - %d at CPI %s - %s; %.3f ms at %g MHz and CPI %s, %.1f %% of the %g s frame period"
          " (target %g %%)" % (cyc_lo, cyc_hi, board["cpi_range"][0], board["cpi_range"][1], t * 1e3,
                                 board["clock_hz"] / 1e6, board["cpi_plan"], 100.0 * t / board["frame_period_s"],
                                 board["frame_period_s"], 100.0 * board["target_fraction"]))
    if args.update or os.environ.get("KESTREL_UPDATE_FRAME_BUDGETS") == "1":
        board.update({k: m[k] for k in ("instructions", "convert", "step", "frames_hash", "tracks", "plots")})
        save(args.budgets, data)
        print("recorded in %s" % args.budgets)
        return 0
    failures = []
    if "instructions" not in board:
        failures.append("no budget recorded for %s (run with --update)" % args.board)
    else:
        if m["frames_hash"] != board["frames_hash"]:
            failures.append("frames_hash %s is not the recorded (host) %s: not the same frames"
                            % (m["frames_hash"], board["frames_hash"]))
        if (m["tracks"], m["plots"]) != (board["tracks"], board["plots"]):
            failures.append("capacity %d x %d, budget recorded for %d x %d"
                            % (m["tracks"], m["plots"], board["tracks"], board["plots"]))
        budget, tol = board["instructions"], data["tolerance"]
        ratio = m["instructions"] / budget
        print("  budget %d, measured/budget %.4f (fails above %.2f)" % (budget, ratio, 1.0 + tol))
        if ratio > 1.0 + tol:
            failures.append("%d instructions, %.1f %% over the budget %d" % (m["instructions"], 100 * (ratio - 1), budget))
        elif ratio < 1.0 - tol:
            print("  %.1f %% under the budget: lock the gain in with --update" % (100 * (1 - ratio)))
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
