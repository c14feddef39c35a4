// SPDX-License-Identifier: Apache-2.0
#include "report/run_files.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "kestrel/host/csv_track_sink.hpp"
#include "timing/step_timing.hpp"

namespace kestrel::sim {

RunFileNames run_file_names(const std::filesystem::path& dir, const std::string& filter) {
  return RunFileNames{dir / (filter + "_tracks.csv"), dir / (filter + "_steps.csv"), dir / (filter + "_runs.csv"),
                      dir / (filter + "_modes.csv"), dir / filter};
}

void write_track_csv(const std::filesystem::path& path, const StreamRunResult& run) {
  host::CsvTrackSink sink(path);
  for (const FrameOutcome& f : run.frames) {
    for (const host::TrackRow& row : f.tracks) {
      if (sink.write(row) != Status::kOk) throw std::runtime_error("cannot write '" + path.string() + "'");
    }
  }
}

void write_runs_csv(const std::filesystem::path& path, const std::vector<RunRecord>& runs) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!file) throw std::runtime_error("cannot create '" + path.string() + "'");
  std::FILE* f = file.get();
  std::fprintf(f, "run,seed,rmse_m,peak_m,nees_pos,nis,track_loss_s,recovery_s,episodes,missing_steps,"
                  "max_confirmed_tracks,track_switches,step_ns_median,step_ns_p99,step_ns_max\n");
  const auto num = [f](double v) {
    if (std::isfinite(v)) std::fprintf(f, "%.6g", v);
    std::fputc(',', f);
  };
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunRecord& r = runs[i];
    const StepTiming t = summarise_step_times(r.step_ns, 0);
    std::fprintf(f, "%zu,%llu,", i, static_cast<unsigned long long>(r.seed));
    num(r.metrics.rmse_m);
    num(r.metrics.peak_m);
    num(r.metrics.nees_pos);
    num(r.metrics.nis);
    num(r.metrics.track_loss_s);
    num(r.metrics.recovery_s);
    std::fprintf(f, "%zu,%zu,%zu,%zu,%llu,%llu,%llu\n", r.metrics.episodes.size(), r.metrics.missing_steps,
                 r.max_confirmed_tracks, r.track_switches, static_cast<unsigned long long>(t.median_ns),
                 static_cast<unsigned long long>(t.p99_ns), static_cast<unsigned long long>(t.max_ns));
  }
  if (std::ferror(f) != 0) throw std::runtime_error("cannot write '" + path.string() + "'");
}

bool write_modes_csv(const std::filesystem::path& path, const std::vector<RunRecord>& runs,
                     const std::vector<std::string>& mode_names) {
  bool any = false;
  for (const RunRecord& r : runs) any = any || !r.modes.empty();
  if (!any || mode_names.empty()) return false;
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!file) throw std::runtime_error("cannot create '" + path.string() + "'");
  std::FILE* f = file.get();
  std::fprintf(f, "run,seed,time_s,track_id");
  for (const std::string& n : mode_names) std::fprintf(f, ",mu_%s", n.c_str());
  std::fputc('\n', f);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    for (const ModeSample& m : runs[i].modes) {
      std::fprintf(f, "%zu,%llu,%.6f,%u", i, static_cast<unsigned long long>(runs[i].seed), m.t_s, m.track_id);
      for (std::size_t j = 0; j < mode_names.size(); ++j) {
        const double v = j < m.mu.size() ? m.mu[j] : std::nan("");
        std::fputc(',', f);
        if (std::isfinite(v)) std::fprintf(f, "%.6g", v);
      }
      std::fputc('\n', f);
    }
  }
  if (std::ferror(f) != 0) throw std::runtime_error("cannot write '" + path.string() + "'");
  return true;
}

}  // namespace kestrel::sim
