#!/bin/sh
# cortex_m4f_heap_guard_rejects_malloc: prove the Cortex-M4F heap guard is
# real. The probe project (heap_guard_probe/) links tiny images with the
# board's own options (targets/cortex-m4f/image.cmake):
#   control.elf      no heap use               -> must link
#   malloc_probe.elf calls malloc and free     -> must FAIL, naming __wrap_malloc
#   new_probe.elf    uses operator new/delete  -> must FAIL, naming __wrap__Znwj
#   stdio_probe.elf  defines and calls puts    -> links, and check_symbols.cmake
#                                                 must reject it
# usage: m4f_heap_guard_test.sh <cmake> <kestrel source dir> <build dir>
# exit: 0 pass, 1 fail, 77 skip (no arm-none-eabi-g++).
set -u
cmake=$1 src=$2 build=$3

fail() { echo "FAIL: $*"; exit 1; }

if ! command -v arm-none-eabi-g++ >/dev/null 2>&1; then
  echo "SKIP: arm-none-eabi-g++ is not on PATH, so the Cortex-M4F link guard cannot be exercised"
  exit 77
fi

"$cmake" -S "$src/tests/targets/heap_guard_probe" -B "$build" \
  --toolchain "$src/toolchains/arm-none-eabi-cortex-m4f.cmake" \
  -DKESTREL_SOURCE_DIR="$src" -DCMAKE_BUILD_TYPE=MinSizeRel || fail "probe configure failed"

"$cmake" --build "$build" --target control.elf || fail "control.elf (no heap use) did not link: the probe setup is broken"
echo "control.elf links"

# expect_link_failure <target> <symbol the linker must name>
expect_link_failure() {
  log=$build/$1.log
  if "$cmake" --build "$build" --target "$1" >"$log" 2>&1; then
    cat "$log"
    fail "$1 linked although it uses the heap: the guard is decorative"
  fi
  if ! grep -q "undefined reference to \`$2'" "$log"; then
    cat "$log"
    fail "$1 failed to build, but not with 'undefined reference to $2'"
  fi
  echo "$1 is refused: $(grep -m1 "undefined reference to \`$2'" "$log")"
}
expect_link_failure malloc_probe.elf __wrap_malloc
expect_link_failure new_probe.elf __wrap__Znwj

"$cmake" --build "$build" --target stdio_probe.elf || fail "stdio_probe.elf did not link"
elf=$build/stdio_probe.elf
if "$cmake" -DNM=arm-none-eabi-nm -DELF="$elf" -P "$src/targets/cortex-m4f/check_symbols.cmake" \
    >"$build/stdio_check.log" 2>&1; then
  cat "$build/stdio_check.log"
  fail "check_symbols.cmake accepted an image that defines puts"
fi
grep -q "puts" "$build/stdio_check.log" || { cat "$build/stdio_check.log"; fail "the rejection does not name puts"; }
rm -f "$elf.rejected"  # the check renames what it rejects; next run relinks
echo "check_symbols.cmake rejects stdio_probe.elf (puts)"
echo "PASS"
