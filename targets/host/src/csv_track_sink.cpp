// SPDX-License-Identifier: Apache-2.0
// CsvTrackSink: formatting of the track CSV.
#include "kestrel/host/csv_track_sink.hpp"

#include <cmath>
#include <stdexcept>

namespace kestrel::host {

namespace {
// %.17g round-trips any double; NaN becomes an empty cell.
void put_number(std::FILE* f, double v) {
  if (!std::isnan(v)) std::fprintf(f, "%.17g", v);
}
}  // namespace

CsvTrackSink::CsvTrackSink(const std::filesystem::path& path) : file_(std::fopen(path.c_str(), "w")) {
  if (file_ == nullptr) throw std::runtime_error("cannot create track CSV '" + path.string() + "'");
  std::fprintf(file_, "%s\n", header());
}

CsvTrackSink::~CsvTrackSink() {
  if (file_ != nullptr) std::fclose(file_);
}

const char* CsvTrackSink::header() {
  return "time_s,track_id,x_m,y_m,vx_mps,vy_mps,p_xx,p_xy,p_yy,"
         "status,age,hits,misses,associated,nis,ax_mps2,ay_mps2";
}

Status CsvTrackSink::write(const TrackRow& row) {
  std::FILE* f = file_;
  std::fprintf(f, "%.6f,%u,", row.time_s, row.track_id);
  const double numbers[] = {row.x_m, row.y_m, row.vx_mps, row.vy_mps, row.p_xx, row.p_xy, row.p_yy};
  for (const double v : numbers) {
    put_number(f, v);
    std::fputc(',', f);
  }
  std::fprintf(f, "%s,%u,%u,%u,%d,", row.confirmed ? "confirmed" : "tentative", row.age, row.hits,
               row.misses, row.associated ? 1 : 0);
  put_number(f, row.nis);
  std::fputc(',', f);
  put_number(f, row.ax_mps2);
  std::fputc(',', f);
  put_number(f, row.ay_mps2);
  std::fputc('\n', f);
  return std::ferror(f) != 0 ? Status::kOutOfRange : Status::kOk;
}

}  // namespace kestrel::host
