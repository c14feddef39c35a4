#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Compare the float tracker's reports from the host and from a board's code
generation (float_agreement.cpp prints them).

usage: compare.py <host output> <board output> --exact
       compare.py <host output> <board output> --position-m D --variance-rel R

Both modes need the same reports in the same order: scenario, step, track id
and status equal line by line. --exact then needs every bit of every state
and variance equal; otherwise each state component may differ by D metres
(positions; velocities and accelerations by D per second and per second
squared) and each variance by R relative. Prints the count of reports that
are bit-identical and the largest differences either way."""
import argparse
import struct
import sys


def as_float(word):
    return struct.unpack("<f", struct.pack("<I", int(word, 16)))[0]


def load(path):
    with open(path) as f:
        rows = [line.split() for line in f if line.strip()]
    for row in rows:
        if len(row) != 16:
            sys.exit("%s: malformed line %r" % (path, " ".join(row)))
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("host")
    ap.add_argument("board")
    ap.add_argument("--exact", action="store_true")
    ap.add_argument("--position-m", type=float)
    ap.add_argument("--variance-rel", type=float)
    a = ap.parse_args()
    if not a.exact and (a.position_m is None or a.variance_rel is None):
        ap.error("give --exact or both --position-m and --variance-rel")

    host, board = load(a.host), load(a.board)
    if not host:
        sys.exit("FAIL: the host printed no reports")
    if len(host) != len(board):
        sys.exit("FAIL: host %d reports, board %d" % (len(host), len(board)))
    identical = 0
    worst_state = 0.0
    worst_var = 0.0
    for h, b in zip(host, board):
        if h[:4] != b[:4]:
            sys.exit("FAIL: report differs in scenario, step, id or status: host %s, board %s"
                     % (" ".join(h[:4]), " ".join(b[:4])))
        if h == b:
            identical += 1
            continue
        for i in range(4, 10):
            worst_state = max(worst_state, abs(as_float(h[i]) - as_float(b[i])))
        for i in range(10, 16):
            hv, bv = as_float(h[i]), as_float(b[i])
            if not (hv > 0.0 and bv > 0.0):
                sys.exit("FAIL: a variance that is not positive: host %g, board %g" % (hv, bv))
            worst_var = max(worst_var, abs(hv - bv) / hv)
    print("%d reports, %d bit-identical; largest state difference %.6g, largest relative variance difference %.3g"
          % (len(host), identical, worst_state, worst_var))
    if a.exact:
        if identical != len(host):
            sys.exit("FAIL: %d reports differ in their bits" % (len(host) - identical))
    elif worst_state > a.position_m or worst_var > a.variance_rel:
        sys.exit("FAIL: over the tolerance (%g m, %g relative)" % (a.position_m, a.variance_rel))
    print("PASS")


if __name__ == "__main__":
    main()
