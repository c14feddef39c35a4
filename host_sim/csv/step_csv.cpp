// SPDX-License-Identifier: Apache-2.0
#include "csv/step_csv.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>

namespace kestrel::sim {

namespace {
void put(std::FILE* f, double v) {
  if (std::isfinite(v)) std::fprintf(f, "%.6f", v);
  std::fputc(',', f);
}
}  // namespace

void write_step_csv(const std::filesystem::path& path, const std::vector<ScoredStep>& steps,
                    const std::vector<MeasurementFrame>& frames, double loss_threshold_m) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!file) throw std::runtime_error("cannot create step CSV '" + path.string() + "'");
  std::FILE* f = file.get();
  std::fprintf(f, "time_s,k,truth_x_m,truth_y_m,meas_x_m,meas_y_m,est_x_m,est_y_m,track_id,error_m,nees,nis,lost,"
                  "confirmed_tracks\n");
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (const ScoredStep& s : steps) {
    std::fprintf(f, "%.6f,%zu,", s.t_s, s.k);
    put(f, s.truth.x_m);
    put(f, s.truth.y_m);
    // The plot the scored track was updated with, in Cartesian coordinates.
    double mx = kNaN;
    double my = kNaN;
    if (s.estimate.has_value() && s.estimate->associated && s.k < frames.size()) {
      const auto idx = static_cast<std::size_t>(s.estimate->measurement_index);
      if (s.estimate->measurement_index >= 0 && idx < frames[s.k].radar.size()) {
        const RadarPlotSi& p = frames[s.k].radar[idx];
        mx = p.range_m * std::cos(p.bearing_rad);
        my = p.range_m * std::sin(p.bearing_rad);
      }
    }
    put(f, mx);
    put(f, my);
    put(f, s.estimate.has_value() ? s.estimate->x_m : kNaN);
    put(f, s.estimate.has_value() ? s.estimate->y_m : kNaN);
    if (s.estimate.has_value()) std::fprintf(f, "%u", s.estimate->track_id);
    std::fputc(',', f);
    put(f, s.error_m.value_or(kNaN));
    put(f, s.nees);
    put(f, s.nis);
    const bool lost = !s.error_m.has_value() || *s.error_m > loss_threshold_m;
    std::fprintf(f, "%d,%zu\n", lost ? 1 : 0, s.confirmed_tracks);
  }
  if (std::ferror(f) != 0) throw std::runtime_error("cannot write step CSV '" + path.string() + "'");
}

}  // namespace kestrel::sim
