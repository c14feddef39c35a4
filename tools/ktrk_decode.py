#!/usr/bin/env python3
"""Decode KTRK v1 track records (the binary track output of every board,
targets/common/include/kestrel/board/ktrk_record.hpp) into CSV on stdout.

  tools/ktrk_decode.py tracks.ktrk > tracks.csv
  tools/ktrk_decode.py - < /dev/ttyUSB0        # a board's UART, via a raw tty

Records are 56 bytes, little-endian, with a CRC-32 (IEEE, the wire format's)
over the first 52. Bytes that do not start a record with a valid CRC are
skipped one at a time until the magic is found again; the number of skipped
bytes and of records with a bad CRC go to stderr. Exit status: 0, or 1 if
any record had a bad CRC or any byte was skipped.
"""

import struct
import sys
import zlib

MAGIC = 0x4B52544B
SIZE = 56
FIELDS = ("t_us", "track_id", "status", "associated", "x_mm", "y_mm", "vx_mmps", "vy_mmps", "pos_sigma_mm",
          "age", "hits", "misses", "measurement_index", "nis_centi")
STATUS = {1: "tentative", 2: "confirmed"}


def records(data):
    """Yield (fields dict) for every valid record; count skipped bytes and bad CRCs."""
    stats = {"skipped": 0, "bad_crc": 0}
    i = 0
    out = []
    while i + SIZE <= len(data):
        magic, version = struct.unpack_from("<IB", data, i)
        if magic != MAGIC or version != 1:
            i += 1
            stats["skipped"] += 1
            continue
        (crc,) = struct.unpack_from("<I", data, i + 52)
        if zlib.crc32(data[i:i + 52]) & 0xFFFFFFFF != crc:
            stats["bad_crc"] += 1
            i += 1
            continue
        (_, _, status, flags, _, track_id, t_us, x, y, vx, vy, sigma, age, hits, misses, midx, nis,
         _) = struct.unpack_from("<IBBBBIqiiiiIHHHhHH", data, i)
        out.append({"t_us": t_us, "track_id": track_id, "status": STATUS.get(status, str(status)),
                    "associated": flags & 1, "x_mm": x, "y_mm": y, "vx_mmps": vx, "vy_mmps": vy,
                    "pos_sigma_mm": sigma, "age": age, "hits": hits, "misses": misses,
                    "measurement_index": midx, "nis_centi": nis})
        i += SIZE
    stats["skipped"] += len(data) - i
    return out, stats


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    data = sys.stdin.buffer.read() if argv[1] == "-" else open(argv[1], "rb").read()
    rows, stats = records(data)
    print(",".join(FIELDS))
    for r in rows:
        print(",".join(str(r[f]) for f in FIELDS))
    if stats["skipped"] or stats["bad_crc"]:
        sys.stderr.write("ktrk_decode: %d records, %d bytes skipped, %d bad CRCs\n"
                         % (len(rows), stats["skipped"], stats["bad_crc"]))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
