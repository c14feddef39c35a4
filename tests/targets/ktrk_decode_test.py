#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ktrk_decode_reads_v1_and_v2: tools/ktrk_decode.py on a stream of a v1
record (packed here from the v1 layout), the two v2 records that
tests/targets/ktrk_record_test.cpp checks the C++ encoder against (a CA
radar report, layout 2, and a PCL report, layout 3), a v2 record with a
damaged byte, and noise between them (one a false "KTRK" v2 header): every
good record comes out with its fields, the damaged one and the false start
are counted as bad CRCs and the noise as skipped bytes, and the CSV has
both layouts' columns.
usage: ktrk_decode_test.py <src dir>
"""
import contextlib
import io
import os
import struct
import sys
import zlib

sys.path.insert(0, os.path.join(sys.argv[1], "tools"))
import ktrk_decode  # noqa: E402

# Same strings as kGoldenCa / kGoldenPcl in ktrk_record_test.cpp.
GOLDEN_CA = bytes.fromhex(
    "4b54524b0202010204030201cb04fb711f01000044d612008eeff0ffa9cfffff581b0000f401000006ffffff88130000"
    "2c01fa000200110096000600b362bd7b")
GOLDEN_PCL = bytes.fromhex(
    "4b54524b0202010304030201cb04fb711f010000aafeb802941dfeff0000000000000000000000000000000010270000"
    "2c01fa0002001100960002005045ca7a")

body = struct.pack("<IBBBBIqiiiiIHHHhHH", 0x4B52544B, 1, 1, 0, 0, 7, 500000, 1000, -2000, 30, -40, 250,
                   3, 2, 1, -1, 42, 0)
v1 = body + struct.pack("<I", zlib.crc32(body) & 0xFFFFFFFF)
damaged = bytearray(GOLDEN_PCL)
damaged[25] ^= 0x10
stream = b"\x00KTR" + v1 + b"KTRK\x02junk" + GOLDEN_CA + bytes(damaged) + GOLDEN_PCL + b"\xff\xff"

rows, stats = ktrk_decode.records(stream)
assert len(rows) == 3, rows
# Bad CRCs: the false start "KTRK\x02junk..." and the damaged record. Skipped:
# the 4 noise bytes, the false start's other 8, the damaged record's other 63, the tail.
assert stats["bad_crc"] == 2, stats
assert stats["skipped"] == 4 + 8 + 63 + 2, stats

r1, ca, pcl = rows
assert r1["version"] == 1 and r1["layout"] == "cartesian2d_cv", r1
assert (r1["t_us"], r1["track_id"], r1["status"], r1["x_mm"], r1["y_mm"], r1["vx_mmps"], r1["vy_mmps"],
        r1["pos_sigma_mm"], r1["measurement_index"], r1["nis_centi"]) == (500000, 7, "tentative", 1000, -2000, 30,
                                                                         -40, 250, -1, 42), r1
for r in (ca, pcl):
    assert r["version"] == 2, r
    assert (r["t_us"], r["track_id"], r["status"], r["associated"]) == (1234567890123, 0x01020304, "confirmed", 1), r
    assert (r["age"], r["hits"], r["misses"], r["measurement_index"], r["nis_centi"]) == (300, 250, 2, 17, 150), r
assert ca["layout"] == "cartesian2d_ca", ca
assert (ca["x_mm"], ca["y_mm"], ca["vx_mmps"], ca["vy_mmps"], ca["ax_mmps2"], ca["ay_mmps2"], ca["pos_sigma_mm"]) == \
    (1234500, -987250, -12375, 7000, 500, -250, 5000), ca
assert pcl["layout"] == "bistatic1d", pcl
assert (pcl["rb_mm"], pcl["drb_mmps"], pcl["rb_sigma_mm"]) == (45678250, -123500, 10000), pcl
assert "x_mm" not in pcl

# The CSV: one header with both layouts' columns, empty cells where a layout lacks one.
path = os.path.join(os.environ.get("TMPDIR", "/tmp"), "ktrk_decode_test.%d.ktrk" % os.getpid())
with open(path, "wb") as f:
    f.write(GOLDEN_CA + GOLDEN_PCL)
out = io.StringIO()
with contextlib.redirect_stdout(out):
    rc = ktrk_decode.main(["ktrk_decode.py", path])
os.remove(path)
assert rc == 0, rc
lines = out.getvalue().splitlines()
header = lines[0].split(",")
assert header[:6] == ["t_us", "track_id", "status", "associated", "version", "layout"], header
assert "x_mm" in header and "rb_mm" in header and "ax_mmps2" in header, header
pcl_row = dict(zip(header, lines[2].split(",")))
assert pcl_row["rb_mm"] == "45678250" and pcl_row["x_mm"] == "", pcl_row
print("PASS: v1 and v2 (layouts 2 and 3) decoded, 2 bad CRCs and %d noise bytes counted" % stats["skipped"])
