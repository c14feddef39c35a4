#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""cortex_m4f_qemu_replay_matches_host (CTest labels `emulated`, `boards`).

Boots the unmodified Cortex-M4F image (kestrel-m4f.elf, built by
cortex_m4f_image_has_no_heap) in QEMU's STM32F405 machine
(`qemu-system-arm -M netduinoplus2`), feeds a generated S1 radar stream
(seed 7, the wire format of docs/wire_format.md) into the USART the board
reads, captures the KTRK records it writes back, decodes them with
tools/ktrk_decode.py and compares them record for record with the host's
replay of the same stream: `kestrel-sim replay -f ekf-ca-f32 --gate-d2
13.816`, the board's tracker (float EKF-CA, the board's 0.999 gate) on the
host, for the state; and kestrel-host-replay (the host board, double) for
the frame times, track ids and statuses, which must be the same too.

Serial mapping: QEMU gives the STM32F405's USARTs the -serial options in
order USART1, USART2, ...; the board uses USART2 (targets/cortex-m4f/
uart_feed.hpp), so USART1 gets `-serial null` and USART2 `-serial stdio`,
and this script holds both ends of QEMU's stdin/stdout pipe.

The stream is paced (2880 bytes/s by default, a quarter of the link's
115200 baud 8N1): the board has no flow control and its 1 KiB receive ring
is sized for the link rate (board_config.hpp), while QEMU would otherwise
deliver bytes as fast as the emulated USART takes them. At the full link
rate a 44-byte frame arrives every 3.8 ms of host time, and QEMU's speed is
the host's, not the board's: on this 2-core CI host the emulated image fell
behind and overflowed the ring in 2 of 3 runs (316 and 375 of 383 records),
with nothing else running. A quarter of the rate still delivers frames 130
times faster than the sensor's 0.5 s period. QEMU does not model
the STM32's clock tree or flash interface, so the image runs on its HSI
fallback (docs/porting.md, "Boot without hanging"); emulated cycle counts
mean nothing and are not checked.

Checks (each can fail): the image took the clock fallback QEMU forces
(read through QEMU's monitor at the address of the board's clock state:
FLASH_ACR reads 0, so kFlashLatency, core and APB1 at 16 MHz); the decoder
skipped no byte and found no bad CRC;
as many records as each host replay's rows; each record has the host's
frame time, track id, status and layout; positions, velocities and
accelerations within the tolerances below of the host float replay. The run
is bounded: QEMU is killed at --timeout.

