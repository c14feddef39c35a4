#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# One short libFuzzer run (CTest label `fuzz`): the seed corpus in the tree
# is read, new inputs go to a scratch corpus, a crash leaves its input in
# <work>/artifacts/ and fails the test. Keep a finding as a regression
# input by copying it into the seed corpus.
# Usage: run_fuzzer.sh <fuzzer> <seed corpus dir> <work dir> <seconds>
set -eu
exe=$1 seeds=$2 work=$3 seconds=$4
rm -rf "$work"
mkdir -p "$work/corpus" "$work/artifacts"
exec "$exe" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/corpus" "$seeds"
