// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim montecarlo --campaign mc001` and `kestrel-sim merge DIR...`:
// the MC-001 grid of paper 001 over every filter (campaigns/mc001.hpp),
// on every core, optionally as one shard of a cluster job array whose
// outputs `merge` joins into the same table bit for bit (docs/filters.md
// has a Slurm example).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace kestrel::sim::cli {

struct MonteCarloOptions {
  std::string campaign = "mc001";
  std::uint64_t runs = 3000;  ///< Runs per cell (seeds 0..runs-1).
  unsigned threads = 0;       ///< 0: every core (std::thread::hardware_concurrency).
  std::string shard;          ///< "K/N" (1-based), empty: all runs.
  std::string out;            ///< Default results/mc001 (a shard: results/mc001/shard-K-of-N).
  bool plots = true;
  bool progress = true;
};

struct MergeOptions {
  std::vector<std::string> dirs;  ///< Shard output directories.
  std::string out = "results/mc001";
  bool plots = true;
};

/// Register `montecarlo` and `merge` on `app`; returns them for dispatch.
void add_montecarlo_commands(CLI::App& app, MonteCarloOptions& mc, MergeOptions& merge, CLI::App*& mc_cmd,
                             CLI::App*& merge_cmd);

int cmd_montecarlo(const MonteCarloOptions& options);
int cmd_merge(const MergeOptions& options);

}  // namespace kestrel::sim::cli
