#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# cortex_m4f_image_has_no_heap: configure and build the Cortex-M4F firmware
# in its own tree, then check the ELF with arm-none-eabi-nm and -size.
# usage: m4f_image_test.sh <cmake> <kestrel source dir> <build dir>
# exit: 0 pass, 1 fail, 77 skip (no arm-none-eabi-g++).
set -u
cmake=$1 src=$2 build=$3

fail() { echo "FAIL: $*"; exit 1; }

if ! command -v arm-none-eabi-g++ >/dev/null 2>&1; then
  echo "SKIP: arm-none-eabi-g++ is not on PATH, so the Cortex-M4F image cannot be built"
  exit 77
fi
for tool in arm-none-eabi-nm arm-none-eabi-size; do
  command -v $tool >/dev/null 2>&1 || fail "$tool is missing although arm-none-eabi-g++ is present"
done

"$cmake" -S "$src" -B "$build" --toolchain "$src/toolchains/arm-none-eabi-cortex-m4f.cmake" \
  -DKESTREL_BOARD=cortex-m4f -DCMAKE_BUILD_TYPE=MinSizeRel || fail "configure failed"
# The post-link step already runs check_symbols.cmake and renames a bad
# image to .rejected, so a failed build here may be the symbol check.
"$cmake" --build "$build" --target kestrel-m4f.elf -j 2 || fail "build of kestrel-m4f.elf failed (see above)"

elf=$build/targets/cortex-m4f/kestrel-m4f.elf
[ -f "$elf" ] || fail "$elf does not exist"

# Independent of the post-link script: the raw symbol table must not name
# any allocator, operator new/delete, printf-family or exception-throw symbol.
syms=$(arm-none-eabi-nm "$elf" | awk '{print $NF}') || fail "nm failed on $elf"
bad=$(printf '%s\n' "$syms" | grep -E -x \
  'malloc|free|calloc|realloc|memalign|_malloc_r|_free_r|_calloc_r|_realloc_r|_memalign_r|_sbrk|_sbrk_r|_Zn[wa].*|_Zd[la].*|__wrap_.*|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsnprintf|iprintf|_printf_r|_vfprintf_r|_svfprintf_r|_vfiprintf_r|puts|fputs|putchar|fwrite|_write|_write_r|__cxa_throw|__cxa_allocate_exception|__cxa_begin_catch|__gxx_personality_v0|_Unwind_RaiseException|_ZSt[0-9]+__throw_.*')
[ -z "$bad" ] || fail "forbidden symbols in $elf:
$bad"
echo "nm: no heap, operator new/delete, printf-family or exception symbols"

"$cmake" -DNM=arm-none-eabi-nm -DELF="$elf" -P "$src/targets/common/check_symbols.cmake" \
  || fail "check_symbols.cmake rejected the image"

text=$(arm-none-eabi-size -A "$elf" | awk '$1 == ".text" {print $2}')
[ -n "$text" ] && [ "$text" -gt 0 ] || fail ".text is missing or empty (size: '$text')"
echo ".text: $text bytes"

vectors=$(arm-none-eabi-nm "$elf" | awk '$3 == "g_vector_table" {print $1}')
[ "$vectors" = "08000000" ] || fail "the vector table is at '$vectors', not at the start of flash 08000000"
echo "vector table at 0x$vectors"
echo "PASS"
