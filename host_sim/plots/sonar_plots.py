#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Figures of one UW run and of its Monte Carlo, like paper 003's figures 1-3
(called by `kestrel-sim run -s uw003`; runnable by hand).

  sonar_plots.py --dir D [--title X]

Reads D/sonar_truth.csv, D/sonar_track.csv, D/sonar_arrivals.csv (run 0) and
D/sonar_steps.csv (per-frame RMSE over the runs), written by `kestrel-sim run -s uw003`,
and draws:
  D/sonar_track.png        the track as x-y and x-z projections (truth green,
                        estimate red, beacons, the seabed; the fix frame
                        marked), paper fig. 1;
  D/sonar_error.png        position error per frame: run 0's 3D, horizontal and
                        depth error, and the Monte Carlo RMSE per frame,
                        paper fig. 2; frames with an outlier gated marked;
  D/sonar_sound_speed.png  sound speed estimate (+-2 sigma) against the truth
                        for run 0, and the RMS error per frame over the runs,
                        paper fig. 3.
Only the csv module is used; without matplotlib it prints a warning and
exits 1.
"""
import argparse
import math
import os
import sys

from plot_common import load_matplotlib, number, read_rows, save_figure






def col(rs, name):
    return [number(r[name]) for r in rs]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dir", required=True)
    ap.add_argument("--title", default="UW run 0")
    a = ap.parse_args()
    plt = load_matplotlib()
    truth = read_rows(os.path.join(a.dir, "sonar_truth.csv"))
    track = [r for r in read_rows(os.path.join(a.dir, "sonar_track.csv")) if r["reported"] == "1"]
    arrivals = read_rows(os.path.join(a.dir, "sonar_arrivals.csv"))
    steps = read_rows(os.path.join(a.dir, "sonar_steps.csv"))
    summary_path = os.path.join(a.dir, "summary.json")
    beacons = []
    seabed = math.nan
    if os.path.exists(summary_path):
        import json
        with open(summary_path) as f:
            results = json.load(f).get("results", {})
        # The sonar entry: results[<scenario>]["sonar-ekf"].
        for entries in results.values():
            s = entries.get("sonar-ekf")
            if s is not None:
                beacons = s["scenario"]["beacons_m"]
                seabed = s["scenario"]["seabed_depth_m"]
                break

    tx, ty, tz, tc = col(truth, "x_m"), col(truth, "y_m"), col(truth, "z_m"), col(truth, "c_mps")
    kx = [int(r["frame"]) for r in track]
    ex, ey, ez, ec = col(track, "x_m"), col(track, "y_m"), col(track, "z_m"), col(track, "c_mps")
    sc = col(track, "sd_c_mps")
    fixes = [i for i, r in enumerate(track) if r["initialised"] == "1"]

    # Figure 1: x-y and x-z projections.
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5.2))
    ax1.plot(tx, ty, "g-", lw=1.5, label="truth")
    ax1.plot(ex, ey, "r.-", lw=0.8, ms=3, label="EKF estimate")
    if fixes:
        ax1.plot([ex[i] for i in fixes], [ey[i] for i in fixes], "ks", mfc="none", label="multilateration fix")
    if beacons:
        ax1.plot([b[0] for b in beacons], [b[1] for b in beacons], "b^", label="beacons")
    ax1.set_xlabel("x (m)")
    ax1.set_ylabel("y (m)")
    ax1.set_title("x-y")
    ax1.axis("equal")
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    # Zoom on the track, beacons at the edges would hide it.
    pad = 15.0
    xs = [v for v in tx + ex if math.isfinite(v)]
    ys = [v for v in ty + ey if math.isfinite(v)]
    ax1.set_xlim(min(xs) - pad, max(xs) + pad)
    ax1.set_ylim(min(ys) - pad, max(ys) + pad)
    ax2.plot(tx, tz, "g-", lw=1.5, label="truth")
    ax2.plot(ex, ez, "r.-", lw=0.8, ms=3, label="EKF estimate")
    if fixes:
        ax2.plot([ex[i] for i in fixes], [ez[i] for i in fixes], "ks", mfc="none", label="multilateration fix")
    zs = [v for v in tz + ez if math.isfinite(v)]
    zlo, zhi = min(zs + [0.0]) - 5, max(zs) + 10
    if math.isfinite(seabed):
        ax2.axhline(seabed, color="saddlebrown", lw=2, label=f"seabed {seabed:g} m")
        zhi = max(zhi, seabed + 5)
    ax2.axhline(0.0, color="b", lw=1, ls=":", label="surface (beacons)")
    ax2.set_ylim(zhi, zlo)  # depth positive down
    ax2.set_xlabel("x (m)")
    ax2.set_ylabel("depth z (m, down)")
    ax2.set_title("x-z")
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=8)
    fig.suptitle(a.title + " - track (paper 003 fig. 1)")
    save_figure(plt, fig, os.path.join(a.dir, "sonar_track.png"))

    # Figure 2: position error per frame.
    e3, eh, ed = [], [], []
    for r, k in zip(track, kx):
        dx, dy, dz = number(r["x_m"]) - tx[k], number(r["y_m"]) - ty[k], number(r["z_m"]) - tz[k]
        e3.append(math.sqrt(dx * dx + dy * dy + dz * dz))
        eh.append(math.hypot(dx, dy))
        ed.append(abs(dz))
    gated_outlier_frames = sorted({int(r["frame"]) for r in arrivals if r["outlier"] == "1" and r["gated"] == "1"})
    missed_outlier_frames = sorted({int(r["frame"]) for r in arrivals if r["outlier"] == "1" and r["fused"] == "1"})
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    ax1.plot(kx, e3, "k-", label="3D")
    ax1.plot(kx, eh, "b-", label="horizontal")
    ax1.plot(kx, ed, "r--", label="|depth|")
    for k in gated_outlier_frames:
        ax1.axvline(k, color="orange", alpha=0.25, lw=3)
    for k in missed_outlier_frames:
        ax1.axvline(k, color="purple", alpha=0.4, lw=1, ls=":")
    ax1.set_ylabel("run 0 error (m)")
    ax1.set_title("run 0 (orange: outlier gated out; purple dotted: outlier fused)")
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    sk = [int(r["frame"]) for r in steps]
    ax2.plot(sk, col(steps, "rmse_3d_m"), "k-", label="3D")
    ax2.plot(sk, col(steps, "rmse_h_m"), "b-", label="horizontal")
    ax2.plot(sk, col(steps, "rmse_depth_m"), "r--", label="depth")
    nruns = max((int(r["runs_scored"]) for r in steps), default=0)
    ax2.set_title(f"RMSE per frame over {nruns} runs")
    ax2.set_xlabel("frame (1 s)")
    ax2.set_ylabel("RMSE (m)")
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=8)
    fig.suptitle(a.title + " - position error (paper 003 fig. 2)")
    save_figure(plt, fig, os.path.join(a.dir, "sonar_error.png"))

    # Figure 3: sound speed.
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    ax1.plot(list(range(len(tc))), tc, "g-", lw=1.5, label="truth")
    ax1.plot(kx, ec, "r.-", ms=3, label="EKF estimate")
    ax1.fill_between(kx, [c - 2 * s for c, s in zip(ec, sc)], [c + 2 * s for c, s in zip(ec, sc)], color="r",
                     alpha=0.15, label="estimate +- 2 sigma")
    ax1.set_ylabel("c (m/s)")
    ax1.set_title("run 0")
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    ax2.plot(sk, col(steps, "c_err_rms_mps"), "k-")
    ax2.set_title(f"RMS sound-speed error per frame over {nruns} runs")
    ax2.set_xlabel("frame (1 s)")
    ax2.set_ylabel("RMS error (m/s)")
    ax2.grid(alpha=0.3)
    fig.suptitle(a.title + " - sound speed (paper 003 fig. 3)")
    save_figure(plt, fig, os.path.join(a.dir, "sonar_sound_speed.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
