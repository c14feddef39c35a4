#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Plots for kestrel-sim results (called by kestrel-sim; runnable by hand).

  plot_results.py run --steps S.csv --tracks T.csv --out-prefix P [--title X]
      P_xy.png     truth, the plots the scored track used, and every
                   confirmed track, in the x-y plane (radar at the origin)
      P_error.png  position error e_k over time with the loss threshold L
  plot_results.py summary --summary summary.json --out summary.png
      RMSE and peak error with their 95 % intervals per scenario and filter

Reads only the CSV/JSON files kestrel-sim writes (csv and json modules, no
pandas). If matplotlib is missing it prints a warning and exits 0: plots are
a convenience, the figures are in the CSV and JSON files.
"""
import argparse
import csv
import json
import math
import sys


def load_matplotlib():
    try:
        import matplotlib
        matplotlib.use("Agg")  # files only, no display needed
        import matplotlib.pyplot as plt
        return plt
    except ImportError as e:  # pragma: no cover - depends on the host
        print(f"warning: matplotlib not available ({e}); skipping plots", file=sys.stderr)
        return None


def number(cell):
    """A float, or NaN for an empty cell."""
    return float(cell) if cell not in ("", None) else math.nan


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def plot_run(plt, args):
    steps = read_rows(args.steps)
    tracks = read_rows(args.tracks) if args.tracks else []
    if not steps:
        print(f"warning: {args.steps} has no scored steps; no plots", file=sys.stderr)
        return

    t = [number(r["time_s"]) for r in steps]
    fig, ax = plt.subplots(figsize=(8, 6))
    ax.plot([number(r["truth_x_m"]) / 1e3 for r in steps], [number(r["truth_y_m"]) / 1e3 for r in steps],
            "k-", lw=1.5, label="truth")
    ax.plot([number(r["meas_x_m"]) / 1e3 for r in steps], [number(r["meas_y_m"]) / 1e3 for r in steps],
            ".", color="0.6", ms=3, label="plots (used)")
    by_id = {}
    for r in tracks:
        if r.get("status", "confirmed") != "confirmed":
            continue
        by_id.setdefault(r["track_id"], []).append((number(r["x_m"]) / 1e3, number(r["y_m"]) / 1e3))
    for i, (tid, pts) in enumerate(sorted(by_id.items(), key=lambda kv: int(kv[0]))):
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "-", lw=1,
                label=f"track {tid}" if i < 6 else None)
    ax.plot([0], [0], "r^", label="radar")
    ax.set_xlabel("x [km]")
    ax.set_ylabel("y [km]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    ax.set_title(f"{args.title}: x-y (run 0)")
    fig.tight_layout()
    fig.savefig(f"{args.out_prefix}_xy.png", dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(9, 4))
    err = [number(r["error_m"]) for r in steps]
    ax.plot(t, err, "b-", lw=1, label="position error")
    lost_t = [ti for ti, r in zip(t, steps) if r["error_m"] == ""]
    if lost_t:
        ax.plot(lost_t, [args.loss_threshold_m] * len(lost_t), "rx", label="no confirmed track")
    ax.axhline(args.loss_threshold_m, color="r", ls="--", lw=1, label=f"L = {args.loss_threshold_m:g} m")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("error [m]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title(f"{args.title}: position error (run 0)")
    fig.tight_layout()
    fig.savefig(f"{args.out_prefix}_error.png", dpi=120)
    plt.close(fig)


def plot_summary(plt, args):
    with open(args.summary) as f:
        doc = json.load(f)
    entries = [(s, fl, e) for s, per in doc.get("results", {}).items() for fl, e in per.items()]
    if not entries:
        print(f"warning: {args.summary} holds no results; no plot", file=sys.stderr)
        return
    labels = [f"{s}\n{fl}" for s, fl, _ in entries]
    fig, axes = plt.subplots(1, 2, figsize=(max(6, 1.6 * len(entries) * 2), 4))
    for ax, key, title in ((axes[0], "rmse_m", "RMSE [m]"), (axes[1], "peak_m", "peak error [m]")):
        means, lo, hi = [], [], []
        for _, _, e in entries:
            m = e.get(key, {})
            mean = m.get("mean")
            means.append(mean if mean is not None else math.nan)
            lo.append((mean - m["ci95_low"]) if mean is not None and m.get("ci95_low") is not None else 0)
            hi.append((m["ci95_high"] - mean) if mean is not None and m.get("ci95_high") is not None else 0)
        ax.bar(range(len(entries)), means, yerr=[lo, hi], capsize=4, color="tab:blue", alpha=0.8)
        ax.set_xticks(range(len(entries)))
        ax.set_xticklabels(labels, fontsize=8)
        ax.set_title(f"{title}, mean and 95 % CI")
        ax.grid(True, axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="mode", required=True)
    r = sub.add_parser("run")
    r.add_argument("--steps", required=True)
    r.add_argument("--tracks")
    r.add_argument("--out-prefix", required=True)
    r.add_argument("--title", default="kestrel-sim")
    r.add_argument("--loss-threshold-m", type=float, default=300.0)
    s = sub.add_parser("summary")
    s.add_argument("--summary", required=True)
    s.add_argument("--out", required=True)
    args = p.parse_args()

    plt = load_matplotlib()
    if plt is None:
        return 0
    if args.mode == "run":
        plot_run(plt, args)
    else:
        plot_summary(plt, args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
