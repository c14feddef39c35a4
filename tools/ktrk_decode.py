#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Decode KTRK track records (the binary track output of every board, layout
in docs/wire_format.md, "Track records (KTRK v2)") into CSV on stdout.

  tools/ktrk_decode.py tracks.ktrk > tracks.csv
  tools/ktrk_decode.py - < /dev/ttyUSB0        # a board's UART, via a raw tty

Reads v2 (64 bytes, CRC-32 over the first 60; a layout code says what the
state components are) and v1 (56 bytes, CRC over the first 52; Cartesian
x, y, vx, vy), little-endian, CRC-32 IEEE as the wire format's. The CSV has
the common columns, then the state columns of every layout met, in the
order first met (x_mm, y_mm, ... for Cartesian; rb_mm, drb_mmps for
bistatic); a cell is empty where a record's layout lacks the column.
Bytes that do not start a record with a valid CRC are skipped one at a time
until the magic is found again; the number of skipped bytes and of records
with a bad CRC go to stderr. Exit status: 0, or 1 if any record had a bad
CRC or any byte was skipped.
"""

import struct
import sys
import zlib

MAGIC = 0x4B52544B
SIZE = {1: 56, 2: 64}
COMMON = ("t_us", "track_id", "status", "associated", "version", "layout")
TAIL = ("age", "hits", "misses", "measurement_index", "nis_centi")
STATUS = {1: "tentative", 2: "confirmed"}
# Layout code -> (name, state component columns, sigma column).
LAYOUTS = {
    1: ("cartesian2d_cv", ("x_mm", "y_mm", "vx_mmps", "vy_mmps"), "pos_sigma_mm"),
    2: ("cartesian2d_ca", ("x_mm", "y_mm", "vx_mmps", "vy_mmps", "ax_mmps2", "ay_mmps2"), "pos_sigma_mm"),
    3: ("bistatic1d", ("rb_mm", "drb_mmps"), "rb_sigma_mm"),
}


def _v1(data, i):
    (_, _, status, flags, _, track_id, t_us, x, y, vx, vy, sigma, age, hits, misses, midx, nis,
     _) = struct.unpack_from("<IBBBBIqiiiiIHHHhHH", data, i)
    r = {"version": 1, "layout": LAYOUTS[1][0], "x_mm": x, "y_mm": y, "vx_mmps": vx, "vy_mmps": vy,
         "pos_sigma_mm": sigma}
    return r, status, flags, track_id, t_us, (age, hits, misses, midx, nis)


def _v2(data, i):
    (_, _, status, flags, code, track_id, t_us) = struct.unpack_from("<IBBBBIq", data, i)
    comps = struct.unpack_from("<6i", data, i + 20)
    (sigma, age, hits, misses, midx, nis, count, _) = struct.unpack_from("<IHHHhHBB", data, i + 44)
    if code not in LAYOUTS or count != len(LAYOUTS[code][1]):
        return None
    name, cols, sigma_col = LAYOUTS[code]
    r = {"version": 2, "layout": name}
    r.update(zip(cols, comps))
    r[sigma_col] = sigma
    return r, status, flags, track_id, t_us, (age, hits, misses, midx, nis)


def records(data):
    """Return (list of field dicts, stats) for every valid record; count skipped bytes and bad CRCs."""
    stats = {"skipped": 0, "bad_crc": 0}
    i = 0
    out = []
    while i + 5 <= len(data):
        magic, version = struct.unpack_from("<IB", data, i)
        size = SIZE.get(version)
        if magic != MAGIC or size is None or i + size > len(data):
            i += 1
            stats["skipped"] += 1
            continue
        (crc,) = struct.unpack_from("<I", data, i + size - 4)
        if zlib.crc32(data[i:i + size - 4]) & 0xFFFFFFFF != crc:
            stats["bad_crc"] += 1
            i += 1
            continue
        decoded = (_v1 if version == 1 else _v2)(data, i)
        if decoded is None:  # a valid CRC over a layout this decoder does not know
            i += 1
            stats["skipped"] += 1
            continue
        r, status, flags, track_id, t_us, tail = decoded
        r.update({"t_us": t_us, "track_id": track_id, "status": STATUS.get(status, str(status)),
                  "associated": flags & 1})
        r.update(zip(TAIL, tail))
        out.append(r)
        i += size
    stats["skipped"] += len(data) - i
    return out, stats


def columns(rows):
    """The CSV header: common columns, the state columns of the layouts met, then the rest."""
    state = []
    for r in rows:
        for k in r:
            if k not in COMMON and k not in TAIL and k not in state:
                state.append(k)
    return list(COMMON) + state + list(TAIL)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    data = sys.stdin.buffer.read() if argv[1] == "-" else open(argv[1], "rb").read()
    rows, stats = records(data)
    fields = columns(rows) if rows else list(COMMON) + list(LAYOUTS[1][1]) + [LAYOUTS[1][2]] + list(TAIL)
    print(",".join(fields))
    for r in rows:
        print(",".join(str(r.get(f, "")) for f in fields))
    if stats["skipped"] or stats["bad_crc"]:
        sys.stderr.write("ktrk_decode: %d records, %d bytes skipped, %d bad CRCs\n"
                         % (len(rows), stats["skipped"], stats["bad_crc"]))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
