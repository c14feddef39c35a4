// SPDX-License-Identifier: Apache-2.0
#include "montecarlo/multi_run.hpp"

#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "kestrel/association/global_nearest_neighbour.hpp"
#include "kestrel/association/nearest_neighbour.hpp"
#include "kestrel/hal/frame.hpp"
#include "montecarlo/oracle_association.hpp"
#include "pipeline/stream_run.hpp"
#include "stream/quantise.hpp"
#include "stream/stream_writer.hpp"

namespace kestrel::sim {

namespace {

template <template <class, std::size_t, std::size_t> class Associator>
StreamRunResult run_with(const MultiRunParams& config, StreamInput input,
                         const typename MultiTargetTracker<EkfCa<double>, Associator>::AssociatorParams& params) {
  // The associator's parameters do not depend on the filter.
  if (config.filter == MultiFilter::kImm) {
    auto tracker = make_multi_target_tracker<RadarImm<double>, Associator>(config, params);
    return run_stream(*tracker, std::move(input), config.budget_ns);
  }
  auto tracker = make_multi_target_tracker<EkfCa<double>, Associator>(config, params);
  return run_stream(*tracker, std::move(input), config.budget_ns);
}

/// The frame's confirmed tracks into the step that scores it.
void add_confirmed_tracks(const FrameOutcome& frame, MultiTargetStep& s) {
  for (const host::TrackRow& row : frame.tracks) {
    if (!row.confirmed) continue;
    s.track_ids.push_back(row.track_id);
    s.tracks.push_back(Position2{row.x_m, row.y_m});
  }
}

}  // namespace

MultiAssociator multi_associator_by_name(const std::string& name) {
  if (name == "nn") return MultiAssociator::kNearestNeighbour;
  if (name == "gnn") return MultiAssociator::kGlobalNearestNeighbour;
  if (name == "oracle") return MultiAssociator::kOracle;
  throw std::invalid_argument("unknown associator '" + name + "' (known: nn, gnn, oracle)");
}

const char* multi_associator_name(MultiAssociator a) {
  switch (a) {
    case MultiAssociator::kNearestNeighbour: return "nn";
    case MultiAssociator::kGlobalNearestNeighbour: return "gnn";
    case MultiAssociator::kOracle: return "oracle";
  }
  return "?";
}

MultiFilter multi_filter_by_name(const std::string& name) {
  if (name == "ekf-ca") return MultiFilter::kEkfCa;
  if (name == "imm") return MultiFilter::kImm;
  throw std::invalid_argument("unknown filter '" + name + "' for several targets (known: ekf-ca, imm)");
}

const char* multi_filter_name(MultiFilter f) { return f == MultiFilter::kImm ? "imm" : "ekf-ca"; }

MultiAssociator default_multi_associator(const ScenarioInfo& info) {
  return info.targets > 1 ? MultiAssociator::kGlobalNearestNeighbour : MultiAssociator::kNearestNeighbour;
}

std::vector<MultiTargetStep> multi_target_steps(const ScenarioRun& run, const StreamRunResult& stream) {
  if (run.targets.empty()) throw std::invalid_argument("not a multi-target run");
  std::vector<MultiTargetStep> steps;
  const std::size_t n = std::min(stream.frames.size(), run.frames.size());
  steps.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    MultiTargetStep s;
    s.t_s = run.frames[k].t_s;
    for (const auto& target : run.targets) s.truths.push_back(Position2{target[k].x_m, target[k].y_m});
    add_confirmed_tracks(stream.frames[k], s);
    steps.push_back(std::move(s));
  }
  return steps;
}

StreamRunResult run_multi_stream(const MultiRunParams& config, StreamInput input) {
  switch (config.associator) {
    case MultiAssociator::kNearestNeighbour: return run_with<NearestNeighbour>(config, std::move(input), {});
    case MultiAssociator::kGlobalNearestNeighbour:
      return run_with<GlobalNearestNeighbour>(config, std::move(input), {});
    case MultiAssociator::kOracle: break;
  }
  throw std::invalid_argument("the oracle associator needs each plot's origin, which a recorded stream does not carry");
}

std::vector<MultiTargetStep> multi_target_steps_at_times(const std::vector<std::vector<TruthSample>>& targets,
                                                         const StreamRunResult& stream, std::size_t& without_truth) {
  // Each target's position by wire time; a frame is scored where all have one.
  std::map<std::int64_t, std::vector<Position2>> at;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    for (const TruthSample& s : targets[i]) {
      const std::optional<std::int64_t> t_us = try_wire_time_us(s.t_s);
      if (!t_us.has_value()) continue;
      std::vector<Position2>& row = at[*t_us];
      if (row.size() == i) row.push_back(Position2{s.x_m, s.y_m});
    }
  }
  std::vector<MultiTargetStep> steps;
  without_truth = 0;
  for (const FrameOutcome& f : stream.frames) {
    if (!f.decoded) continue;
    const auto it = at.find(f.t_us);
    if (it == at.end() || it->second.size() != targets.size()) {
      ++without_truth;
      continue;
    }
    MultiTargetStep s;
    s.t_s = static_cast<double>(f.t_us) * 1e-6;
    s.truths = it->second;
    add_confirmed_tracks(f, s);
    steps.push_back(std::move(s));
  }
  return steps;
}

MultiRunDetail run_multi_once(const Scenario& scenario, std::uint64_t seed, const MultiRunParams& config) {
  const ScenarioRun generated = scenario.generate(seed);
  std::vector<std::uint8_t> bytes = encode_stream(generated.frames);
  MultiRunDetail d;
  d.seed = seed;
  if (config.associator == MultiAssociator::kOracle) {
    OracleLabels labels;
    // Keyed by the time the wire carries, which is what the tracker sees.
    for (std::size_t k = 0; k < generated.frames.size(); ++k) {
      labels.origins[to_wire_frame(generated.frames[k]).t_us] = generated.origins[k];
    }
    d.stream = run_with<OracleAssociation>(config, std::move(bytes), {&labels});
  } else {
    d.stream = run_multi_stream(config, std::move(bytes));
  }
  d.steps = multi_target_steps(generated, d.stream);
  d.metrics = compute_multi_target_metrics(d.steps, config.spa, config.persistence_steps);
  return d;
}

}  // namespace kestrel::sim
