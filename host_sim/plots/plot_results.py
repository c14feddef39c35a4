#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Plots for kestrel-sim results (called by kestrel-sim; runnable by hand).

  plot_results.py run --steps S.csv --tracks T.csv --out-prefix P [--title X]
      P_xy.png     truth, the plots the scored track used, and every
                   confirmed track, in the x-y plane (radar at the origin)
      P_error.png  position error e_k over time with the loss threshold L
  plot_results.py summary --summary summary.json --out summary.png
      RMSE and peak error with their 95 % intervals per scenario and filter
  plot_results.py modes --modes M.csv --steps S.csv --out P.png [--title X]
      mean mode probabilities over the runs of M.csv (an IMM's
      <filter>_modes.csv) against time, the truth's turns and speed changes
      (from the truth of S.csv) marked along the top, and the truth's turn
      rate and dv/dt below
  plot_results.py gospa --steps multi_steps.csv --out P.png [--title X]
      mean GOSPA and OSPA per step of each associator that `kestrel-sim run`
      of a multi-target scenario ran (e.g. GNN and the oracle)

Reads only the CSV/JSON files kestrel-sim writes (csv and json modules, no
pandas). If matplotlib is missing it prints a warning and exits 1: plots are
a convenience, the numbers are in the CSV and JSON files.
"""
import argparse
import json
import math
import sys
import textwrap

from plot_common import load_matplotlib, number, read_rows, save_figure






def wrapped(title, width=90):
    """A long title (a filter's full setup) on several lines, never cut at the figure's edge."""
    return "\n".join(textwrap.wrap(title, width))


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
    ax.set_title(wrapped(f"{args.title}: x-y (run 0)"), fontsize=9)
    save_figure(plt, fig, f"{args.out_prefix}_xy.png")

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
    ax.set_title(wrapped(f"{args.title}: position error (run 0)"), fontsize=9)
    save_figure(plt, fig, f"{args.out_prefix}_error.png")


def plot_summary(plt, args):
    with open(args.summary) as f:
        doc = json.load(f)
    # Entries with an RMSE (single-target radar); PCL, sonar and
    # multi-target runs into the same directory add entries of their own.
    entries = [(s, fl, e) for s, per in doc.get("results", {}).items() for fl, e in per.items() if "rmse_m" in e]
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
    save_figure(plt, fig, args.out)


def truth_manoeuvre(steps):
    """Turn rate (rad/s) and rate of change of speed (m/s^2) of the truth at
    each interior scored step, from central differences of its positions
    (the truth is noise-free); NaN at the ends and across uneven steps."""
    t = [number(r["time_s"]) for r in steps]
    x = [number(r["truth_x_m"]) for r in steps]
    y = [number(r["truth_y_m"]) for r in steps]
    turn, dspeed = [math.nan] * len(t), [math.nan] * len(t)
    for k in range(1, len(t) - 1):
        h0, h1 = t[k] - t[k - 1], t[k + 1] - t[k]
        if h0 <= 0 or abs(h1 - h0) > 1e-9 * h0:
            continue
        vx, vy = (x[k + 1] - x[k - 1]) / (2 * h0), (y[k + 1] - y[k - 1]) / (2 * h0)
        ax, ay = (x[k + 1] - 2 * x[k] + x[k - 1]) / h0 ** 2, (y[k + 1] - 2 * y[k] + y[k - 1]) / h0 ** 2
        v = math.hypot(vx, vy)
        if v > 0:
            dspeed[k] = (ax * vx + ay * vy) / v
            turn[k] = (vx * ay - vy * ax) / (v * v)
    return t, turn, dspeed


def intervals(t, flags):
    """[(t0, t1)] of the runs of True in flags, each widened by half a step."""
    out, start = [], None
    for k, f in enumerate(flags):
        if f and start is None:
            start = k
        if (not f or k == len(flags) - 1) and start is not None:
            end = k if f else k - 1
            half = (t[1] - t[0]) / 2 if len(t) > 1 else 0
            out.append((t[start] - half, t[end] + half))
            start = None
    return out


def plot_modes(plt, args):
    rows = read_rows(args.modes)
    names = [c[3:] for c in (rows[0].keys() if rows else []) if c.startswith("mu_")]
    if not rows or not names:
        print(f"warning: {args.modes} holds no mode probabilities; no plot", file=sys.stderr)
        return
    by_t = {}
    runs = set()
    for r in rows:
        runs.add(r["run"])
        by_t.setdefault(round(number(r["time_s"]), 6), []).append([number(r["mu_" + n]) for n in names])
    times = sorted(by_t)
    means = [[math.fsum(v[j] for v in by_t[ti]) / len(by_t[ti]) for ti in times] for j in range(len(names))]

    steps = read_rows(args.steps)
    tt, turn, dspeed = truth_manoeuvre(steps) if len(steps) > 2 else ([], [], [])
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(11, 6), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    if tt:
        # Strips along the top, so the curves stay readable where the truth
        # manoeuvres all the time (the S1 weave).
        spans = ((intervals(tt, [abs(w) > args.turn_radps for w in turn]), 0.94, "tab:green",
                  f"truth turning, |turn rate| > {args.turn_radps:g} rad/s"),
                 (intervals(tt, [abs(a) > args.speed_mps2 for a in dspeed]), 0.88, "tab:red",
                  f"truth speed changing, |dv/dt| > {args.speed_mps2:g} m/s$^2$"))
        for spans_of, low, colour, label in spans:
            for i, (a, b) in enumerate(spans_of):
                ax.axvspan(a, b, ymin=low, ymax=low + 0.05, color=colour, alpha=0.6, lw=0,
                           label=label if i == 0 else None)
        ax2.plot(tt, [math.degrees(w) for w in turn], "-", color="tab:green", lw=1, label="turn rate [deg/s]")
        ax2.plot(tt, dspeed, "-", color="tab:red", lw=1, label="dv/dt [m/s$^2$]")
    colours = {"cv": "tab:blue", "ca": "tab:orange", "ct": "tab:purple"}
    for j, n in enumerate(names):
        ax.plot(times, means[j], "-", lw=1.5, color=colours.get(n), label=f"mean mu {n.upper()}")
    ax.set_ylim(0, 1.0)
    ax.set_ylabel("mode probability")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7)
    ax.set_title(f"{args.title}: mean mode probabilities of the scored track ({len(runs)} runs)", fontsize=9)
    ax2.set_ylabel("truth")
    ax2.set_xlabel("time [s]")
    ax2.grid(True, alpha=0.3)
    ax2.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7)
    save_figure(plt, fig, args.out)


def plot_gospa(plt, args):
    rows = read_rows(args.steps)
    names = [c[len("gospa_m_"):] for c in (rows[0].keys() if rows else []) if c.startswith("gospa_m_")]
    if not rows or not names:
        print(f"warning: {args.steps} holds no GOSPA columns; no plot", file=sys.stderr)
        return False
    t = [number(r["time_s"]) for r in rows]
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(11, 6), sharex=True)
    colours = {"gnn": "tab:blue", "nn": "tab:orange", "oracle": "tab:green"}
    for n in names:
        ax.plot(t, [number(r["gospa_m_" + n]) for r in rows], "-", lw=1.2, color=colours.get(n), label=n)
        ax2.plot(t, [number(r["ospa_m_" + n]) for r in rows], "-", lw=1.2, color=colours.get(n), label=n)
    ax.set_ylabel("mean GOSPA [m]")
    ax2.set_ylabel("mean OSPA [m]")
    ax2.set_xlabel("time [s]")
    for a in (ax, ax2):
        a.grid(True, alpha=0.3)
        a.set_ylim(bottom=0)
        a.legend(loc="upper right", fontsize=8)
    ax.set_title(f"{args.title}: GOSPA and OSPA per step, mean over runs", fontsize=9)
    save_figure(plt, fig, args.out)
    return True


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
    m = sub.add_parser("modes")
    m.add_argument("--modes", required=True)
    m.add_argument("--steps", required=True)
    m.add_argument("--out", required=True)
    m.add_argument("--title", default="kestrel-sim")
    m.add_argument("--turn-radps", type=float, default=0.02, help="mark the truth's turns above this rate")
    m.add_argument("--speed-mps2", type=float, default=2.0, help="mark the truth's speed changes above this")
    g = sub.add_parser("gospa")
    g.add_argument("--steps", required=True, help="multi_steps.csv of `kestrel-sim run` of a multi-target scenario")
    g.add_argument("--out", required=True)
    g.add_argument("--title", default="kestrel-sim")
    args = p.parse_args()

    plt = load_matplotlib()
    if args.mode == "run":
        plot_run(plt, args)
    elif args.mode == "modes":
        plot_modes(plt, args)
    elif args.mode == "gospa":
        return 0 if plot_gospa(plt, args) else 1
    else:
        plot_summary(plt, args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
