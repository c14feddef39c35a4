// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim r2aekf-study`: the paper 000 reproduction (docs/r2aekf.md) in
// one command (report/r2aekf_study.hpp): tuned EKF-CA baseline, the five-row
// table over S1, S2, S1n, S2n, the sensitivity table, the side-by-side cost
// per step, run-0 CSVs (steps and per-step scales) and figures 2-5.
// The filters themselves ("r2aekf", "r2aekf-paper", "r2aekf-f32") are in
// the filter registry, so `run`, `replay`, `suite` and `timing` take them.
#pragma once

#include "report/r2aekf_study.hpp"

namespace CLI {
class App;
}

namespace kestrel::sim::cli {

/// Register the subcommand and its options on `app`.
CLI::App* add_r2aekf_command(CLI::App& app, R2AekfStudyOptions& options);

int cmd_r2aekf(const R2AekfStudyOptions& options);

}  // namespace kestrel::sim::cli
