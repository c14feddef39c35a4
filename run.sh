#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Kestrel's two entry points on a fresh Debian machine (README quick start):
#   bash run.sh sim    install what the simulator needs, build kestrel-sim
#                      alone (host-sim preset), run the main job
#                      -> results/report.md
#   bash run.sh test   install everything, build host-release (clang, with
#                      core's rules also checked by g++), run the whole
#                      CTest suite (including the GCC cross builds)
# .ci/run calls `bash run.sh test`.
set -euo pipefail
cd "$(dirname "$0")"

# Debian packages the project needs. Nothing else is downloaded.
PACKAGES=(
  cmake make g++ git
  libeigen3-dev catch2
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib
  g++-riscv64-linux-gnu qemu-user qemu-system-arm
  libbenchmark-dev libcli11-dev nlohmann-json3-dev
  python3 python3-matplotlib
  valgrind
  tshark
  clang libclang-rt-14-dev
)

# What `run.sh sim` needs: the compiler (the host-sim preset builds with
# clang: it compiles kestrel-sim in about half of GCC's time, see
# docs/decisions.md), core's and kestrel-sim's libraries, and matplotlib
# for the figures.
SIM_PACKAGES=(
  cmake make g++ clang
  libeigen3-dev libcli11-dev nlohmann-json3-dev
  python3 python3-matplotlib
)

# install_deps [package...]: install those not yet installed (default: all).
install_deps() {
  local wanted=("${@}")
  ((${#wanted[@]})) || wanted=("${PACKAGES[@]}")
  local missing=()
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]})); then
    echo "run.sh: installing ${missing[*]}" >&2
    local sudo=()
    [[ $(id -u) -eq 0 ]] || sudo=(sudo)
    "${sudo[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
}

njobs() { nproc 2>/dev/null || echo 2; }

# configure_clang_preset NAME: `cmake --preset NAME` of a preset that builds
# with clang. A build/NAME that another compiler configured (GCC, before the
# preset named clang) is configured afresh: on a compiler switch CMake drops
# the cache and, with it, the preset's settings.
configure_clang_preset() {
  local fresh=()
  if [[ -f build/$1/CMakeCache.txt ]] &&
    ! grep -q '^CMAKE_CXX_COMPILER:.*clang++$' "build/$1/CMakeCache.txt"; then
    fresh=(--fresh)
  fi
  cmake --preset "$1" "${fresh[@]}" >/dev/null
}

build_host() {
  configure_clang_preset host-release
  cmake --build --preset host-release -j "$(njobs)"
}

case "${1:-}" in
  sim)
    install_deps "${SIM_PACKAGES[@]}"
    configure_clang_preset host-sim
    sim=build/host-sim/host_sim/kestrel-sim
    # Should this machine's clang fail where CI's did not (another version,
    # a broken install), the main job still runs, built with GCC.
    if ! cmake --build --preset host-sim -j "$(njobs)"; then
      echo "run.sh: clang could not build kestrel-sim (above); building it with GCC instead" >&2
      cmake --preset host-sim -B build/host-sim-gcc -DCMAKE_C_COMPILER=gcc -DCMAKE_CXX_COMPILER=g++ >/dev/null
      cmake --build build/host-sim-gcc --target kestrel-sim -j "$(njobs)"
      sim=build/host-sim-gcc/host_sim/kestrel-sim
    fi
    "./$sim" suite --out results "${@:2}"
    ;;
  test)
    install_deps
    build_host
    # Every Catch2 case a binary lists must run exactly once under CTest
    # (tools/ci/check_cases_ran.py); checked on full runs only.
    rm -rf build/host-release/catch_cases/ran && mkdir -p build/host-release/catch_cases/ran
    ctest --preset host-release "${@:2}"
    if (($# == 1)); then
      python3 tools/ci/check_cases_ran.py build/host-release
    fi
    ;;
  *)
    echo "usage: bash run.sh sim|test [extra args]" >&2
    exit 2
    ;;
esac
