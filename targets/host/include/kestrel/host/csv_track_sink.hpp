// SPDX-License-Identifier: Apache-2.0
// CsvTrackSink: the host's TrackSink (hal/sink.hpp) writing the track CSV of
// docs/host_sim.md, one row per reported track per frame:
//   time_s,track_id,x_m,y_m,vx_mps,vy_mps,p_xx,p_xy,p_yy,
//   status,age,hits,misses,associated,nis,ax_mps2,ay_mps2
// The first nine columns are the required ones (docs/host_sim.md); the rest are the track
// bookkeeping and last innovation statistics. Numbers are printed with
// enough digits to round-trip a double; NaN (no association, no
// acceleration state) is an empty cell.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "kestrel/host/track_row.hpp"
#include "kestrel/status.hpp"
#include "kestrel/tracking/track.hpp"

namespace kestrel::host {

class CsvTrackSink {
 public:
  /// Create (truncate) `path` and write the header. Throws
  /// std::runtime_error naming the file when it cannot be created.
  explicit CsvTrackSink(const std::filesystem::path& path);
  ~CsvTrackSink();
  CsvTrackSink(const CsvTrackSink&) = delete;
  CsvTrackSink& operator=(const CsvTrackSink&) = delete;

  /// TrackSink entry point: one row per report.
  /// @return kOk; kOutOfRange if the file could not be written.
  template <class Filter>
  [[nodiscard]] Status publish(const TrackReport<Filter>& report) {
    return write(to_track_row(report));
  }

  /// Write an already flattened row (kestrel-sim writes stored rows).
  [[nodiscard]] Status write(const TrackRow& row);

  /// The header line, without the newline.
  static const char* header();

 private:
  std::FILE* file_ = nullptr;
};

}  // namespace kestrel::host
