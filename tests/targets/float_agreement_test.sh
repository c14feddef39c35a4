#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# <board>_float_matches_host: the float radar tracker on S1 and S1n
# (tests/targets/float_agreement/float_agreement.cpp), built in the board's
# own tree (configured by the board's image test) with its code generation
# and run under qemu-arm, against the same program built for the host.
# compare.py's arguments say how close: --exact, or a stated tolerance.
# usage: float_agreement_test.sh <cmake> <board build dir> <host program> <compare.py> <compare args...>
# exit: 0 pass, 1 fail, 77 skip (no qemu-arm, or the board tree was not configured).
set -u
cmake=$1 build=$2 host=$3 compare=$4
shift 4

fail() { echo "FAIL: $*"; exit 1; }

command -v qemu-arm >/dev/null 2>&1 || { echo "SKIP: qemu-arm not found (Debian: qemu-user)"; exit 77; }
[ -f "$build/CMakeCache.txt" ] || { echo "SKIP: $build is not configured (no arm-none-eabi-g++?)"; exit 77; }
"$cmake" --build "$build" --target kestrel-float-agreement -j 2 || fail "building kestrel-float-agreement failed"
program=$(find "$build/targets" -name kestrel-float-agreement -type f | head -n 1)
[ -n "$program" ] || fail "kestrel-float-agreement was not found under $build/targets"

"$host" >"$build/float_agreement.host.txt" || fail "the host program failed"
qemu-arm "$program" >"$build/float_agreement.board.txt" || fail "the board program failed under qemu-arm"
python3 "$compare" "$build/float_agreement.host.txt" "$build/float_agreement.board.txt" "$@"
