#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The table of docs/performance.md: instructions per step (callgrind, via
check_instruction_budgets.py's runner) and CPU ns per step (kestrel-bench),
dense and structured side by side, as Markdown.

  perf_table.py --instr build/host-release-gcc/host_sim/bench/kestrel-instr-count \\
                --bench build/host-release-gcc/host_sim/bench/kestrel-bench [--min-time 0.2]

Instruction counts are exact and repeatable; ns are the median over
--repetitions runs of Google Benchmark's CPU time (thread CPU time for the
single-frame tracker paths) and move with machine load and CPU model.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_instruction_budgets import run_callgrind  # noqa: E402


def bench_ns(exe, min_time, repetitions):
    cmd = [exe, "--benchmark_format=json", "--benchmark_min_time=%g" % min_time,
           "--benchmark_repetitions=%d" % repetitions, "--benchmark_report_aggregates_only=true"]
    out = subprocess.run(cmd, stdout=subprocess.PIPE, check=True, text=True).stdout
    ns = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        name = re.sub(r"/iterations:\d+", "", b["run_name"]).replace("/manual_time", "")
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6}[b["time_unit"]]
        # Manual-time benchmarks report thread CPU time as real_time.
        t = b["real_time"] if "manual_time" in b["run_name"] else b["cpu_time"]
        ns[name] = t * scale
    return ns


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--instr", required=True, help="kestrel-instr-count binary")
    ap.add_argument("--bench", help="kestrel-bench binary (omit for instructions only)")
    ap.add_argument("--min-time", type=float, default=0.2)
    ap.add_argument("--repetitions", type=int, default=3)
    args = ap.parse_args()

    with tempfile.TemporaryDirectory(prefix="kestrel-callgrind-") as tmp:
        counts = run_callgrind(args.instr, None, tmp)
    ns = bench_ns(args.bench, args.min_time, args.repetitions) if args.bench else {}

    rows = {}
    for path, n in counts.items():
        kind, filt, scalar, form, what = path.split("/")
        rows.setdefault((kind, filt, scalar, what), {})[form] = (n, ns.get("/".join([kind, filt, scalar, form, what])))

    def fmt_ns(v):
        return "-" if v is None else ("%.0f" % v if v >= 100 else "%.1f" % v)

    print("| path | scalar | dense instr | structured instr | dense / structured | dense ns | structured ns |")
    print("|---|---|---:|---:|---:|---:|---:|")
    order = {"predict": 0, "innovation": 1, "update": 2, "step": 3, "normal": 4, "gated_out": 5, "rejected": 6,
             "initiation": 7, "worst_case": 8}
    for key in sorted(rows, key=lambda k: (k[0] != "filter", k[1], k[2], order.get(k[3], 99))):
        kind, filt, scalar, what = key
        d = rows[key].get("dense", (None, None))
        s = rows[key].get("structured", (None, None))
        ratio = "%.2f" % (d[0] / s[0]) if d[0] and s[0] else "-"
        print("| %s %s %s | %s | %s | %s | %s | %s | %s |" % (
            kind, filt, what, scalar, "%.0f" % d[0] if d[0] else "-", "%.0f" % s[0] if s[0] else "-", ratio,
            fmt_ns(d[1]), fmt_ns(s[1])))
    return 0


if __name__ == "__main__":
    sys.exit(main())
