#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# <board>_heap_guard_rejects_malloc: prove a board's heap guard and stack
# budget are real. The probe project (heap_guard_probe/) links tiny images
# with the board's own options (its image.cmake; for riscv64-linux the
# options of its heap-guard image):
#   control.elf      no heap use               -> must link
#   malloc_probe.elf calls malloc and free     -> must FAIL, naming __wrap_malloc
#   new_probe.elf    uses operator new/delete  -> must FAIL, naming __wrap__Znw<j|m>
#   stdio_probe.elf  defines and calls puts    -> links, and check_symbols.cmake
#                                                 must reject it
#   frame_probe      an 8 KiB frame, built with -Wstack-usage=4096 -Werror
#                                              -> must FAIL to compile
# usage: heap_guard_test.sh <cmake> <kestrel source dir> <build dir> <board>
#                           <toolchain file> <tool prefix> <size_t mangling j|m>
# exit: 0 pass, 1 fail, 77 skip (the board's compiler is not installed).
set -u
cmake=$1 src=$2 build=$3 board=$4 toolchain=$5 prefix=$6 sizet=$7

fail() { echo "FAIL: $*"; exit 1; }

if ! command -v "${prefix}g++" >/dev/null 2>&1; then
  echo "SKIP: ${prefix}g++ is not on PATH, so the $board link guard cannot be exercised"
  exit 77
fi

"$cmake" -S "$src/tests/targets/heap_guard_probe" -B "$build" --toolchain "$toolchain" \
  -DKESTREL_SOURCE_DIR="$src" -DKESTREL_PROBE_BOARD="$board" -DCMAKE_BUILD_TYPE=MinSizeRel \
  || fail "probe configure failed"

"$cmake" --build "$build" --target control.elf || fail "control.elf (no heap use) did not link: the probe setup is broken"
echo "control.elf links"

# expect_build_failure <target> <text the build log must contain>
expect_build_failure() {
  log=$build/$1.log
  if "$cmake" --build "$build" --target "$1" >"$log" 2>&1; then
    cat "$log"
    fail "$1 built although it must not: the check is decorative"
  fi
  if ! grep -q "$2" "$log"; then
    cat "$log"
    fail "$1 failed to build, but not with '$2'"
  fi
  echo "$1 is refused: $(grep -m1 "$2" "$log")"
}
expect_build_failure malloc_probe.elf "undefined reference to \`__wrap_malloc'"
expect_build_failure new_probe.elf "undefined reference to \`__wrap__Znw$sizet'"
expect_build_failure frame_probe "stack usage is [0-9]* bytes"

"$cmake" --build "$build" --target stdio_probe.elf || fail "stdio_probe.elf did not link"
elf=$build/stdio_probe.elf
if "$cmake" -DNM="${prefix}nm" -DELF="$elf" -P "$src/targets/common/check_symbols.cmake" \
    >"$build/stdio_check.log" 2>&1; then
  cat "$build/stdio_check.log"
  fail "check_symbols.cmake accepted an image that defines puts"
fi
grep -q "puts" "$build/stdio_check.log" || { cat "$build/stdio_check.log"; fail "the rejection does not name puts"; }
rm -f "$elf.rejected"  # the check renames what it rejects; next run relinks
echo "check_symbols.cmake rejects stdio_probe.elf (puts)"
echo "PASS"
