#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Figures like paper 000's figs. 2-5 from `kestrel-sim r2aekf-study` output.

  r2aekf_plots.py --dir results/r2aekf

reads DIR/study.json and, per scenario, DIR/<scenario>/<filter>_steps.csv and
DIR/<scenario>/r2aekf[-paper]_scales.csv (run 0 of the reported seeds), and
writes
  DIR/fig2_trajectories.png  truth, plots and every filter's track (fig. 2)
  DIR/fig3_error.png         position error over time per filter (fig. 3)
  DIR/fig4_scales.png        sRr, sRb, sQax, sQlat over time, both modes (fig. 4)
  DIR/fig5_metrics.png       bars: RMSE, peak, NEES, track loss, recovery with
                             95 % intervals over the Monte Carlo runs (fig. 5)
Only the csv and json modules are used to read; without matplotlib it warns
and exits 1 (every figure's numbers are in the CSV and JSON files).
"""
import argparse
import json
import math
import os
import sys

from plot_common import load_matplotlib, number, read_rows, save_figure

COLOURS = {"r2aekf": "tab:red", "r2aekf-paper": "tab:orange"}






def colour(key, i):
    return COLOURS.get(key, ["tab:blue", "tab:green", "tab:purple", "tab:brown"][i % 4])


def fig2(plt, d, scenarios, filters):
    fig, axes = plt.subplots(1, len(scenarios), figsize=(5.5 * len(scenarios), 5), squeeze=False)
    for ax, s in zip(axes[0], scenarios):
        first = True
        for i, f in enumerate(filters):
            rows = read_rows(os.path.join(d, s, f["key"] + "_steps.csv"), missing_ok=True)
            if not rows:
                continue
            if first:
                ax.plot([number(r["truth_x_m"]) / 1e3 for r in rows], [number(r["truth_y_m"]) / 1e3 for r in rows],
                        "k-", lw=2, label="truth")
                ax.plot([number(r["meas_x_m"]) / 1e3 for r in rows], [number(r["meas_y_m"]) / 1e3 for r in rows],
                        ".", color="0.6", ms=2, label="measurements")
                first = False
            ax.plot([number(r["est_x_m"]) / 1e3 for r in rows], [number(r["est_y_m"]) / 1e3 for r in rows], "-",
                    lw=1, color=colour(f["key"], i), label=f["label"])
        ax.set_title(f"{s}: trajectories (run 0)")
        ax.set_xlabel("x [km]")
        ax.set_ylabel("y [km]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    save_figure(plt, fig, os.path.join(d, "fig2_trajectories.png"), dpi=110)


def fig3(plt, d, scenarios, filters):
    fig, axes = plt.subplots(len(scenarios), 1, figsize=(10, 2.8 * len(scenarios)), squeeze=False)
    for ax, s in zip(axes[:, 0], scenarios):
        for i, f in enumerate(filters):
            rows = read_rows(os.path.join(d, s, f["key"] + "_steps.csv"), missing_ok=True)
            ax.plot([number(r["time_s"]) for r in rows], [number(r["error_m"]) for r in rows], "-", lw=1,
                    color=colour(f["key"], i), label=f["label"])
        ax.axhline(300.0, color="k", ls="--", lw=0.8, label="L = 300 m")
        ax.set_ylabel("position error [m]")
        ax.set_title(f"{s}: position error (run 0)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper right")
    axes[-1, 0].set_xlabel("time [s]")
    save_figure(plt, fig, os.path.join(d, "fig3_error.png"), dpi=110)


def fig4(plt, d, scenarios):
    names = [("s_r_range", "sRr"), ("s_r_bearing", "sRb"), ("s_q_axial", "sQax"), ("s_q_lateral", "sQlat")]
    fig, axes = plt.subplots(len(scenarios), 2, figsize=(12, 2.8 * len(scenarios)), squeeze=False)
    for row, s in enumerate(scenarios):
        for col, key in enumerate(("r2aekf", "r2aekf-paper")):
            ax = axes[row, col]
            rows = read_rows(os.path.join(d, s, key + "_scales.csv"), missing_ok=True)
            t = [number(r["time_s"]) for r in rows]
            for name, label in names:
                ax.semilogy(t, [number(r[name]) for r in rows], lw=1, label=label)
            ax.set_title(f"{s}: {'default' if key == 'r2aekf' else 'paper'} mode scales (run 0)")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7, loc="upper right", ncol=4)
            ax.set_ylabel("scale")
    for col in range(2):
        axes[-1, col].set_xlabel("time [s]")
    save_figure(plt, fig, os.path.join(d, "fig4_scales.png"), dpi=110)


def fig5(plt, d, study, scenarios, filters):
    metrics = [("rmse_m", "RMSE [m]"), ("peak_m", "peak error [m]"), ("nees_pos", "NEES (position)"),
               ("track_loss_s", "track-loss time [s]"), ("recovery_s", "recovery time [s]")]
    table = study.get("table", {})
    fig, axes = plt.subplots(1, len(metrics), figsize=(4.2 * len(metrics), 4.2))
    width = 0.8 / max(1, len(filters))
    for ax, (m, title) in zip(axes, metrics):
        for i, f in enumerate(filters):
            means, lo, hi = [], [], []
            for s in scenarios:
                e = table.get(s, {}).get(f["key"], {}).get(m, {})
                mean = e.get("mean")
                means.append(mean if mean is not None else math.nan)
                lo.append(mean - e["ci95_low"] if mean is not None and e.get("ci95_low") is not None else 0)
                hi.append(e["ci95_high"] - mean if mean is not None and e.get("ci95_high") is not None else 0)
            xs = [j + (i - (len(filters) - 1) / 2) * width for j in range(len(scenarios))]
            ax.bar(xs, means, width, yerr=[lo, hi], capsize=2, color=colour(f["key"], i), label=f["label"])
        ax.set_xticks(range(len(scenarios)))
        ax.set_xticklabels(scenarios)
        ax.set_title(title, fontsize=9)
        ax.grid(True, axis="y", alpha=0.3)
    axes[0].legend(fontsize=6, loc="upper left")
    fig.suptitle("Monte Carlo mean and 95 % interval", fontsize=10)
    save_figure(plt, fig, os.path.join(d, "fig5_metrics.png"), dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--dir", required=True)
    args = p.parse_args()
    with open(os.path.join(args.dir, "study.json")) as f:
        study = json.load(f)
    plt = load_matplotlib()
    scenarios = study.get("options", {}).get("scenarios", [])
    filters = study.get("filters", [])
    fig2(plt, args.dir, scenarios, filters)
    fig3(plt, args.dir, scenarios, filters)
    fig4(plt, args.dir, scenarios)
    fig5(plt, args.dir, study, scenarios, filters)
    return 0


if __name__ == "__main__":
    sys.exit(main())
