// SPDX-License-Identifier: Apache-2.0
#include "cli/cmd_r2aekf.hpp"

#include <CLI/CLI.hpp>

namespace kestrel::sim::cli {

CLI::App* add_r2aekf_command(CLI::App& app, R2AekfStudyOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "r2aekf-study", "Paper 000 reproduction: tuned EKF-CA, R2-AEKF paper/default, sensitivity, cost, figures");
  cmd->add_option("--scenarios", o.scenarios, "Scenarios (the first one is timed)")->capture_default_str();
  cmd->add_option("--runs,-n", o.runs, "Monte Carlo runs per scenario and filter")->capture_default_str();
  cmd->add_option("--seed", o.seed, "Seed of run 0; run i uses seed + i")->capture_default_str();
  cmd->add_option("--jobs,-j", o.jobs, "Worker threads (results do not depend on it)")->capture_default_str();
  cmd->add_option("--out,-o", o.out, "Output directory")->capture_default_str();
  cmd->add_option("--qj-grid", o.qj_grid, "EKF-CA qj grid, m^2/s^5")->capture_default_str();
  cmd->add_option("--select-runs", o.select_runs, "Runs per scenario for the qj choice")->capture_default_str();
  cmd->add_option("--select-seed", o.select_seed, "Seed of the qj-choice runs")->capture_default_str();
  cmd->add_option("--sensitivity-runs", o.sensitivity_runs, "Runs per scenario and variant (0: skip)")
      ->capture_default_str();
  cmd->add_option("--timing-runs", o.timing_runs, "Runs timed side by side (0: skip)")->capture_default_str();
  cmd->add_option("--budget-us", o.budget_us, "Step budget for overrun counting, us")->capture_default_str();
  cmd->add_flag("!--no-plots", o.plots, "Do not run the plot script");
  return cmd;
}

int cmd_r2aekf(const R2AekfStudyOptions& o) { return run_r2aekf_study(o); }

}  // namespace kestrel::sim::cli
