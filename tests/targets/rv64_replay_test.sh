#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# riscv64_linux_replay_matches_host: run the riscv64-linux process image
# (built by riscv64_linux_image_evidence, under qemu-riscv64 user-mode
# emulation) on a generated S1 stream file, and compare its KTRK track
# records with kestrel-host-replay's CSV of the same stream: same tracks,
# same frame times, same statuses, positions, velocities and accelerations
# equal to the KTRK resolution (KTRK v2 rounds a double tracker's state to
# the nearest mm, mm/s, mm/s^2 in double). It shows
# that the board's own main, feed (read(2) system calls, frame assembler),
# step and sink (KTRK over write(2)) run the same tracker on the same bytes
# as the host. Emulated cycle counts mean nothing and are not checked.
# usage: rv64_replay_test.sh <kestrel-sim> <kestrel-host-replay> <kestrel-rv64> <src> <work dir>
# exit: 0 pass, 1 fail, 77 skip (no qemu-riscv64, or the image was not built).
set -u
sim=$1 host_replay=$2 rv64=$3 src=$4 work=$5

fail() { echo "FAIL: $*"; exit 1; }

command -v qemu-riscv64 >/dev/null 2>&1 || { echo "SKIP: qemu-riscv64 not found (Debian: qemu-user)"; exit 77; }
[ -x "$rv64" ] || { echo "SKIP: $rv64 was not built (no riscv64-linux-gnu-g++?)"; exit 77; }
for exe in "$sim" "$host_replay"; do
  [ -x "$exe" ] || { echo "SKIP: $exe was not built (build the host targets kestrel-sim and kestrel-host-replay)"; exit 77; }
done

rm -rf "$work" && mkdir -p "$work" || fail "cannot create $work"
"$sim" generate --scenario S1 --seed 7 --out "$work/s1.kstr" >"$work/generate.log" 2>&1 \
  || { cat "$work/generate.log"; fail "kestrel-sim generate failed"; }
"$host_replay" "$work/s1.kstr" "$work/host.csv" >"$work/host.log" 2>&1 || { cat "$work/host.log"; fail "kestrel-host-replay failed"; }
qemu-riscv64 "$rv64" "$work/s1.kstr" "$work/rv64.ktrk" 2>"$work/rv64.log" || { cat "$work/rv64.log"; fail "kestrel-rv64 failed"; }
cat "$work/rv64.log"
grep -q "^frames [1-9][0-9]*, steps [1-9]" "$work/rv64.log" || fail "kestrel-rv64 printed no runner statistics"
python3 "$src/tools/ktrk_decode.py" "$work/rv64.ktrk" >"$work/rv64.csv" || fail "the KTRK output does not decode cleanly"

python3 - "$work/host.csv" "$work/rv64.csv" <<'PYEOF' || fail "the riscv64-linux tracks differ from the host's"
import csv, sys
host = list(csv.DictReader(open(sys.argv[1])))
board = list(csv.DictReader(open(sys.argv[2])))
assert host, "the host replay produced no tracks"
assert len(host) == len(board), "host %d reports, riscv64-linux %d" % (len(host), len(board))
worst = 0.0
for i, (h, b) in enumerate(zip(host, board)):
    where = "report %d (t %s, track %s)" % (i, b["t_us"], b["track_id"])
    assert round(float(h["time_s"]) * 1e6) == int(b["t_us"]), where + ": frame time"
    assert int(h["track_id"]) == int(b["track_id"]), where + ": track id"
    assert h["status"] == b["status"], where + ": status %s vs %s" % (h["status"], b["status"])
    assert b["layout"] == "cartesian2d_ca", where + ": layout " + b["layout"]
    for hf, bf in (("x_m", "x_mm"), ("y_m", "y_mm"), ("vx_mps", "vx_mmps"), ("vy_mps", "vy_mmps"),
                   ("ax_mps2", "ax_mmps2"), ("ay_mps2", "ay_mmps2")):
        hv, bv = float(h[hf]) * 1000.0, int(b[bf])
        # Rounded to the unit in double: half a unit, plus the CSV's 17 digits.
        tol = 0.5 + 1e-12 * abs(hv)
        assert abs(hv - bv) <= tol, where + ": %s host %.3f board %d" % (bf, hv, bv)
        worst = max(worst, abs(hv - bv))
print("riscv64-linux: %d track reports equal to the host's (largest difference %.2f mm, mm/s or mm/s^2)"
      % (len(board), worst))
PYEOF
echo "PASS"
