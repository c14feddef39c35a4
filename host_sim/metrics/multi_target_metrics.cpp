// SPDX-License-Identifier: Apache-2.0
#include "metrics/multi_target_metrics.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

#include "kestrel/association/gnn.hpp"

namespace kestrel::sim {

namespace {

constexpr std::size_t kMaxSet = 64;  // truths (rows) and tracks (columns) per step
using Solver = Gnn<double, kMaxSet, kMaxSet>;

double distance(const Position2& a, const Position2& b) { return std::hypot(a.x_m - b.x_m, a.y_m - b.y_m); }

/// Minimise sum of cost over assigned pairs + miss per unassigned row;
/// returns the total and the column of each row (-1: none).
double solve(const Solver::CostMatrix& cost, double miss, std::vector<int>& col_of_row) {
  const auto solver = std::make_unique<Solver>();  // about 1 kB of arrays: off the stack
  int cols[kMaxSet];
  double total = 0.0;
  if (solver->solve(cost, miss, cols, total) != Status::kOk) throw std::runtime_error("assignment solver refused a metric problem");
  col_of_row.assign(cols, cols + cost.rows());
  return total;
}

void check_sizes(std::size_t truths, std::size_t tracks) {
  if (truths > kMaxSet || tracks > kMaxSet) throw std::invalid_argument("multi-target metrics take at most 64 truths and 64 tracks per step");
}

/// An assignment that changes only when the new value held for
/// `persistence` observations in a row; counts the changes.
struct Hysteresis {
  long established = -1;
  long candidate = -1;
  std::size_t count = 0;
  std::size_t changes = 0;
  void observe(long v, std::size_t persistence) {
    if (established < 0) {
      established = v;
      return;
    }
    if (v == established) {
      candidate = -1;
      count = 0;
      return;
    }
    if (v == candidate) {
      ++count;
    } else {
      candidate = v;
      count = 1;
    }
    if (count >= persistence) {
      established = v;
      candidate = -1;
      count = 0;
      ++changes;
    }
  }
};

}  // namespace

Gospa gospa(std::span<const Position2> truths, std::span<const Position2> tracks, const SpaParams& c) {
  check_sizes(truths.size(), tracks.size());
  const double cp = std::pow(c.cutoff_m, c.order);
  Gospa g;
  g.assignment.assign(truths.size(), -1);
  if (!truths.empty() && !tracks.empty()) {
    Solver::CostMatrix cost(static_cast<Eigen::Index>(truths.size()), static_cast<Eigen::Index>(tracks.size()));
    for (std::size_t i = 0; i < truths.size(); ++i) {
      for (std::size_t j = 0; j < tracks.size(); ++j) {
        const double d = distance(truths[i], tracks[j]);
        // Only pairs closer than c may be assigned (alpha = 2).
        cost(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
            d < c.cutoff_m ? std::pow(d, c.order) : std::numeric_limits<double>::infinity();
      }
    }
    // Sum d^p + c^p per unassigned truth has the optimum of
    // sum (d^p - c^p): GOSPA's, whose constant part is c^p/2 (|X| + |Y|).
    solve(cost, cp, g.assignment);
  }
  std::size_t assigned = 0;
  for (std::size_t i = 0; i < truths.size(); ++i) {
    const int j = g.assignment[i];
    if (j < 0) continue;
    ++assigned;
    g.localisation_p += std::pow(distance(truths[i], tracks[static_cast<std::size_t>(j)]), c.order);
  }
  g.missed = truths.size() - assigned;
  g.false_tracks = tracks.size() - assigned;
  g.gospa = std::pow(g.localisation_p + 0.5 * cp * static_cast<double>(g.missed + g.false_tracks), 1.0 / c.order);
  return g;
}

double ospa(std::span<const Position2> truths, std::span<const Position2> tracks, const SpaParams& c) {
  check_sizes(truths.size(), tracks.size());
  if (truths.empty() && tracks.empty()) return 0.0;
  if (truths.empty() || tracks.empty()) return c.cutoff_m;
  const bool truths_smaller = truths.size() <= tracks.size();
  const std::span<const Position2> small = truths_smaller ? truths : tracks;
  const std::span<const Position2> large = truths_smaller ? tracks : truths;
  const double cp = std::pow(c.cutoff_m, c.order);
  Solver::CostMatrix cost(static_cast<Eigen::Index>(small.size()), static_cast<Eigen::Index>(large.size()));
  for (std::size_t i = 0; i < small.size(); ++i) {
    for (std::size_t j = 0; j < large.size(); ++j) {
      cost(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          std::pow(std::min(distance(small[i], large[j]), c.cutoff_m), c.order);
    }
  }
  // A row left unassigned costs c^p, as much as any capped pair: the
  // optimum equals that of the full assignment of the smaller set.
  std::vector<int> unused;
  const double total = solve(cost, cp, unused);
  const double n = static_cast<double>(large.size());
  return std::pow((total + cp * (n - static_cast<double>(small.size()))) / n, 1.0 / c.order);
}

MultiTargetRunMetrics compute_multi_target_metrics(std::span<const MultiTargetStep> steps, const SpaParams& c,
                                                   std::size_t persistence_steps) {
  MultiTargetRunMetrics m;
  if (steps.empty()) return m;
  const std::size_t n_truths = steps.front().truths.size();
  struct TrackLife {
    std::size_t reported = 0;
    std::size_t assigned = 0;
    Hysteresis truth;
  };
  std::map<std::uint32_t, TrackLife> tracks;
  std::vector<Hysteresis> truth_track(n_truths);
  m.time_to_confirm_s.assign(n_truths, -1.0);
  double sum_loc = 0.0;
  double sum_missed = 0.0;
  double sum_false = 0.0;
  for (const MultiTargetStep& s : steps) {
    if (s.truths.size() != n_truths || s.tracks.size() != s.track_ids.size()) {
      throw std::invalid_argument("multi-target step with a different truth count or ids and tracks apart");
    }
    const Gospa g = gospa(s.truths, s.tracks, c);
    m.gospa_m.push_back(g.gospa);
    m.ospa_m.push_back(ospa(s.truths, s.tracks, c));
    sum_loc += std::pow(g.localisation_p, 1.0 / c.order);
    sum_missed += static_cast<double>(g.missed);
    sum_false += static_cast<double>(g.false_tracks);
    for (const std::uint32_t id : s.track_ids) ++tracks[id].reported;
    for (std::size_t i = 0; i < n_truths; ++i) {
      const int j = g.assignment[i];
      if (j < 0) continue;
      const std::uint32_t id = s.track_ids[static_cast<std::size_t>(j)];
      TrackLife& life = tracks[id];
      ++life.assigned;
      life.truth.observe(static_cast<long>(i), persistence_steps);
      truth_track[i].observe(static_cast<long>(id), persistence_steps);
      if (m.time_to_confirm_s[i] < 0.0) m.time_to_confirm_s[i] = s.t_s - steps.front().t_s;
    }
  }
  const double n = static_cast<double>(steps.size());
  double sum_gospa = 0.0;
  double sum_ospa = 0.0;
  for (const double v : m.gospa_m) sum_gospa += v;
  for (const double v : m.ospa_m) sum_ospa += v;
  m.mean_gospa_m = sum_gospa / n;
  m.mean_ospa_m = sum_ospa / n;
  m.mean_gospa_localisation_m = sum_loc / n;
  m.mean_missed = sum_missed / n;
  m.mean_false = sum_false / n;
  m.confirmed_tracks = tracks.size();
  for (const auto& [id, life] : tracks) {
    m.swaps += life.truth.changes;
    if (2 * (life.reported - life.assigned) > life.reported) ++m.false_tracks;
  }
  for (const Hysteresis& h : truth_track) m.fragmentations += h.changes;
  return m;
}

}  // namespace kestrel::sim
