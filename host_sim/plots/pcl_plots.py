#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Range-Doppler plot of one PCL run, like paper 002's figure 2 (called by
`kestrel-sim run -s pcl002`; runnable by hand).

  pcl_plots.py --dir D [--title X] [--out D/pcl_range_doppler.png]

Reads D/pcl_candidates.csv, D/pcl_tracks.csv and D/pcl_truth.csv (written by
`kestrel-sim run -s pcl002`) and draws, in the bistatic range / Doppler plane and
against time:
  - every candidate of every frame (grey dots; zero-Doppler ridge included),
  - the candidates the target track chose (black dots joined by a dotted
    line: the paper's "selected measurements"),
  - the filtered track (red line: the paper's KF estimate),
  - the one-step predictions F x (purple dashed: the paper's prediction step),
  - the truth (green, thin), and any false confirmed track (orange).
The target track is the confirmed track on the target (50 m, 5 m/s) for most
of its life, as in the metrics. Only the csv module is used; without
matplotlib it prints a warning and exits 1.
"""
import argparse
import os
import sys

from plot_common import load_matplotlib, number, read_rows






def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dir", required=True)
    ap.add_argument("--title", default="PCL run 0")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    plt = load_matplotlib()
    cands = read_rows(os.path.join(a.dir, "pcl_candidates.csv"))
    tracks = read_rows(os.path.join(a.dir, "pcl_tracks.csv"))
    truth = read_rows(os.path.join(a.dir, "pcl_truth.csv"))

    # Target tracks: on target in more than half of their reported frames.
    life = {}
    for r in tracks:
        n, on = life.get(r["track_id"], (0, 0))
        life[r["track_id"]] = (n + 1, on + int(r["on_target"]))
    target_ids = {tid for tid, (n, on) in life.items() if 2 * on > n}

    fig = plt.figure(figsize=(13, 7.5))
    gs = fig.add_gridspec(2, 2, width_ratios=[1.25, 1])
    ax_rd = fig.add_subplot(gs[:, 0])
    ax_rt = fig.add_subplot(gs[0, 1])
    ax_ft = fig.add_subplot(gs[1, 1], sharex=ax_rt)

    def scatter_all(ax, x, y, **kw):
        ax.scatter(x, y, s=3, c="0.75", linewidths=0, **kw)

    cx = [number(c["fd_hz"]) for c in cands]
    cy = [number(c["rb_m"]) for c in cands]
    ct = [number(c["time_s"]) for c in cands]
    scatter_all(ax_rd, cx, cy, label="candidates (all frames)")
    scatter_all(ax_rt, ct, cy)
    scatter_all(ax_ft, ct, cx)

    tt = [number(r["time_s"]) for r in truth]
    ax_rd.plot([number(r["fd_hz"]) for r in truth], [number(r["rb_m"]) for r in truth], color="tab:green", lw=1,
               label="truth")
    ax_rt.plot(tt, [number(r["rb_m"]) for r in truth], color="tab:green", lw=1)
    ax_ft.plot(tt, [number(r["fd_hz"]) for r in truth], color="tab:green", lw=1)

    chosen = {}
    for c in cands:
        if c["chosen_by_track"] in target_ids:
            chosen.setdefault(c["chosen_by_track"], []).append(c)
    first = True
    for tid in sorted(life, key=int):
        tr = [r for r in tracks if r["track_id"] == tid]
        t = [number(r["time_s"]) for r in tr]
        rb = [number(r["rb_m"]) for r in tr]
        fd = [number(r["fd_hz"]) for r in tr]
        if tid in target_ids:
            ch = chosen.get(tid, [])
            chx = [number(c["fd_hz"]) for c in ch]
            chy = [number(c["rb_m"]) for c in ch]
            cht = [number(c["time_s"]) for c in ch]
            kw = dict(color="black", ls=":", lw=0.8, marker=".", ms=4)
            ax_rd.plot(chx, chy, label="chosen candidates" if first else None, **kw)
            ax_rt.plot(cht, chy, **kw)
            ax_ft.plot(cht, chx, **kw)
            pt = [number(r["time_s"]) for r in tr]
            prb = [number(r["pred_rb_m"]) for r in tr]
            pfd = [number(r["pred_fd_hz"]) for r in tr]
            kw = dict(color="tab:purple", ls="--", lw=1)
            ax_rd.plot(pfd, prb, label="prediction F x" if first else None, **kw)
            ax_rt.plot(pt, prb, **kw)
            ax_ft.plot(pt, pfd, **kw)
            kw = dict(color="tab:red", lw=1.6)
            ax_rd.plot(fd, rb, label=f"KF track (id {tid})" if first else f"KF track (id {tid})", **kw)
            ax_rt.plot(t, rb, **kw)
            ax_ft.plot(t, fd, **kw)
            first = False
        else:
            kw = dict(color="tab:orange", lw=1.2)
            ax_rd.plot(fd, rb, label=f"false track (id {tid})", **kw)
            ax_rt.plot(t, rb, **kw)
            ax_ft.plot(t, fd, **kw)

    ax_rd.axvspan(-2, 2, color="tab:blue", alpha=0.08, label="no track start (|fD| < 2 Hz)")
    ax_rd.set_xlabel("Doppler fD (Hz)")
    ax_rd.set_ylabel("bistatic range Rb (m)")
    ax_rd.set_title("range-Doppler")
    ax_rd.legend(loc="upper right", fontsize=8, markerscale=2)
    ax_rt.set_ylabel("Rb (m)")
    ax_ft.set_ylabel("fD (Hz)")
    ax_ft.set_xlabel("time (s)")
    if truth:
        lo = min(number(r["rb_m"]) for r in truth)
        hi = max(number(r["rb_m"]) for r in truth)
        ax_rt.set_ylim(lo - 150, hi + 150)
        flo = min(number(r["fd_hz"]) for r in truth)
        fhi = max(number(r["fd_hz"]) for r in truth)
        ax_ft.set_ylim(flo - 15, fhi + 15)
    for ax in (ax_rd, ax_rt, ax_ft):
        ax.grid(True, lw=0.3)
    fig.suptitle(a.title)
    fig.tight_layout()
    out = a.out or os.path.join(a.dir, "pcl_range_doppler.png")
    fig.savefig(out, dpi=130)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