usage: m4f_qemu_replay_test.py --elf E --sim S --host-replay R --src DIR --work DIR
exit: 0 pass, 1 fail, 77 skip (no qemu-system-arm, or an input was not built).
"""

import argparse
import csv
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time

# The board (float, newlib's single-precision libm, Cortex-M4F code) against
# the host float replay (glibc's libm, x86-64 code). Measured on S1 seed 7
# (docs/porting.md, section 15): 383 of 383 reports, largest differences
# 11.2 / 18.9 mm (x / y), 5.3 / 6.8 mm/s, 2.7 / 3.0 mm/s^2; 380 of 383
# positions within 13 mm. Position: the 50 mm cortex_m4f_float_matches_host
# allows between the M4F's code generation and the host in float; velocity
# and acceleration: about five times the measured maximum.
TOL = {"x_mm": 50.0, "y_mm": 50.0, "vx_mmps": 30.0, "vy_mmps": 30.0, "ax_mmps2": 15.0, "ay_mmps2": 15.0}
HOST_COLUMN = {"x_mm": "x_m", "y_mm": "y_m", "vx_mmps": "vx_mps", "vy_mmps": "vy_mps", "ax_mmps2": "ax_mps2",
               "ay_mmps2": "ay_mps2"}
RECORD_BYTES = 64  # KTRK v2
# kestrel::m4f's ClockState in system.cpp: core_hz, apb1_hz (uint32), then
# ClockFallback (uint8, kFlashLatency = 1) padded to a word.
CLOCK_SYMBOL = "_ZN7kestrel3m4f12_GLOBAL__N_17g_clockE"
EXPECTED_CLOCK = (16_000_000, 16_000_000, 1)


def skip(msg):
    print("SKIP: " + msg)
    sys.exit(77)


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def symbol_address(nm, elf, name):
    r = subprocess.run([nm, elf], capture_output=True, text=True, timeout=60)
    for line in r.stdout.splitlines():
        f = line.split()
        if len(f) == 3 and f[2] == name:
            return int(f[0], 16)
    return None


def read_words(monitor_path, address, count, timeout=10.0):
    """Read `count` 32-bit words of guest memory with the HMP command xp; None if the monitor does not answer."""
    deadline = time.monotonic() + timeout
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as sock:
        sock.settimeout(timeout)
        sock.connect(monitor_path)
        sock.sendall(b"xp /%dwx 0x%x\n" % (count, address))
        text = b""
        pattern = re.compile(rb"%x:((?:\s+0x[0-9a-f]{8}){%d})" % (address, count))
        while time.monotonic() < deadline:
            chunk = sock.recv(4096)
            if not chunk:
                break
            text += chunk
            m = pattern.search(text)
            if m:
                return tuple(int(w, 16) for w in m.group(1).split())
    return None


def run_qemu(args, stream, expected_records, clock_address):
    """Boot the image, feed `stream` at args.rate bytes/s; return (output bytes, seconds, how it ended,
    the clock state words or None)."""
    # A short path: a Unix socket's name is limited to about 100 bytes.
    sock_dir = tempfile.mkdtemp(prefix="kestrel-qemu-")
    monitor = os.path.join(sock_dir, "monitor.sock")
    cmd = [args.qemu, "-M", "netduinoplus2", "-nographic", "-monitor", "unix:%s,server=on,wait=off" % monitor,
           "-serial", "null", "-serial", "stdio", "-kernel", args.elf]
    print("running: " + " ".join(cmd))
    start = time.monotonic()
    proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = bytearray()
    err = bytearray()
    lock = threading.Lock()

    def pump(src, dst):
        while True:
            chunk = os.read(src.fileno(), 4096)
            if not chunk:
                return
            with lock:
                dst.extend(chunk)

    readers = [threading.Thread(target=pump, args=(proc.stdout, out), daemon=True),
               threading.Thread(target=pump, args=(proc.stderr, err), daemon=True)]
    for r in readers:
        r.start()

    deadline = start + args.timeout
    ended = "timeout"
    try:
        # Let the image boot before the first byte (the USART drops bytes until enabled).
        time.sleep(args.boot_s)
        sent = 0
        t0 = time.monotonic()
        while sent < len(stream):
            if time.monotonic() > deadline or proc.poll() is not None:
                break
            due = min(len(stream), int((time.monotonic() - t0) * args.rate) + 64)
            if due > sent:
                proc.stdin.write(stream[sent:due])
                proc.stdin.flush()
                sent = due
            time.sleep(0.005)
        fed = time.monotonic()
        # Wait for the records: all expected ones (plus a grace period in which
        # any extra record would show up), or silence, or the deadline.
        last_len, last_change = -1, time.monotonic()
        while time.monotonic() < deadline and proc.poll() is None:
            with lock:
                n = len(out)
            if n != last_len:
                last_len, last_change = n, time.monotonic()
            if sent == len(stream):
                if n >= expected_records * RECORD_BYTES and time.monotonic() - last_change > args.grace_s:
                    ended = "all records"
                    break
                if time.monotonic() - max(last_change, fed) > args.quiet_s:
                    ended = "quiet for %.0f s" % args.quiet_s
                    break
            time.sleep(0.05)
        if proc.poll() is not None:
            ended = "QEMU exited with status %d" % proc.returncode
        print("fed %d of %d stream bytes in %.1f s" % (sent, len(stream), fed - t0))
        clock = None
        if proc.poll() is None:
            try:
                clock = read_words(monitor, clock_address, 3)
            except OSError as e:
                print("QEMU monitor: %s" % e)
    finally:
        if proc.poll() is None:
            proc.terminate()
            try:
                proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        for r in readers:
            r.join(timeout=5)
        shutil.rmtree(sock_dir, ignore_errors=True)
    elapsed = time.monotonic() - start
    if err:
        print("qemu stderr: " + err.decode(errors="replace").strip())
    return bytes(out), elapsed, ended, clock


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--qemu", default="qemu-system-arm")
    p.add_argument("--nm", default="arm-none-eabi-nm")
    p.add_argument("--elf", required=True)
    p.add_argument("--sim", required=True, help="kestrel-sim (generates the S1 stream, host float replay)")
    p.add_argument("--host-replay", required=True, help="kestrel-host-replay")
    p.add_argument("--src", required=True, help="source tree (tools/ktrk_decode.py)")
    p.add_argument("--work", required=True)
    p.add_argument("--scenario", default="S1")
    p.add_argument("--seed", default="7")
    p.add_argument("--rate", type=float, default=115200 / 40,
                   help="stream bytes per second (a quarter of 8N1 at 115200 baud)")
    p.add_argument("--timeout", type=float, default=240.0, help="QEMU is killed after this many seconds")
    p.add_argument("--boot-s", type=float, default=0.5)
    p.add_argument("--grace-s", type=float, default=1.0)
    p.add_argument("--quiet-s", type=float, default=20.0)
    args = p.parse_args()

    if shutil.which(args.qemu) is None:
        skip("%s not found (Debian: qemu-system-arm)" % args.qemu)
    if not os.path.isfile(args.elf):
        skip("%s was not built (cortex_m4f_image_has_no_heap builds it; no arm-none-eabi-g++?)" % args.elf)
    for exe in (args.sim, args.host_replay):
        if not os.access(exe, os.X_OK):
            skip("%s was not built (build the host targets kestrel-sim and kestrel-host-replay)" % exe)

    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    stream_path = os.path.join(args.work, "s1.kstr")
    host_csv = os.path.join(args.work, "host.csv")
    float_dir = os.path.join(args.work, "host-float")
    for cmd in ([args.sim, "generate", "--scenario", args.scenario, "--seed", args.seed, "--out", stream_path],
                [args.host_replay, stream_path, host_csv],
                [args.sim, "replay", "--stream", stream_path, "-f", "ekf-ca-f32", "--gate-d2", "13.816", "--no-plots",
                 "-o", float_dir]):
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
        if r.returncode != 0:
            fail("%s failed:\n%s%s" % (" ".join(cmd), r.stdout, r.stderr))
    host_double = list(csv.DictReader(open(host_csv)))
    host = list(csv.DictReader(open(os.path.join(float_dir, "ekf-ca-f32_tracks.csv"))))
    if not host or not host_double:
        fail("a host replay produced no tracks")
    stream = open(stream_path, "rb").read()
    print("stream %s: %d bytes; host replay: %d track reports (float), %d (double)"
          % (stream_path, len(stream), len(host), len(host_double)))

    clock_address = symbol_address(args.nm, args.elf, CLOCK_SYMBOL)
    if clock_address is None:
        fail("%s has no symbol %s (the board's clock state)" % (args.elf, CLOCK_SYMBOL))
    out, elapsed, ended, clock = run_qemu(args, stream, len(host), clock_address)
    ktrk = os.path.join(args.work, "board.ktrk")
    open(ktrk, "wb").write(out)
    print("QEMU ran %.1f s (%s); the board wrote %d bytes" % (elapsed, ended, len(out)))
    if clock is None:
        fail("could not read the board's clock state through the QEMU monitor")
    clock = (clock[0], clock[1], clock[2] & 0xFF)
    print("clock state at 0x%08x: core %d Hz, APB1 %d Hz, fallback %d" % ((clock_address,) + clock))
    if clock != EXPECTED_CLOCK:
        fail("clock state %s, expected %s (HSI fallback kFlashLatency: QEMU does not model FLASH_ACR)"
             % (clock, EXPECTED_CLOCK))

    board_csv = os.path.join(args.work, "board.csv")
    with open(board_csv, "w") as f:
        r = subprocess.run([sys.executable, os.path.join(args.src, "tools", "ktrk_decode.py"), ktrk], stdout=f,
                           stderr=subprocess.PIPE, text=True, timeout=60)
    if r.stderr.strip():
        print("ktrk_decode: " + r.stderr.strip())
    if r.returncode != 0:
        fail("the board's output does not decode cleanly (skipped bytes or bad CRCs)")
    board = list(csv.DictReader(open(board_csv)))
    if len(board) != len(host) or len(board) != len(host_double):
        fail("host %d (float) and %d (double) reports, board %d" % (len(host), len(host_double), len(board)))

    for i, (h, b) in enumerate(zip(host_double, board)):
        if (round(float(h["time_s"]) * 1e6), int(h["track_id"]), h["status"]) != (int(b["t_us"]), int(b["track_id"]),
                                                                                     b["status"]):
            fail("report %d: board (t %s, track %s, %s), host double (%s s, track %s, %s)"
                 % (i, b["t_us"], b["track_id"], b["status"], h["time_s"], h["track_id"], h["status"]))
    worst = {k: 0.0 for k in TOL}
    within13 = 0
    for i, (h, b) in enumerate(zip(host, board)):
        where = "report %d (t %s, track %s)" % (i, b["t_us"], b["track_id"])
        if round(float(h["time_s"]) * 1e6) != int(b["t_us"]):
            fail(where + ": frame time host %s s" % h["time_s"])
        if int(h["track_id"]) != int(b["track_id"]):
            fail(where + ": track id host %s" % h["track_id"])
        if h["status"] != b["status"]:
            fail(where + ": status host %s board %s" % (h["status"], b["status"]))
        if b["layout"] != "cartesian2d_ca":
            fail(where + ": layout " + b["layout"])
        d_pos = 0.0
        for col, tol in TOL.items():
            d = abs(float(h[HOST_COLUMN[col]]) * 1000.0 - int(b[col]))
            worst[col] = max(worst[col], d)
            if col in ("x_mm", "y_mm"):
                d_pos = max(d_pos, d)
            if d > tol:
                fail(where + ": %s differs by %.1f (limit %.0f)" % (col, d, tol))
        within13 += d_pos <= 13.0
    print("cortex-m4f under QEMU netduinoplus2: %d of %d track reports match the host float replay "
          "(times, ids, statuses also the double host's); positions within 13 mm: %d; largest differences: %s"
          % (len(board), len(host), within13, ", ".join("%s %.1f" % (k, v) for k, v in worst.items())))
    print("PASS")


if __name__ == "__main__":
    main()
