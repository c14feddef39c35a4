#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the seed corpora of the PCL and sonar tracker fuzzers
(tests/fuzz/corpus/pcl_tracker/, tests/fuzz/corpus/sonar_tracker/) in
the byte format of pcl_tracker_invariants.hpp and
sonar_tracker_invariants.hpp. Run from the repository root:
    python3 tests/fuzz/make_tracker_seeds.py
"""
import os
import random
import struct

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")

# Time-step choices of fuzz_bytes.hpp (op bits 0-1) and their operands.
PERIOD, SIGNED_MS, ABSOLUTE_US, GAP_MS = 0, 1, 2, 3


def time_operand(kind, value):
    if kind == SIGNED_MS:
        return struct.pack("<h", value)
    if kind == ABSOLUTE_US:
        return struct.pack("<q", value)
    if kind == GAP_MS:
        return struct.pack("<I", value)
    return b""


def frame(kind, count, items, value=0, high=0):
    """One frame: op byte (time kind, item count, bits 6-7), operand, items."""
    return bytes([kind | (count << 2) | (high << 6)]) + time_operand(kind, value) + b"".join(items)


# PCL: per candidate, bit 0 clear = target (bits 1-2) with noise (bits 3-7);
# 01 = clutter (u16 range in 3 m, i16 Doppler in 1/8 Hz); 11 = raw.
def pcl_target(rng, target):
    return bytes([(target << 1) | (rng.randrange(32) << 3)])


def pcl_clutter(rng):
    return bytes([1 | (rng.randrange(64) << 2)]) + struct.pack("<Hh", rng.randrange(65536), rng.randrange(-32768, 32768))


def pcl_raw(range_mm, doppler_mhz, snr_cdb):
    return bytes([3]) + struct.pack("<Iih", range_mm, doppler_mhz, snr_cdb)


def pcl_tracking(rng, n, clutter=1, targets=(0, 1, 2, 3)):
    out = []
    for _ in range(n):
        items = [pcl_target(rng, t) for t in targets] + [pcl_clutter(rng) for _ in range(clutter)]
        rng.shuffle(items)
        out.append(frame(PERIOD, len(items), items))
    return out


def pcl_seeds():
    rng = random.Random(2026)
    seeds = {}
    seeds["normal_tracking"] = pcl_tracking(rng, 40)
    seeds["zero_doppler_crossing"] = pcl_tracking(rng, 40, clutter=0, targets=(3,))
    seeds["dropouts"] = (pcl_tracking(rng, 15) + [frame(PERIOD, 0, [])] * 4 + pcl_tracking(rng, 5) +
                         [frame(GAP_MS, 0, [], 60000)] + pcl_tracking(rng, 8) +
                         [frame(GAP_MS, 2, [pcl_target(rng, 0), pcl_target(rng, 1)], 3600000)] + pcl_tracking(rng, 8))
    seeds["step_back"] = (pcl_tracking(rng, 15) + [frame(SIGNED_MS, 4, [pcl_target(rng, t) for t in range(4)], -2000)] +
                          pcl_tracking(rng, 3) + [frame(SIGNED_MS, 4, [pcl_target(rng, t) for t in range(4)], 0)] +
                          [frame(SIGNED_MS, 0, [], -30000)] * 4 + pcl_tracking(rng, 10))
    seeds["far_future_frame"] = (pcl_tracking(rng, 15) +
                                 [frame(ABSOLUTE_US, 4, [pcl_target(rng, t) for t in range(4)], 2**63 - 1000)] +
                                 pcl_tracking(rng, 10) + [frame(ABSOLUTE_US, 1, [pcl_target(rng, 0)], -(2**63))] +
                                 pcl_tracking(rng, 6))
    seeds["too_many_candidates"] = pcl_tracking(rng, 12) + [
        frame(PERIOD, 15, [pcl_target(rng, k % 4) for k in range(4)] + [pcl_clutter(rng) for _ in range(11)])
        for _ in range(20)]
    seeds["extreme_values"] = pcl_tracking(rng, 10) + [
        frame(PERIOD, 4, [pcl_raw(0, 0, 0), pcl_raw(0xFFFFFFFF, 2**31 - 1, 32767),
                          pcl_raw(200000000, -(2**31), -32768), pcl_raw(1, 5000000, 0)]),
        frame(PERIOD, 2, [pcl_raw(200000000, 5000000, 100), pcl_raw(200000001, -5000001, 100)]),
        frame(PERIOD, 1, [pcl_raw(0, 855, 0)])] + pcl_tracking(rng, 10)
    return seeds


# Sonar: op bits 6-7 = the beacon the target's arrivals start at; per
# arrival, bit 0 clear = target (noise bits 1-5, bits 6-7 = 11 late by 40 ms);
# bit 0 set = raw u32 ns, beacon bits 4-6 (or a raw u8 with bit 7), path
# code bits 1-3 (6-7 not a path).
def sonar_target(rng, late=False):
    return bytes([(rng.randrange(32) << 1) | ((3 if late else rng.randrange(3)) << 6)])


def sonar_raw(ns, beacon, code):
    if beacon < 8:
        return bytes([1 | (code << 1) | (beacon << 4)]) + struct.pack("<I", ns)
    return bytes([1 | (code << 1) | 0x80]) + struct.pack("<IB", ns, beacon)


def sonar_tracking(rng, n, count=8):
    return [frame(PERIOD, count, [sonar_target(rng) for _ in range(count)], high=rng.randrange(4)) for _ in range(n)]


def sonar_seeds():
    rng = random.Random(2027)
    seeds = {}
    seeds["normal_tracking"] = sonar_tracking(rng, 20)
    seeds["direct_only_and_partial"] = (sonar_tracking(rng, 3) + sonar_tracking(rng, 6, count=4) +
                                        sonar_tracking(rng, 6, count=5) + sonar_tracking(rng, 6, count=2))
    seeds["outliers"] = sonar_tracking(rng, 3) + [
        frame(PERIOD, 8, [sonar_target(rng, late=(k in (1, 6))) for k in range(8)]) for _ in range(6)] + [
        frame(PERIOD, 8, [sonar_target(rng, late=True) for _ in range(8)]) for _ in range(4)] + sonar_tracking(rng, 5)
    seeds["dropouts"] = (sonar_tracking(rng, 5) + [frame(PERIOD, 0, [])] * 4 + sonar_tracking(rng, 3) +
                         [frame(GAP_MS, 8, [sonar_target(rng) for _ in range(8)], 59000)] + sonar_tracking(rng, 2) +
                         [frame(GAP_MS, 8, [sonar_target(rng) for _ in range(8)], 120000)] + sonar_tracking(rng, 4))
    seeds["step_back"] = (sonar_tracking(rng, 8) + [frame(SIGNED_MS, 8, [sonar_target(rng) for _ in range(8)], -1500)] +
                          [frame(SIGNED_MS, 8, [sonar_target(rng) for _ in range(8)], 0)] + sonar_tracking(rng, 5))
    seeds["far_future_frame"] = (sonar_tracking(rng, 8) +
                                 [frame(ABSOLUTE_US, 8, [sonar_target(rng) for _ in range(8)], 2**63 - 1)] +
                                 sonar_tracking(rng, 3) + [frame(ABSOLUTE_US, 8, [sonar_target(rng) for _ in range(8)], -(2**63))])
    seeds["too_many_arrivals"] = sonar_tracking(rng, 4) + sonar_tracking(rng, 8, count=15) + [
        frame(PERIOD, 12, [sonar_target(rng) for _ in range(8)] + [sonar_raw(7, 9, 7)] * 4)]
    seeds["extreme_values"] = sonar_tracking(rng, 6) + [
        frame(PERIOD, 2, [sonar_target(rng), sonar_raw(0, 3, 1)]),
        frame(PERIOD, 2, [sonar_target(rng), sonar_raw(0xFFFFFFFF, 1, 1)]),
        frame(PERIOD, 2, [sonar_target(rng), sonar_raw(1, 255, 0)]),
        frame(PERIOD, 2, [sonar_target(rng), sonar_raw(500000000, 5, 0)]),
        frame(PERIOD, 2, [sonar_target(rng), sonar_raw(500000000, 2, 7)]),
        frame(PERIOD, 5, [sonar_raw(1, b, 0) for b in range(4)] + [sonar_raw(1, 0, 1)]),
        frame(PERIOD, 8, [sonar_target(rng) for _ in range(7)] + [sonar_raw(1333333, 3, 1)])] + sonar_tracking(rng, 6)
    return seeds


def write(name, seeds):
    d = os.path.join(ROOT, name)
    os.makedirs(d, exist_ok=True)
    for seed, frames in seeds.items():
        with open(os.path.join(d, seed), "wb") as f:
            f.write(b"".join(frames))


if __name__ == "__main__":
    write("pcl_tracker", pcl_seeds())
    write("sonar_tracker", sonar_seeds())
