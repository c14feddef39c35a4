#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# One command for the firmware evidence of every board (docs/footprint.md):
#
#   targets/evidence.sh [--host-instructions] [board ...]
#
# For each board (default: every folder of targets/ that has a configure
# preset of the same name, i.e. cortex-m4f, cortex-m7, riscv64-linux and
# any board added since), configure build/<board> with its preset and build
# its kestrel-evidence target: the board's images, each followed by its
# post-link size report and budget, forbidden-symbol check, and worst stack
# of step against its budget (targets/common/evidence.cmake). A budget
# overrun or a forbidden symbol stops the script with the build's error.
# Then it regenerates the tables of docs/footprint.md from
# build/<board>/evidence/*.json (targets/common/footprint_table.py).
#
# --host-instructions also builds host-release-gcc's kestrel-instr-count and
# runs the instruction-count budget check of host_sim/bench (docs/performance.md:
# callgrind instructions per step and path class, failing over budget by
# more than 2 %), and puts its table into docs/footprint.md as well.
set -euo pipefail
cd "$(dirname "$0")/.."

host_instructions=0
boards=()
for arg in "$@"; do
  case $arg in
    --host-instructions) host_instructions=1 ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) boards+=("$arg") ;;
  esac
done
if ((${#boards[@]} == 0)); then
  for dir in targets/*/; do
    b=$(basename "$dir")
    [[ $b == host || $b == common ]] && continue
    grep -q "\"name\": \"$b\"" CMakePresets.json && boards+=("$b")
  done
fi

jobs=$(nproc 2>/dev/null || echo 2)
evidence_dirs=()
for b in "${boards[@]}"; do
  echo "== $b"
  cmake --preset "$b" >/dev/null
  if cmake --build "build/$b" --target help 2>/dev/null | grep "kestrel-evidence" >/dev/null; then
    cmake --build "build/$b" --target kestrel-evidence -j "$jobs"
    evidence_dirs+=("build/$b/evidence")
  else
    echo "evidence.sh: $b has no kestrel-evidence target (its CMakeLists.txt does not call" \
         "kestrel_board_evidence); building it without evidence" >&2
    cmake --build --preset "$b" -j "$jobs"
  fi
done

host_args=()
if ((host_instructions)); then
  script=host_sim/bench/check_instruction_budgets.py
  if [[ -f $script ]]; then
    echo "== host instruction counts (callgrind, $script)"
    cmake --preset host-release-gcc >/dev/null
    cmake --build --preset host-release-gcc --target kestrel-instr-count -j "$jobs"
    mkdir -p build/host-release-gcc/evidence
    python3 "$script" --exe build/host-release-gcc/host_sim/bench/kestrel-instr-count \
      | tee build/host-release-gcc/evidence/host-instructions.txt
    host_args=(--host-instructions build/host-release-gcc/evidence/host-instructions.txt)
  else
    echo "evidence.sh: $script is not there: no instruction counts" >&2
  fi
fi

python3 targets/common/footprint_table.py --doc docs/footprint.md "${host_args[@]}" "${evidence_dirs[@]}"
echo "docs/footprint.md: tables regenerated from ${evidence_dirs[*]}"
