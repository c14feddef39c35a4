#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Plots of the MC-001 campaign (called by kestrel-sim montecarlo/merge; runnable by hand).

  mc001_plots.py --dir DIR
      DIR/mc001_mse.png   position MSE per cell and filter with 95 % intervals:
                          one panel per bearing sigma, range sigma on the x axis
                          (paper 001 figs. 4-6)
      DIR/mc001_time.png  time per step per filter (paper 001 fig. 7)

Reads DIR/mc001_mse.csv and DIR/mc001_timing.csv only (csv module). If
matplotlib is missing it prints a warning and exits 1: the numbers are in the
CSV files.
"""
import argparse
import os
import sys

from plot_common import load_matplotlib, read_rows, save_figure




def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dir", required=True)
    args = ap.parse_args()
    plt = load_matplotlib()
    rows = read_rows(os.path.join(args.dir, "mc001_mse.csv"))
    filters = []
    for r in rows:
        if r["filter"] not in filters:
            filters.append(r["filter"])
    bearings = sorted({float(r["bearing_sigma_deg"]) for r in rows})
    runs = rows[0]["runs"] if rows else "?"

    fig, axes = plt.subplots(1, len(bearings), figsize=(5.0 * len(bearings), 4.6), sharey=False)
    if len(bearings) == 1:
        axes = [axes]
    markers = "os^vD<>px*"
    for ax, sb in zip(axes, bearings):
        for i, name in enumerate(filters):
            pts = sorted((float(r["range_sigma_m"]), float(r["mse_m2"]), float(r["ci95_low_m2"]),
                          float(r["ci95_high_m2"])) for r in rows
                         if r["filter"] == name and float(r["bearing_sigma_deg"]) == sb)
            x = [p[0] * (1.0 + 0.04 * (i - len(filters) / 2)) for p in pts]  # spread overlapping markers
            y = [p[1] for p in pts]
            lo = [max(p[1] - p[2], 0.0) for p in pts]
            hi = [p[3] - p[1] for p in pts]
            ax.errorbar(x, y, yerr=[lo, hi], marker=markers[i % len(markers)], capsize=2, label=name,
                        linestyle="-" if not name.startswith("CRPF") else "--", linewidth=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("range sigma, m (accel sigma 0.01 / 0.1 / 1 m/s^2)")
        ax.set_title(f"bearing sigma {sb:g} deg")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("position MSE, m^2 (95 % interval)")
    axes[-1].legend(fontsize=8, loc="upper left")
    fig.suptitle(f"MC-001: position MSE per cell, {runs} runs per cell (filters tuned to the middle cell)")
    save_figure(plt, fig, os.path.join(args.dir, "mc001_mse.png"))

    timing = read_rows(os.path.join(args.dir, "mc001_timing.csv"))
    names = [r["filter"] for r in timing]
    us = [float(r["ns_per_step"]) / 1000.0 for r in timing]
    threads = timing[0]["threads"] if timing else "?"
    fig, ax = plt.subplots(figsize=(8, 4.2))
    bars = ax.bar(names, us, color=["#4477aa" if not n.startswith("CRPF") else "#cc6677" for n in names])
    for b, v in zip(bars, us):
        ax.text(b.get_x() + b.get_width() / 2, v, f"{v:.2f}", ha="center", va="bottom", fontsize=8)
    ax.set_yscale("log")
    ax.set_ylabel("time per step (predict + update), us")
    ax.set_title(f"MC-001: mean time per step ({threads} worker threads, double)")
    ax.tick_params(axis="x", labelrotation=30)
    save_figure(plt, fig, os.path.join(args.dir, "mc001_time.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
