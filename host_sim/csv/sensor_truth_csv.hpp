// SPDX-License-Identifier: Apache-2.0
// Truth CSVs of the PCL and sonar scenarios (docs/host_sim.md, "Scoring a
// PCL or sonar replay"), one row per frame time, written by `generate`
// beside the stream and by `run` for run 0, and read by `replay
// --truth`. Beside the target's state each row carries what the kind's
// scorer needs of the sensor's side: for PCL, whether the sensor detected
// the target and the wire values of that detection (so the replay can find
// it in the frame by content); for sonar, which channels (bit 2 beacon +
// path) the frame holds and which of them carry an outlier delay. Numbers
// are written with 17 significant digits: a replay scores bit for bit as
// the run that generated the stream.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/hal/frame.hpp"
#include "scenarios/pcl002.hpp"
#include "scenarios/uw003.hpp"

namespace kestrel::sim {

/// The sensor kind a truth CSV is for, told by its columns: `rb_m` and
/// `drb_mps` make a PCL truth, `c_mps` a sonar truth, anything else a
/// radar truth. Throws std::runtime_error (unreadable) or CsvError (no header).
hal::FrameKind truth_csv_kind(const std::filesystem::path& path);

struct PclTruthRow {
  PclTruth truth;                               ///< The drone and its Rb, dRb, fD.
  bool detected = false;                        ///< The sensor detected the target in this frame.
  std::optional<hal::PclCandidate> detection;   ///< That detection as on the wire, if the frame carries it.
};

/// time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,rb_m,drb_mps,fd_hz,detected,
/// target_rb_mm,target_doppler_mhz,target_snr_cdb (the last three empty
/// when the frame holds no target detection).
void write_pcl_truth_csv(const std::filesystem::path& path, const PclScenarioRun& run);
/// Throws CsvError naming the line for a malformed row, a missing column or
/// times that do not increase.
std::vector<PclTruthRow> read_pcl_truth_csv(const std::filesystem::path& path);

struct SonarTruthRow {
  SonarTruth truth;                      ///< The target and the sound speed.
  std::uint32_t channels = 0;         ///< Arrivals the sonar sent (bit 2 beacon + path).
  std::uint32_t outlier_channels = 0; ///< Of those, the ones carrying an outlier delay.
};

/// time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,c_mps,channels,outlier_channels.
void write_sonar_truth_csv(const std::filesystem::path& path, const SonarScenarioRun& run);
/// Throws CsvError as read_pcl_truth_csv.
std::vector<SonarTruthRow> read_sonar_truth_csv(const std::filesystem::path& path);

}  // namespace kestrel::sim
