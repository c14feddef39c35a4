#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Grid search of the IMM's parameters on the tuning seeds (docs/imm.md).

Usage: imm_tune.py KESTREL_SIM 'GRID_JSON' [--seed 1000] [--runs 100]
  GRID_JSON maps --imm keys to value lists, e.g. '{"ca_qj": [100, 300], "p_stay": [0.8, 0.9]}'.

For every combination it runs `kestrel-sim run -f imm` on s1, s2, s1n and s2n
and prints the worst ratio to the best-tuned EKF-CA (qj 500 on s1/s1n, 50 on
s2/s2n, run on the same seeds) over the four scenarios and both RMSE and
peak, then RMSE/peak/NEES per scenario. Sort the output to rank.
"""
import argparse
import itertools
import json
import re
import subprocess
import tempfile

SCENARIOS = {"s1": 500, "s2": 50, "s1n": 500, "s2n": 50}  # the EKF-CA's best qj


def run(sim, scenario, filt, extra, seed, runs, out):
    args = [sim, "run", "-s", scenario, "-f", filt, "-n", str(runs), "--seed", str(seed), "--no-plots", "-o", out]
    args += extra
    line = subprocess.run(args, capture_output=True, text=True, check=True).stdout.splitlines()[1]
    nums = re.findall(r"[-\d.]+", line.split(filt, 1)[1])
    return float(nums[1]), float(nums[4]), float(nums[7])  # RMSE, peak, position NEES (means)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sim")
    ap.add_argument("grid")
    ap.add_argument("--seed", type=int, default=1000)
    ap.add_argument("--runs", type=int, default=100)
    a = ap.parse_args()
    grid = json.loads(a.grid)
    with tempfile.TemporaryDirectory() as out:
        base = {s: run(a.sim, s, "ekf-ca", ["--qj", str(q)], a.seed, a.runs, out) for s, q in SCENARIOS.items()}
        for values in itertools.product(*grid.values()):
            kv = [f"{k}={v}" for k, v in zip(grid, values)]
            extra = [x for item in kv for x in ("--imm", item)]
            r = {s: run(a.sim, s, "imm", extra, a.seed, a.runs, out) for s in SCENARIOS}
            worst = max(max(r[s][0] / base[s][0], r[s][1] / base[s][1]) for s in r)
            print(f"{worst:.3f} " + " ".join(kv) + " | " +
                  " ".join(f"{s}:{r[s][0]:.1f}/{r[s][1]:.0f}/{r[s][2]:.1f}" for s in r), flush=True)


if __name__ == "__main__":
    main()
