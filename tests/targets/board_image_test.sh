#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# <board>_image_evidence: configure a board in its own tree and build its
# kestrel-evidence target, i.e. exactly the board's images (not core's
# rules-check object) with their post-link steps: size budget, forbidden
# symbols, worst stack of step against its budget. Any of them over budget
# fails the build, so it fails this test. Then, independently of those
# scripts:
#   - every image named has its size evidence, and the stack evidence when
#     asked (<image>:stack);
#   - the raw symbol table of each image checked for symbols (<image>:nm)
#     names no allocator, operator new/delete, printf family or exception
#     throw;
#   - the budget checks are real: the size check on a copy of the first
#     image with a 1-byte text budget, and the stack report with a 1-byte
#     budget, must both fail.
# usage: board_image_test.sh <cmake> <src> <build> <board> <toolchain> <build type>
#                            <tool prefix> <image>[:nm][:stack] ...
# exit: 0 pass, 1 fail, 77 skip (the board's compiler is not installed).
set -u
cmake=$1 src=$2 build=$3 board=$4 toolchain=$5 build_type=$6 prefix=$7
shift 7

fail() { echo "FAIL: $*"; exit 1; }

if ! command -v "${prefix}g++" >/dev/null 2>&1; then
  echo "SKIP: ${prefix}g++ is not on PATH, so the $board images cannot be built"
  exit 77
fi
for tool in nm size objdump; do
  command -v "${prefix}$tool" >/dev/null 2>&1 || fail "${prefix}$tool is missing although ${prefix}g++ is present"
done

"$cmake" -S "$src" -B "$build" --toolchain "$toolchain" \
  -DKESTREL_BOARD="$board" -DCMAKE_BUILD_TYPE="$build_type" || fail "configure failed"
"$cmake" --build "$build" --target kestrel-evidence -j 2 \
  || fail "building the $board images failed: a compile error, the heap guard, the symbol check, or a size or stack budget (see above)"

first=""
for spec in "$@"; do
  image=${spec%%:*}
  stem=${image%.elf}
  elf=$build/targets/$board/$image
  [ -f "$elf" ] || fail "$elf does not exist"
  [ -n "$first" ] || first=$elf
  [ -f "$build/evidence/$stem.size.json" ] || fail "no size evidence for $image"
  case $spec in
    *:stack*) [ -f "$build/evidence/$stem.stack.json" ] || fail "no stack evidence for $image (is Python 3 installed?)" ;;
  esac
  case $spec in
    *:nm*)
      syms=$("${prefix}nm" "$elf" | awk '{print $NF}') || fail "nm failed on $elf"
      bad=$(printf '%s\n' "$syms" | grep -E -x \
        'malloc|free|calloc|realloc|memalign|_malloc_r|_free_r|_calloc_r|_realloc_r|_memalign_r|__libc_malloc|_sbrk|_sbrk_r|sbrk|__sbrk|_Zn[wa].*|_Zd[la].*|__wrap_.*|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsnprintf|iprintf|_printf_r|_vfprintf_r|_svfprintf_r|_vfiprintf_r|puts|fputs|putchar|fwrite|_write|_write_r|__cxa_throw|__cxa_allocate_exception|__cxa_begin_catch|__gxx_personality_v0|_Unwind_RaiseException|_ZSt[0-9]+__throw_.*')
      [ -z "$bad" ] || fail "forbidden symbols in $elf:
$bad"
      echo "$image: nm finds no heap, operator new/delete, printf-family or exception symbols"
      ;;
  esac
  python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print("%s: text %d, data %d, bss %d bytes (budgets %s)" % (d["elf"], d["text"], d["data"], d["bss"], d["budget"]))' \
    "$build/evidence/$stem.size.json" || fail "unreadable size evidence for $image"
done

# The budget checks must be able to fail.
copy=$build/budget_probe.elf
cp "$first" "$copy" || fail "cannot copy $first"
if "$cmake" -DSIZE="${prefix}size" -DELF="$copy" -DOUT="$build/budget_probe.size.txt" -DTEXT_BUDGET=1 \
    -P "$src/targets/common/size_report.cmake" >"$build/budget_probe.log" 2>&1; then
  cat "$build/budget_probe.log"
  fail "size_report.cmake accepted a 1-byte text budget"
fi
[ -f "$copy.rejected" ] || fail "size_report.cmake did not rename the over-budget image"
rm -f "$copy" "$copy.rejected"
echo "size_report.cmake rejects an image over its text budget"

for spec in "$@"; do
  case $spec in *:stack*) ;; *) continue ;; esac
  image=${spec%%:*}
  stem=${image%.elf}
  python3 - "$build/evidence/$stem.stack.json" <<'EOF' || fail "the stack evidence of $image is not a bounded step chain"
import json, sys
doc = json.load(open(sys.argv[1]))
assert doc["step_bytes"] and doc["step_bytes"] > 0, doc
assert doc["budget"] and doc["step_bytes"] <= doc["budget"], doc
print("%s: worst chain of step %d bytes, budget %d" % (doc["label"], doc["step_bytes"], doc["budget"]))
EOF
  if python3 "$src/targets/common/stack_report.py" --elf "$build/targets/$board/$image" --objdump "${prefix}objdump" \
      --ci-dir "$build/targets/$board" --ci-dir "$build/hal" --budget 1 >"$build/stack_probe.log" 2>&1; then
    cat "$build/stack_probe.log"
    fail "stack_report.py accepted a 1-byte stack budget for $image"
  fi
  grep -q "^FAIL: the worst chain" "$build/stack_probe.log" || { cat "$build/stack_probe.log"; fail "stack_report.py failed for another reason"; }
  echo "stack_report.py rejects $image against a 1-byte stack budget"
done
echo "PASS"
