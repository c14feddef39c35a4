#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Wireshark as an independent judge of Kestrel's ASTERIX (CTest label `asterix`).

Runs the pcap tool (asterix_pcap_tool.cpp), decodes its CAT048 and CAT062
pcaps with tshark's ASTERIX dissector and checks that nothing is malformed
or flagged by an expert item, and that every decoded value matches: CAT048
against what was written and what Kestrel's reader made of it (azimuth
convention included), CAT062 against the track reports that were written.
Usage: asterix_tshark_check.py <kestrel_asterix_pcap> <work dir>
Exit 77 (CTest skip) when tshark is not installed.
"""
import json
import shutil
import subprocess
import sys
from pathlib import Path

PORT = 8600


def tshark(pcap, *args):
    cmd = ["tshark", "-r", str(pcap), "-d", f"udp.port=={PORT},asterix", *args]
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def messages(pcap):
    """The asterix.message trees in order, each flattened to {field: value}.

    tshark's JSON repeats keys (one asterix.message per record), so pairs are
    kept as lists instead of dicts."""
    doc = json.loads(tshark(pcap, "-T", "json"), object_pairs_hook=list)
    found, flagged = [], []

    def flatten(pairs, into):
        for pair in pairs:
            if not (isinstance(pair, tuple) and len(pair) == 2):
                continue
            key, value = pair
            if isinstance(value, list):
                flatten(value, into)
            else:
                into.setdefault(key, value)

    def walk(node):
        if isinstance(node, list):
            for item in node:
                if isinstance(item, tuple) and len(item) == 2:
                    key, value = item
                    if key.startswith("_ws.malformed") or key.startswith("_ws.expert"):
                        flagged.append(key)
                    if key == "asterix.message":
                        fields = {}
                        flatten(value, fields)
                        found.append(fields)
                        continue
                    walk(value)
                else:
                    walk(item)

    walk(doc)
    return found, flagged


def expert_lines(pcap):
    out = tshark(pcap, "-q", "-z", "expert")
    return [line for line in out.splitlines() if line.strip() and not line.startswith("=")]


class Checker:
    def __init__(self):
        self.failures = 0

    def near(self, what, got, want, tol):
        ok = abs(got - want) <= tol
        if not ok:
            self.failures += 1
        print(f"  {'ok ' if ok else 'BAD'} {what}: tshark {got!r}, Kestrel {want!r} (tolerance {tol})")

    def near_angle(self, what, got, want, tol):
        ok = abs((got - want + 180.0) % 360.0 - 180.0) <= tol
        if not ok:
            self.failures += 1
        print(f"  {'ok ' if ok else 'BAD'} {what}: tshark {got!r}, Kestrel {want!r} (tolerance {tol})")

    def equal(self, what, got, want):
        self.near(what, got, want, 0)


def main():
    if shutil.which("tshark") is None:
        print("tshark not installed (run.sh installs it): skipped")
        return 77
    tool, work = sys.argv[1], Path(sys.argv[2])
    work.mkdir(parents=True, exist_ok=True)
    subprocess.run([tool, str(work)], check=True)
    expected = json.loads((work / "expected.json").read_text())
    print(subprocess.run(["tshark", "--version"], capture_output=True, text=True).stdout.splitlines()[0])
    c = Checker()

    for name in ("cat048.pcap", "cat062.pcap"):
        _, flagged = messages(work / name)
        lines = expert_lines(work / name)
        print(f"{name}: malformed/expert items in the JSON: {len(flagged)}; `-z expert` lines: {len(lines)}")
        for line in lines:
            print("   ", line)
        if flagged or lines:
            c.failures += 1

    print("CAT048 (tshark vs written record vs Kestrel's reader):")
    msgs, _ = messages(work / "cat048.pcap")
    c.equal("records", len(msgs), len(expected["cat048"]))
    for k, (m, w, r) in enumerate(zip(msgs, expected["cat048_written"], expected["cat048"])):
        print(f" record {k}")
        c.equal("SAC", int(m["asterix.048_010_SAC"], 0), w["sac"])
        c.equal("SIC", int(m["asterix.048_010_SIC"], 0), w["sic"])
        c.equal("SIC = frame sensor_id", int(m["asterix.048_010_SIC"], 0), r["sensor_id"])
        c.near("time of day s", float(m["asterix.048_140_VALUE"]), r["t_us"] / 1e6, 1 / 256)
        c.near("RHO NM", float(m["asterix.048_040_RHO"]), r["range_mm"] / 1852000.0, 1 / 512 + 1e-9)
        kestrel_az = (90.0 - r["bearing_bam"] * 360.0 / 2**32) % 360.0
        c.near_angle("THETA deg vs 90 - bearing_bam", float(m["asterix.048_040_THETA"]), kestrel_az, 360 / 2**17)
        c.equal("track number", int(m["asterix.048_161_TRN"], 0), w["track_number"])
        c.equal("Doppler CAL m/s", float(m["asterix.048_120_CAL_CAL"]), w["doppler_mps"])
        c.equal("Doppler as range rate", float(m["asterix.048_120_CAL_CAL"]), r["range_rate_mmps"] / 1000)

    print("CAT062 (tshark vs the track reports written):")
    msgs, _ = messages(work / "cat062.pcap")
    src = expected["cat062_source"]
    c.equal("records", len(msgs), len(expected["cat062"]))
    for k, (m, t) in enumerate(zip(msgs, expected["cat062"])):
        print(f" record {k}")
        c.equal("SAC", int(m["asterix.062_010_SAC"], 0), src["sac"])
        c.equal("SIC", int(m["asterix.062_010_SIC"], 0), src["sic"])
        c.equal("service id", int(m["asterix.062_015_VALUE"], 0), src["service_id"])
        c.near("time of track s", float(m["asterix.062_070_VALUE"]), t["t_us"] / 1e6, 1 / 256)
        c.near("X m", float(m["asterix.062_100_X"]), t["x_m"], 0.25)
        c.near("Y m", float(m["asterix.062_100_Y"]), t["y_m"], 0.25)
        c.near("VX m/s", float(m["asterix.062_185_VX"]), t["vx_mps"], 0.125)
        c.near("VY m/s", float(m["asterix.062_185_VY"]), t["vy_mps"], 0.125)
        c.equal("track number", int(m["asterix.062_040_VALUE"], 0), t["track_id"])
        c.equal("CNF (1 tentative)", int(m["asterix.062_080_CNF"]), 1 if t["tentative"] else 0)
        c.near("APC X m", float(m["asterix.062_500_APC_X"]), t["sigma_x_m"], 0.25)
        c.near("APC Y m", float(m["asterix.062_500_APC_Y"]), t["sigma_y_m"], 0.25)

    print("FAILED" if c.failures else "all checks passed", f"({c.failures} failures)")
    return 1 if c.failures else 0


if __name__ == "__main__":
    sys.exit(main())
