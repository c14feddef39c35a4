#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds examples/firmware_loop as an outside project would and runs it.
#
#   consumer_check.sh install   SRC WORK [CMAKE [CXX]]
#       configure Kestrel library-only (KESTREL_BOARD=none), build, install
#       to WORK/prefix; then configure the example with
#       CMAKE_PREFIX_PATH=WORK/prefix (find_package(kestrel 0.1)), build, run.
#   consumer_check.sh subdirectory SRC WORK [CMAKE [CXX]]
#       configure the example with KESTREL_SOURCE_DIR=SRC (add_subdirectory,
#       Kestrel's subproject defaults), build, run.
#
# Besides the example's own exit status (non-zero without a confirmed track),
# it checks what a consumer gets: the installed files, that kestrel::core
# carries -ffp-contract=off and that nothing of kestrel_firmware_flags
# (-Werror, the warning wall) reaches the consumer's compile line, and that
# a subproject builds no board, tests or simulator. WORK is wiped first.
# Builds use -j1 (CI machines are shared). Run by CTest (label consumer).
set -euo pipefail

mode=${1:?usage: consumer_check.sh install|subdirectory SRC WORK [CMAKE [CXX]]}
src=$(cd "${2:?source dir}" && pwd)
work=${3:?work dir}
cmake=${4:-cmake}
cxx=${5:-}

fail() { echo "consumer_check ($mode): FAIL: $*" >&2; exit 1; }
step() { echo "consumer_check ($mode): $*"; }

rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
compiler=()
[[ -n $cxx ]] && compiler=(-DCMAKE_CXX_COMPILER="$cxx")
example_src=$src/examples/firmware_loop
example_build=$work/example

# The compile line of the example's main.cpp, from its flags.make.
example_flags() {
  local f=$example_build/CMakeFiles/firmware_loop.dir/flags.make
  [[ -f $f ]] || fail "no $f"
  cat "$f"
}

check_consumer_flags() {
  local flags
  flags=$(example_flags)
  grep -q -- '-ffp-contract=off' <<<"$flags" || fail "kestrel::core's -ffp-contract=off did not reach the consumer"
  grep -q -- 'EIGEN_GEMM_TO_COEFFBASED_THRESHOLD=4096' <<<"$flags" ||
    fail "kestrel::core's EIGEN_GEMM_TO_COEFFBASED_THRESHOLD did not reach the consumer"
  for leak in -Werror -Wsign-conversion -Wdouble-promotion -Wold-style-cast -Wfloat-equal EIGEN_NO_MALLOC; do
    if grep -q -- "$leak" <<<"$flags"; then fail "$leak leaked into the consumer's compile flags"; fi
  done
}

run_example() {
  step "run $example_build/firmware_loop"
  local out
  out=$("$example_build/firmware_loop") || { echo "$out"; fail "firmware_loop exited non-zero"; }
  echo "$out"
  grep -q '^PASS$' <<<"$out" || fail "firmware_loop did not print PASS"
  local want
  want=$(sed -n 's/^project(kestrel VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
  grep -q "^kestrel $want " <<<"$out" || fail "firmware_loop does not report kestrel $want (kestrel/version.hpp)"
}

case $mode in
  install)
    prefix=$work/prefix
    step "configure Kestrel library-only"
    "$cmake" -S "$src" -B "$work/kestrel" -DKESTREL_BOARD=none -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_INSTALL_PREFIX="$prefix" "${compiler[@]}" >/dev/null
    # What the install holds: kestrel_hal (core is header-only). The rest of
    # `all`, core's firmware-rules object library (minutes of CPU), is built
    # and checked by the host build already.
    step "build Kestrel's kestrel_hal (-j1)"
    "$cmake" --build "$work/kestrel" --target kestrel_hal -j1 >/dev/null
    step "install to $prefix"
    "$cmake" --install "$work/kestrel" >/dev/null
    for f in include/kestrel/version.hpp include/kestrel/status.hpp include/kestrel/tracking/radar_tracker.hpp \
             include/kestrel/hal/runner.hpp lib/libkestrel_hal.a share/licenses/kestrel/LICENSE \
             lib/cmake/kestrel/kestrelConfig.cmake lib/cmake/kestrel/kestrelConfigVersion.cmake \
             lib/cmake/kestrel/kestrelTargets.cmake; do
      [[ -f $prefix/$f ]] || fail "not installed: $f"
    done
    # Nothing but headers under include/ (no sources, docs or board code).
    if find "$prefix/include" -type f ! -name '*.hpp' | grep -q .; then fail "non-header files under include/"; fi
    # Every quoted include of an installed header resolves inside the prefix.
    unresolved=$(cd "$prefix/include" && grep -rhoE '#include "[^"]+"' . | sed 's/#include "//; s/"$//' | sort -u |
                 while read -r h; do [[ -f $h ]] || echo "$h"; done)
    [[ -z $unresolved ]] || fail "installed headers include files that are not installed: $unresolved"
    if grep -rq -- '-Werror\|kestrel_firmware_flags' "$prefix/lib/cmake/kestrel"; then
      fail "the exported targets carry the firmware flags"
    fi
    step "configure the example with find_package(kestrel 0.1), CMAKE_PREFIX_PATH=$prefix"
    "$cmake" -S "$example_src" -B "$example_build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
      "${compiler[@]}" >/dev/null
    grep -q "^kestrel_DIR:PATH=$prefix/lib/cmake/kestrel\$" "$example_build/CMakeCache.txt" ||
      fail "the example did not find kestrel in $prefix"
    ;;
  subdirectory)
    step "configure the example with add_subdirectory($src)"
    "$cmake" -S "$example_src" -B "$example_build" -DKESTREL_SOURCE_DIR="$src" "${compiler[@]}" >/dev/null
    # Subproject defaults: libraries only, and the build type left to the consumer.
    targets=$(cat "$example_build/CMakeFiles/TargetDirectories.txt")
    grep -q '/kestrel_hal.dir$' <<<"$targets" || fail "kestrel_hal is not a target"
    for t in kestrel_host kestrel-host-replay kestrel_sim kestrel-sim kestrel_core_tests kestrel_test_support; do
      if grep -q "/$t.dir\$" <<<"$targets"; then fail "the subproject defines $t (board, sim or tests)"; fi
    done
    grep -q '^CMAKE_BUILD_TYPE:STRING=$' "$example_build/CMakeCache.txt" ||
      fail "Kestrel set the consumer's CMAKE_BUILD_TYPE"
    ;;
  *)
    fail "unknown mode (install or subdirectory)"
    ;;
esac

check_consumer_flags
step "build the example (-j1)"
"$cmake" --build "$example_build" -j1 >/dev/null
run_example
step "PASS"
