// SPDX-License-Identifier: Apache-2.0
// Radar plot CSV (docs/host_sim.md), the input of `kestrel-sim replay --csv`
// and a by-product of `generate`:
//   time_s,range_m,bearing_rad[,range_rate_mps][,sensor_id]
// Consecutive rows with the same time_s form one frame (rows are not
// reordered: a time that goes backwards reaches the tracker, which refuses
// that frame with kTimeWentBackwards, as it would from a live feed).
// bearing is atan2(y, x), counter-clockwise from +x, radar at the origin.
// An empty range_rate_mps cell means "not measured".
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "scenarios/scenario.hpp"

namespace kestrel::sim {

/// Parse plot rows into frames. Throws CsvError (with the line number) on a
/// malformed row: a missing or non-numeric required value, a non-finite
/// value, a negative range, a value its wire field cannot carry (time,
/// range, bearing, range rate: stream/quantise.hpp, never clamped or
/// wrapped beyond a turn), a sensor_id outside 0..255, or a frame with
/// more plots than a wire frame holds (hal::kMaxRadarPlots). A file with
/// a header and no rows gives no frames; the caller decides what that means.
std::vector<MeasurementFrame> read_radar_plot_csv(std::istream& in, const std::string& source);
std::vector<MeasurementFrame> read_radar_plot_csv(const std::filesystem::path& path);

/// Write frames as plot rows (all five columns; empty range_rate_mps when
/// not measured). Numbers use 17 significant digits, so reading them back
/// and quantising gives the same wire frames.
void write_radar_plot_csv(const std::filesystem::path& path, const std::vector<MeasurementFrame>& frames);

}  // namespace kestrel::sim
