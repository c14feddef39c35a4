#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Write the seed corpus of the CAT048 fuzzer (tests/fuzz/corpus/asterix_cat048):
a few valid data blocks, item layouts from the CAT048 specification.
Usage: python3 tests/fuzz/make_asterix_seeds.py tests/fuzz/corpus/asterix_cat048"""
import pathlib
import struct
import sys


def block(cat, records):
    body = b"".join(records)
    return bytes([cat]) + struct.pack(">H", len(body) + 3) + body


def plot(sac, sic, tod, rho, theta, doppler=None, track=None):
    fspec = [0xF0, 0, 0]  # FRN 1-4: 010, 140, 020, 040
    items = bytes([sac, sic]) + tod.to_bytes(3, "big") + b"\x20" + struct.pack(">HH", rho, theta)
    if track is not None:
        fspec[1] |= 0x10  # FRN 11: 161
        items += struct.pack(">H", track)
    if doppler is not None:
        fspec[2] |= 0x04  # FRN 20: 120, CAL only
        items += b"\x80" + struct.pack(">H", doppler & 0x3FF)
    n = 3 if fspec[2] else 2 if fspec[1] else 1
    for i in range(n - 1):
        fspec[i] |= 0x01
    return bytes(fspec[:n]) + items


def every_item():
    items = [b"\x01\x02", b"\x00\x00\x80", b"\x21\x01\x00", b"\x01\x00\x40\x00", b"\x0f\xff", b"\x01\x90",
             b"\xfe\x01\x02\x03\x04\x05\x06\x07", b"\xab\xcd\xef", bytes(range(1, 7)),
             b"\x01" + bytes(range(8)), b"\x0f\xff", bytes(4), bytes(4), b"\x01\x00", bytes(4),
             b"\x03\x05\x04", bytes(2), bytes(4), bytes(2), b"\xc0\x00\x07\x01" + bytes(6), bytes(2),
             bytes(7), b"\x01", b"\x01\x02", b"\x01", b"\x01\x02", b"\x03\xaa\xbb", b"\x01"]
    return b"\xff\xff\xff\xfe" + b"".join(items)


def main(out):
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    seeds = {
        "one_plot": block(48, [plot(0, 1, 1280, 2560, 0)]),
        "grouped_plots": block(48, [plot(0, 1, 1280, 256, 0), plot(0, 1, 1280, 512, 0x4000),
                                    plot(0, 2, 1280, 768, 0x8000), plot(0, 1, 1408, 1024, 0xC000)]),
        "doppler_and_track": block(48, [plot(7, 42, 5529664, 2560, 0x2000, doppler=-5, track=0x123)]),
        "every_item": block(48, [every_item(), plot(0, 9, 640, 512, 0x8000)]),
        "two_blocks_and_cat062": block(48, [plot(0, 1, 1, 1, 1)]) + block(62, [b"\x80\x00\x01"]) +
                                 block(48, [plot(0, 1, 2, 2, 2)]),
        "over_capacity": block(48, [plot(0, 1, 7, 100 + i, 0) for i in range(40)]),
    }
    for name, data in seeds.items():
        (out / name).write_bytes(data)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/fuzz/corpus/asterix_cat048")
