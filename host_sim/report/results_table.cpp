// SPDX-License-Identifier: Apache-2.0
#include "report/results_table.hpp"

#include <cmath>

namespace kestrel::sim {

namespace {
// "mean [lo, hi]" in a fixed width, "-" when there is no data.
std::string interval(const MeanCi& m, const char* fmt) {
  if (!std::isfinite(m.mean)) return "-";
  char buf[112];
  char mean[32], lo[32], hi[32];
  std::snprintf(mean, sizeof mean, fmt, m.mean);
  std::snprintf(lo, sizeof lo, fmt, m.ci95_low);
  std::snprintf(hi, sizeof hi, fmt, m.ci95_high);
  std::snprintf(buf, sizeof buf, "%s [%s, %s]", mean, lo, hi);
  return buf;
}
// The same in per cent, two decimals.
std::string percent(const MeanCi& m) {
  MeanCi p = m;
  p.mean *= 100.0;
  p.ci95_low *= 100.0;
  p.ci95_high *= 100.0;
  return interval(p, "%.2f");
}
}  // namespace

void print_table_header(std::FILE* out) {
  std::fprintf(out, "%-8s %-11s %5s  %-22s %-22s %-20s %-16s %-18s %-18s %8s  %s\n", "scenario", "filter", "runs",
               "RMSE m [95% CI]", "peak m", "NEES pos", "NIS", "track loss s", "recovery s", "no loss",
               "step us med/p99/max");
}

void print_table_row(std::FILE* out, const TableRow& r) {
  const MonteCarloSummary& s = r.summary;
  char no_loss[32];
  std::snprintf(no_loss, sizeof no_loss, "%zu/%zu", s.runs_without_loss, s.runs);
  std::fprintf(out, "%-8s %-11s %5zu  %-22s %-22s %-20s %-16s %-18s %-18s %8s  %.1f/%.1f/%.1f\n",
               r.scenario.c_str(), r.filter.c_str(), s.runs, interval(s.rmse_m, "%.1f").c_str(),
               interval(s.peak_m, "%.0f").c_str(), interval(s.nees_pos, "%.1f").c_str(),
               interval(s.nis, "%.2f").c_str(), interval(s.track_loss_s, "%.1f").c_str(),
               interval(s.recovery_s, "%.1f").c_str(), no_loss, static_cast<double>(s.timing.median_ns) * 1e-3,
               static_cast<double>(s.timing.p99_ns) * 1e-3, static_cast<double>(s.timing.max_ns) * 1e-3);
  if (s.missing_steps > 0) {
    std::fprintf(out, "%-8s %-11s        note: %zu scored frames in %zu runs had no confirmed track (counted lost)\n",
                 "", "", s.missing_steps, s.runs_with_missing);
  }
  if (s.max_confirmed_tracks > 1 || s.track_switches.mean > 0.0) {
    std::fprintf(out,
                 "%-8s %-11s        note: track not held: scored track id changed %.1f times per run, up to %zu "
                 "confirmed tracks in one frame (the nearest is scored)\n",
                 "", "", s.track_switches.mean, s.max_confirmed_tracks);
  }
}

void print_continuity(std::FILE* out, const TableRow& r) {
  const MonteCarloSummary& s = r.summary;
  if (!std::isfinite(s.held_fraction.mean)) return;
  std::fprintf(out,
               "%-8s %-11s        continuity: one confirmed track on target in %s %% of frames after confirmation "
               "(worst run %.2f %%); loss episodes per run %s; track ids on target per run %s (max %zu); "
               "false confirmed tracks per run %s\n",
               "", "", percent(s.held_fraction).c_str(), 100.0 * s.worst_held_fraction,
               interval(s.loss_episodes, "%.3f").c_str(), interval(s.track_ids_on_target, "%.3f").c_str(),
               s.max_track_ids_on_target, interval(s.false_tracks, "%.3f").c_str());
}

void print_timing(std::FILE* out, const std::string& what, const StepTiming& t) {
  std::fprintf(out, "%s: %zu steps, convert+step latency (SteadyClock, ns)\n", what.c_str(), t.steps);
  std::fprintf(out, "  min %llu  median %llu  p99 %llu  max %llu  mean %.0f\n",
               static_cast<unsigned long long>(t.min_ns), static_cast<unsigned long long>(t.median_ns),
               static_cast<unsigned long long>(t.p99_ns), static_cast<unsigned long long>(t.max_ns), t.mean_ns);
  std::fprintf(out, "  budget %.1f us: %zu overruns (%.3f %%)\n", static_cast<double>(t.budget_ns) * 1e-3, t.overruns,
               t.steps > 0 ? 100.0 * static_cast<double>(t.overruns) / static_cast<double>(t.steps) : 0.0);
}

}  // namespace kestrel::sim
