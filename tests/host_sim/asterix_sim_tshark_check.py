#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Wireshark judges kestrel-sim's ASTERIX files (CTest
asterix.tshark_judges_kestrel_sim, label asterix; docs/asterix.md).

  kestrel-sim generate --scenario s1 --seed 1 --asterix --sac 25  -> s1.ast (CAT048)
  kestrel-sim replay --asterix s1.ast --ungated --asterix-out tracks062.ast --sac 7 --sic 9
                                                                  -> tracks CSV + CAT062

Both .ast files are split into their data blocks (by LEN), one UDP datagram
per block, written as pcaps and decoded by tshark's ASTERIX dissector. The
check fails on any malformed or expert item, and compares every CAT048
record with the plot CSV (RHO, THETA as 90 deg - bearing, time, SAC/SIC)
and every CAT062 record with the replay's track CSV, row by row (time,
X, Y, VX, VY, track number, CNF, APC, SAC/SIC), each within half an LSB.

Usage: asterix_sim_tshark_check.py <kestrel-sim> <work dir>
Exit 77 (CTest skip) when tshark is not installed.
"""
import csv
import math
import shutil
import struct
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "hal"))
from asterix_tshark_check import PORT, Checker, expert_lines, messages  # noqa: E402


def blocks(data):
    """Split concatenated ASTERIX data blocks by their LEN."""
    out, pos = [], 0
    while pos < len(data):
        if len(data) - pos < 3:
            raise SystemExit(f"trailing {len(data) - pos} bytes are not a block")
        n = struct.unpack(">H", data[pos + 1:pos + 3])[0]
        if n < 3 or pos + n > len(data):
            raise SystemExit(f"block at byte {pos} has LEN {n}, {len(data) - pos} bytes left")
        out.append(data[pos:pos + n])
        pos += n
    return out


def ip_checksum(header):
    s = sum(struct.unpack(">10H", header))
    while s >> 16:
        s = (s & 0xFFFF) + (s >> 16)
    return (~s) & 0xFFFF


def write_pcap(path, payloads):
    with open(path, "wb") as f:
        f.write(struct.pack("<IHHiIII", 0xA1B2C3D4, 2, 4, 0, 0, 65535, 1))  # LINKTYPE_ETHERNET
        for i, p in enumerate(payloads):
            udp = struct.pack(">HHHH", PORT, PORT, 8 + len(p), 0) + p
            ip = struct.pack(">BBHHHBBH4s4s", 0x45, 0, 20 + len(udp), i & 0xFFFF, 0, 64, 17, 0,
                             bytes([10, 0, 0, 1]), bytes([10, 0, 0, 2]))
            ip = ip[:10] + struct.pack(">H", ip_checksum(ip)) + ip[12:]
            frame = b"\x02\x00\x00\x00\x00\x02" + b"\x02\x00\x00\x00\x00\x01" + b"\x08\x00" + ip + udp
            f.write(struct.pack("<IIII", i, 0, len(frame), len(frame)))
            f.write(frame)


def run(*cmd):
    print("$", " ".join(str(c) for c in cmd))
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    print(r.stdout, end="")
    if r.returncode != 0:
        print(r.stderr, end="")
        raise SystemExit(f"exit {r.returncode}")
    return r.stdout


def main():
    if shutil.which("tshark") is None:
        print("SKIP: tshark is not installed")
        return 77
    sim, work = Path(sys.argv[1]), Path(sys.argv[2])
    work.mkdir(parents=True, exist_ok=True)
    run(sim, "generate", "--scenario", "s1", "--seed", "1", "--out", work / "s1.kstr", "--asterix", "--sac", "25")
    # Ungated, as S1 is scored: one track over the whole run, so every
    # frame after confirmation has a report to compare.
    run(sim, "replay", "--asterix", work / "s1.ast", "--out", work / "replay", "--no-plots", "--ungated",
        "--asterix-out", work / "tracks062.ast", "--sac", "7", "--sic", "9")

    c = Checker()
    plots = list(csv.DictReader(open(work / "s1.plots.csv")))
    tracks = list(csv.DictReader(open(work / "replay" / "ekf-ca_tracks.csv")))
    pcaps = {}
    for name, rows in (("s1.ast", plots), ("tracks062.ast", tracks)):
        b = blocks((work / name).read_bytes())
        c.equal(f"{name}: data blocks (one per plot frame / track report) vs CSV rows", len(b), len(rows))
        pcap = work / (name + ".pcap")
        write_pcap(pcap, b)
        pcaps[name] = pcap

    for name, pcap in pcaps.items():
        msgs, flagged = messages(pcap)
        lines = expert_lines(pcap)
        print(f"{name}: malformed/expert items in the JSON: {len(flagged)}; `-z expert` lines: {len(lines)}")
        c.equal(f"{name}: malformed or expert items", len(flagged) + len(lines), 0)

    msgs, _ = messages(pcaps["s1.ast"])
    c.equal("CAT048 records vs plot CSV rows", len(msgs), len(plots))
    for i, (m, p) in enumerate(zip(msgs, plots)):
        if i % 50 == 0:
            print(f" CAT048 record {i}")
        c.equal("SAC", int(m["asterix.048_010_SAC"], 0), 25)
        c.equal("SIC = sensor_id", int(m["asterix.048_010_SIC"], 0), int(p["sensor_id"]))
        c.near("time of day s", float(m["asterix.048_140_VALUE"]), float(p["time_s"]), 1 / 256)
        # The CSV holds the wire-quantised plot (1 mm, 2^-32 turn): half an
        # ASTERIX LSB plus that.
        c.near("RHO NM", float(m["asterix.048_040_RHO"]), float(p["range_m"]) / 1852.0, 1 / 512 + 1e-6)
        az = (90.0 - math.degrees(float(p["bearing_rad"]))) % 360.0
        c.near_angle("THETA deg vs 90 - bearing", float(m["asterix.048_040_THETA"]), az, 360 / 2**17 + 1e-6)

    msgs, _ = messages(pcaps["tracks062.ast"])
    c.equal("CAT062 records vs track CSV rows", len(msgs), len(tracks))
    for i, (m, t) in enumerate(zip(msgs, tracks)):
        if i % 50 == 0:
            print(f" CAT062 record {i}")
        c.equal("SAC", int(m["asterix.062_010_SAC"], 0), 7)
        c.equal("SIC", int(m["asterix.062_010_SIC"], 0), 9)
        c.near("time of track s", float(m["asterix.062_070_VALUE"]), float(t["time_s"]), 1 / 256)
        c.near("X m", float(m["asterix.062_100_X"]), float(t["x_m"]), 0.25)
        c.near("Y m", float(m["asterix.062_100_Y"]), float(t["y_m"]), 0.25)
        c.near("VX m/s", float(m["asterix.062_185_VX"]), float(t["vx_mps"]), 0.125)
        c.near("VY m/s", float(m["asterix.062_185_VY"]), float(t["vy_mps"]), 0.125)
        c.equal("track number", int(m["asterix.062_040_VALUE"], 0), int(t["track_id"]))
        c.equal("CNF (1 tentative)", int(m["asterix.062_080_CNF"]), 0 if t["status"] == "confirmed" else 1)
        c.near("APC X m", float(m["asterix.062_500_APC_X"]), math.sqrt(float(t["p_xx"])), 0.25)
        c.near("APC Y m", float(m["asterix.062_500_APC_Y"]), math.sqrt(float(t["p_yy"])), 0.25)

    print(f"{c.failures} failures")
    return 1 if c.failures else 0


if __name__ == "__main__":
    sys.exit(main())
