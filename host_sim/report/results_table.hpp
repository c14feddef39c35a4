// SPDX-License-Identifier: Apache-2.0
// The results table printed by `run`, `replay`, `suite` and `timing`.
#pragma once

#include <cstdio>
#include <string>

#include "montecarlo/monte_carlo.hpp"

namespace kestrel::sim {

/// One row of the table.
struct TableRow {
  std::string scenario;
  std::string filter;
  MonteCarloSummary summary;
};

/// Header lines (column names and units).
void print_table_header(std::FILE* out);
/// One row: mean [95 % CI] per figure, runs without loss, step times.
void print_table_row(std::FILE* out, const TableRow& row);
/// The track-continuity line of a row (docs/robustness.md); nothing when
/// no run had a track on the target.
void print_continuity(std::FILE* out, const TableRow& row);
/// Step latency block of the timing command.
void print_timing(std::FILE* out, const std::string& what, const StepTiming& timing);

}  // namespace kestrel::sim
