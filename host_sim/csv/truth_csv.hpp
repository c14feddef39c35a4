// SPDX-License-Identifier: Apache-2.0
// Truth CSV (docs/host_sim.md): time_s,x_m,y_m[,vx_mps,vy_mps][,z_m], one
// row per frame time. Velocity columns are optional on input (NaN when
// absent); z_m is accepted and ignored by the 2D scenarios. The truth of
// several targets has a `target` column (0, 1, ...): one row per target
// and frame time.
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// Throws CsvError (with the line number) on a malformed row.
std::vector<TruthSample> read_truth_csv(std::istream& in, const std::string& source);
std::vector<TruthSample> read_truth_csv(const std::filesystem::path& path);

void write_truth_csv(const std::filesystem::path& path, const std::vector<TruthSample>& truth);

/// Whether the truth CSV at `path` has a `target` column (several targets).
bool truth_csv_has_targets(const std::filesystem::path& path);

/// targets[i]: the rows of target i, time increasing. Ids must be whole,
/// 0..kMaxTruthTargets - 1, and each one in 0..max present. Throws CsvError
/// (with the line number) on a malformed row.
inline constexpr long long kMaxTruthTargets = 1024;
std::vector<std::vector<TruthSample>> read_targets_truth_csv(std::istream& in, const std::string& source);
std::vector<std::vector<TruthSample>> read_targets_truth_csv(const std::filesystem::path& path);

/// time_s,target,x_m,y_m,vx_mps,vy_mps; targets[i][k] is target i at the
/// k-th time (all targets share the times).
void write_targets_truth_csv(const std::filesystem::path& path, const std::vector<std::vector<TruthSample>>& targets);

}  // namespace kestrel::sim
