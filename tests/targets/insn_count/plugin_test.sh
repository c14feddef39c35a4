#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# qemu_insn_count_is_exact: the counting plugin of the frame budgets, on a
# Thumb-1 program whose intervals are known (known_loop.cpp): 256,004 and 2
# instructions, exactly.
# usage: plugin_test.sh <plugin .so> <source dir of tests> <work dir>
# exit: 0 pass, 1 fail, 77 skip (no qemu-arm or arm-none-eabi-g++).
set -u
plugin=$1 tests=$2 work=$3
command -v qemu-arm >/dev/null 2>&1 || { echo "SKIP: qemu-arm not found (Debian: qemu-user)"; exit 77; }
command -v arm-none-eabi-g++ >/dev/null 2>&1 || { echo "SKIP: arm-none-eabi-g++ not found"; exit 77; }
mkdir -p "$work"
arm-none-eabi-g++ -mcpu=cortex-m0plus -mthumb -Os -std=c++20 -nostartfiles --specs=nano.specs -I"$tests" \
  "$tests/targets/insn_count/known_loop.cpp" -o "$work/known_loop.elf" || { echo "FAIL: build"; exit 1; }
qemu-arm -d plugin -plugin "$plugin,marker=kestrel_count_mark" "$work/known_loop.elf" 2>"$work/counts.txt" ||
  { echo "FAIL: qemu-arm"; cat "$work/counts.txt"; exit 1; }
cat "$work/counts.txt"
grep -qx 'kestrel-insn-count: interval 2 256004' "$work/counts.txt" || { echo "FAIL: interval 2 is not 256004"; exit 1; }
grep -qx 'kestrel-insn-count: interval 3 2' "$work/counts.txt" || { echo "FAIL: interval 3 is not 2"; exit 1; }
echo "PASS"
