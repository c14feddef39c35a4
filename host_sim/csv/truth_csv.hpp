// SPDX-License-Identifier: Apache-2.0
// Truth CSV (docs/host_sim.md): time_s,x_m,y_m[,vx_mps,vy_mps][,z_m], one
// row per frame time. Velocity columns are optional on input (NaN when
// absent); z_m is accepted and ignored by the 2D scenarios.
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

}  // namespace kestrel::sim
