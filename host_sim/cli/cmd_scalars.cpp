// SPDX-License-Identifier: Apache-2.0
#include "cli/cmd_scalars.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "kestrel/scalar/fixed_point.hpp"
#include "montecarlo/single_run.hpp"
#include "cli/scenario_report.hpp"
#include "scenarios/registry.hpp"

namespace kestrel::sim::cli {

namespace {

constexpr std::string_view kSuffixes[] = {"", "-f32", "-q31_32", "-q23_40"};  // kScalarNames order

std::string base_name(std::string_view filter) {
  for (std::string_view s : kSuffixes) {
    if (!s.empty() && filter.size() > s.size() && filter.substr(filter.size() - s.size()) == s) {
      return std::string(filter.substr(0, filter.size() - s.size()));
    }
  }
  return std::string(filter);
}

/// One scalar's row of the comparison table.
struct Row {
  std::string scalar;
  const FilterEntry* filter = nullptr;
  double rmse_sum = 0.0;
  std::size_t rmse_runs = 0;
  double worst_rmse_rel = 0.0;     ///< max over runs of |RMSE / RMSE_double - 1|
  double worst_deviation_m = 0.0;  ///< max |p - p_double| over matched reports
  std::size_t other_frames = 0;    ///< frames whose report ids differ from double's
  std::uint64_t saturations = 0;   ///< fixed-point saturation events
  std::vector<std::uint64_t> step_ns;
};

/// Largest position difference between two runs' reports (matched by
/// track id); frames whose id sets differ are counted, not compared.
void compare_runs(const RunDetail& ref, const RunDetail& run, Row& row) {
  const auto& a = ref.stream.frames;
  const auto& b = run.stream.frames;
  const std::size_t n = std::min(a.size(), b.size());
  row.other_frames += std::max(a.size(), b.size()) - n;
  for (std::size_t k = 0; k < n; ++k) {
    std::map<std::uint32_t, const host::TrackRow*> by_id;
    for (const auto& t : a[k].tracks) by_id[t.track_id] = &t;
    bool same = a[k].tracks.size() == b[k].tracks.size();
    for (const auto& t : b[k].tracks) {
      const auto it = by_id.find(t.track_id);
      if (it == by_id.end()) {
        same = false;
        continue;
      }
      row.worst_deviation_m = std::max(row.worst_deviation_m, std::hypot(t.x_m - it->second->x_m, t.y_m - it->second->y_m));
    }
    if (!same) ++row.other_frames;
  }
}

double median_us(std::vector<std::uint64_t> v) {
  if (v.empty()) return std::nan("");
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return static_cast<double>(*mid) / 1000.0;
}

}  // namespace

void add_scalar_option(CLI::App* cmd, std::string& scalar) {
  cmd->add_option("--scalar", scalar, "Scalar of the filter: double, float, q31_32 or q23_40 (default: as --filter names it)")
      ->check(CLI::IsMember({"double", "float", "q31_32", "q23_40"}));
}

std::string filter_for_scalar(std::string_view filter, std::string_view scalar) {
  if (scalar.empty()) return std::string(filter);
  for (std::size_t i = 0; i < std::size(kScalarNames); ++i) {
    if (kScalarNames[i] != scalar) continue;
    const std::string name = base_name(filter) + std::string(kSuffixes[i]);
    for (const FilterEntry& e : filter_registry()) {
      if (e.name == name) return name;
    }
    throw std::invalid_argument("filter '" + base_name(filter) + "' has no " + std::string(scalar) + " build (no '" +
                                name + "' in `kestrel-sim list`)");
  }
  throw std::invalid_argument("unknown scalar '" + std::string(scalar) + "' (double, float, q31_32, q23_40)");
}

CLI::App* add_scalars_command(CLI::App& app, ScalarsOptions& o) {
  CLI::App* cmd = app.add_subcommand("scalars", "Compare double, float, Q31.32 and Q23.40 builds of a filter on the same runs");
  cmd->add_option("--scenario,-s", o.scenario, "Scenario (see `list`)")->required();
  cmd->add_option("--filter,-f", o.filter, "Filter family (see `list`)")->capture_default_str();
  cmd->add_option("--qj", o.options.qj, "White-jerk PSD of CA filters, m^2/s^5 (default 1.6)");
  cmd->add_option("--gate-d2", o.options.confirmed_gate_d2, "Gate of confirmed tracks, d2 units (default: ungated)");
  cmd->add_option("--budget-us", o.budget_us, "Step budget for overrun counting, us")->capture_default_str();
  cmd->add_option("--runs,-n", o.runs, "Runs (seeds seed .. seed + runs - 1)")->capture_default_str();
  cmd->add_option("--seed", o.seed, "Seed of run 0")->capture_default_str();
  return cmd;
}

int cmd_scalars(const ScalarsOptions& o) {
  if (o.runs == 0) throw std::invalid_argument("--runs must be at least 1");
  const auto scenario = make_scenario(o.scenario);
  const ScenarioInfo& info = scenario->info();
  const std::uint64_t budget_ns = budget_ns_from_us(o.budget_us);
  const ScoringParams scoring;

  std::vector<Row> rows;
  for (std::string_view s : kScalarNames) {
    try {
      Row r;
      r.scalar = std::string(s);
      r.filter = &find_filter(filter_for_scalar(o.filter, s));
      rows.push_back(std::move(r));
    } catch (const std::invalid_argument& e) {
      std::printf("(skipped: %s)\n", e.what());
    }
  }
  if (rows.empty() || rows.front().scalar != "double") {
    throw std::invalid_argument("filter '" + base_name(o.filter) + "' has no double build to compare with");
  }

  // One job at a time: the step times are comparable and the saturation
  // counter (per thread) belongs to the run that just finished.
  for (std::size_t i = 0; i < o.runs; ++i) {
    const std::uint64_t seed = o.seed + i;
    const RunDetail ref = run_scenario_once(*scenario, seed, *rows.front().filter, o.options, budget_ns, scoring);
    for (Row& row : rows) {
      reset_fixed_point_overflow_count();
      const RunDetail run = &row == &rows.front()
                                ? ref
                                : run_scenario_once(*scenario, seed, *row.filter, o.options, budget_ns, scoring);
      row.saturations += fixed_point_overflow_count();
      if (std::isfinite(run.metrics.rmse_m)) {
        row.rmse_sum += run.metrics.rmse_m;
        ++row.rmse_runs;
        if (std::isfinite(ref.metrics.rmse_m) && ref.metrics.rmse_m > 0) {
          row.worst_rmse_rel = std::max(row.worst_rmse_rel, std::fabs(run.metrics.rmse_m / ref.metrics.rmse_m - 1));
        }
      }
      compare_runs(ref, run, row);
      for (const FrameOutcome& f : run.stream.frames) {
        if (f.stepped) row.step_ns.push_back(f.step_ns);
      }
    }
  }

  std::printf("%s, %s, %zu runs (seeds %llu..%llu): every scalar on the same streams\n", info.name.c_str(),
              rows.front().filter->setup(o.options).label.c_str(), o.runs, static_cast<unsigned long long>(o.seed),
              static_cast<unsigned long long>(o.seed + o.runs - 1));
  std::printf("%-8s %-15s %12s %18s %16s %13s %12s %15s\n", "scalar", "filter", "RMSE m", "max|dRMSE|/RMSE",
              "max|p-p_dbl| m", "other frames", "saturations", "median step us");
  for (const Row& r : rows) {
    const double rmse = r.rmse_runs > 0 ? r.rmse_sum / static_cast<double>(r.rmse_runs) : std::nan("");
    std::printf("%-8s %-15s %12.4f %18.2e %16.2e %13zu %12llu %15.1f\n", r.scalar.c_str(),
                std::string(r.filter->name).c_str(), rmse, r.worst_rmse_rel, r.worst_deviation_m, r.other_frames,
                static_cast<unsigned long long>(r.saturations), median_us(r.step_ns));
  }
  std::printf("  RMSE: mean over runs; differences against the double build's run with the same seed;\n"
              "  step time: hal::Runner around adapter + Tracker::step, wall clock on this host (compare medians)\n");
  return 0;
}

}  // namespace kestrel::sim::cli
