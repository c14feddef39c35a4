#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Configure and build tests/fuzz with clang (CTest fixture of the `fuzz` and
# `asan` tests). Usage: sanitized_build.sh <cmake> <tests/fuzz dir> <build dir>
set -eu
if ! command -v clang++ >/dev/null 2>&1; then
  echo "clang++ not on PATH (run.sh installs clang): skipped"
  exit 77
fi
# -O1 with line tables and NDEBUG (as the host build: KESTREL_ASSERT needs a
# board hook otherwise): sanitizer reports keep their lines, and the build
# stays a few minutes on two cores.
"$1" -S "$2" -B "$3" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=None \
  "-DCMAKE_CXX_FLAGS=-O1 -gline-tables-only -DNDEBUG" >/dev/null
"$1" --build "$3" -j "$(nproc 2>/dev/null || echo 2)"
