// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim multi`: Monte Carlo runs of a multi-target radar scenario
// (crossing, raid, formation-split; docs/multitarget.md) with the EKF-CA
// radar tracker, scored with OSPA, GOSPA, track swaps, false confirmed
// tracks, fragmentation and time to confirm; optionally beside the same
// runs with the oracle associator.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace kestrel::sim::cli {

struct MultiOptions {
  std::string scenario;
  std::size_t runs = 200;
  std::uint64_t seed = 0;
  unsigned jobs = 1;
  std::string out;              ///< Default results/<scenario>-multi.
  std::string associator;       ///< nn, gnn, oracle; empty: gnn with more than one target.
  std::string filter = "ekf-ca";  ///< ekf-ca or imm.
  bool compare_oracle = false;  ///< Also run the oracle associator on the same seeds.
  std::optional<double> qj;             ///< --qj: wins over --set and --config.
  std::string config;                   ///< --config FILE (filters/settings.hpp keys).
  std::vector<std::string> sets;        ///< --set KEY=VALUE, in order.
  std::optional<double> gate_tentative;  ///< 0.90, 0.95, 0.99, 0.995 or 0.999.
  double cutoff_m = 500.0;
  double order = 2.0;
  std::size_t persistence_steps = 3;
  double budget_us = 1000.0;
  bool plots = true;  ///< multi_gospa.png from multi_steps.csv.
};

CLI::App* add_multi_command(CLI::App& app, MultiOptions& options);
int cmd_multi(const MultiOptions& options);

}  // namespace kestrel::sim::cli
