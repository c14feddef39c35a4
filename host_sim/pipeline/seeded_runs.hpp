// SPDX-License-Identifier: Apache-2.0
// The Monte Carlo loop of a sensor kind that keeps its own scenario run
// and tracker output types (PCL, sonar): run i uses seed base_seed + i for
// everything random in it, runs go through the one worker pool, and run
// 0's truth, frames and tracker output are kept for the CSVs and plots.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "pipeline/worker_pool.hpp"

namespace kestrel::sim {

template <class Metrics, class ScenarioRun, class Output>
struct SeededRuns {
  std::vector<Metrics> runs;  ///< In seed order.
  ScenarioRun first_run;      ///< Run 0's truth and frames.
  Output first_output;        ///< Run 0's tracker output.
};

/// generate(seed) -> ScenarioRun, track(run) -> Output, score(run, output)
/// -> Metrics, whose `seed` this sets. Each run writes only its own slot,
/// so the figures do not depend on `jobs` (step times do).
template <class Result, class Generate, class Track, class Score>
Result run_seeded(std::size_t runs, std::uint64_t base_seed, unsigned jobs, const char* label, Generate generate,
                  Track track, Score score) {
  Result result;
  result.runs.resize(runs);
  for_each_index(
      runs, jobs,
      [&](std::size_t i) {
        const std::uint64_t seed = base_seed + i;
        auto run = generate(seed);
        auto output = track(run);
        result.runs[i] = score(run, output);
        result.runs[i].seed = seed;
        if (i == 0) {  // only the worker that takes i == 0 writes these
          result.first_run = std::move(run);
          result.first_output = std::move(output);
        }
      },
      Progress{label});
  return result;
}

}  // namespace kestrel::sim
