// SPDX-License-Identifier: Apache-2.0
// kestrel-sim: scenario generation, Monte Carlo runs, replay of recorded
// data and timing of the real-time loop, all through the HAL exactly as a
// board runs the tracker (docs/host_sim.md). This file only parses the
// command line; each subcommand lives in its own cmd_*.cpp.
#include <cstdio>
#include <exception>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cmd_montecarlo.hpp"
#include "cli/cmd_r2aekf.hpp"
#include "cli/cmd_scalars.hpp"
#include "cli/commands.hpp"
#include "kestrel/version.hpp"
#include "scenarios/sensor_kind.hpp"

namespace {

using namespace kestrel::sim::cli;  // NOLINT(google-build-using-namespace): this file wires them up

// How a command gates confirmed tracks when no option says: `run` and the
// commands like it score as the papers do (ungated), `replay` as a board.
enum class ConfirmedGateDefault { kUngated, kBoard };

void add_model_options(CLI::App* cmd, kestrel::sim::FilterOptions& o,
                       ConfirmedGateDefault gate = ConfirmedGateDefault::kUngated) {
  const bool board = gate == ConfirmedGateDefault::kBoard;
  cmd->add_option("--qj", o.qj, "White-jerk PSD of CA filters, m^2/s^5 (default 1.6)");
  cmd->add_option("--gate-d2", o.confirmed_gate_d2,
                  std::string("Gate of confirmed tracks, d2 units (e.g. 13.8 = 0.999 for 2 dof; default: ") +
                      (board ? "the board's gate, --ungated for none)" : "ungated)"));
  cmd->add_flag("--board-gate", o.board_gate,
                board ? "Without --gate-d2: gate confirmed tracks as a board does (its chi-square gate); the default "
                        "here"
                      : "Without --gate-d2: gate confirmed tracks as a board does (its chi-square gate) instead of "
                        "not at all");
  cmd->add_option("--robust-gate", o.robust_gate_factor,
                  "With the board's gate: take plots up to this factor x the gate's d2 with a shrunk innovation "
                  "(default 0: off; 25 for a sensor without clutter, docs/robustness.md)");
  cmd->add_option("--imm", o.imm,
                  "IMM parameter override KEY=VALUE, repeatable (filters imm, imm-f32; keys in docs/imm.md)");
}

// --set is left to the caller when it means more (sweep's value lists).
void add_filter_options(CLI::App* cmd, FilterChoice& f, bool with_set = true,
                        ConfirmedGateDefault gate = ConfirmedGateDefault::kUngated) {
  cmd->add_option("--filter,-f", f.filter, "Filter (see `list`)")->capture_default_str();
  add_scalar_option(cmd, f.scalar);
  add_model_options(cmd, f.options, gate);
  cmd->add_option("--config", f.config,
                  "JSON file of tracker and filter parameters by key (`list --settings`, docs/parameters.md)");
  if (with_set) {
    cmd->add_option("--set", f.sets,
                    "KEY=VALUE, repeatable: one parameter (`list --settings`); wins over --config, loses to "
                    "the parameter's own option (--qj, ...)");
  }
  cmd->add_option("--budget-us", f.budget_us, "Step budget for overrun counting, us")->capture_default_str();
}

// --asterix-out and its SAC/SIC (docs/asterix.md, "kestrel-sim and ASTERIX").
void add_cat062_output(CLI::App* cmd, Cat062Output& o) {
  cmd->add_option("--asterix-out", o.path, "Also write every published track report as a CAT062 data block to FILE");
  cmd->add_option("--sac", o.sac, "I062/010 SAC of --asterix-out")->check(CLI::Range(0, 255))->capture_default_str();
  cmd->add_option("--sic", o.sic, "I062/010 SIC of --asterix-out")->check(CLI::Range(0, 255))->capture_default_str();
}

// Which of `names` the user gave on `cmd` (CLI11 throws for a name it does
// not know, so a misspelt one here fails every time, not silently).
std::vector<std::string> given_options(const CLI::App* cmd, std::initializer_list<const char*> names) {
  std::vector<std::string> out;
  for (const char* n : names) {
    if (cmd->count(n) > 0) out.emplace_back(n);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"kestrel-sim: drive the Kestrel tracker through the HAL with simulated or recorded data"};
  app.require_subcommand(1);

  bool list_settings = false;
  app.add_subcommand("list", "List scenarios and filters")
      ->add_flag("--settings", list_settings, "List the parameter keys of --set and --config instead");

  GenerateOptions gen;
  CLI::App* generate = app.add_subcommand("generate", "Write one seeded run as a stream file plus truth and plot CSVs");
  generate->add_option("--scenario,-s", gen.scenario, "Scenario (see `list`)")->required();
  generate->add_option("--seed", gen.seed, "Noise seed")->capture_default_str();
  generate->add_option("--out,-o", gen.out, "Stream file; FILE.truth.csv and FILE.plots.csv are written beside it")
      ->required();
  generate->add_flag("--asterix", gen.asterix,
                     "Also write the plots as ASTERIX CAT048 data blocks to FILE.ast (FILE without its extension)");
  generate->add_option("--sac", gen.asterix_sac, "I048/010 SAC of the CAT048 blocks (SIC = the plot's sensor_id)")
      ->check(CLI::Range(0, 255))
      ->capture_default_str();

  RunOptions run;
  CLI::App* run_cmd = app.add_subcommand("run", "Monte Carlo runs of one scenario with one filter");
  run_cmd->add_option("--scenario,-s", run.scenario, "Scenario (see `list`): radar (one or several targets), PCL or sonar")
      ->required();
  add_filter_options(run_cmd, run.filter);
  run_cmd->add_option("--runs,-n", run.runs, "Monte Carlo runs")->capture_default_str();
  run_cmd->add_option("--seed", run.seed, "Seed of run 0; run i uses seed + i")->capture_default_str();
  run_cmd->add_option("--jobs,-j", run.jobs, "Worker threads (results do not depend on it)")->capture_default_str();
  run_cmd->add_option("--out,-o", run.out, "Output directory (default results/<scenario>)");
  run_cmd->add_flag("!--no-plots", run.plots, "Do not run the plot script");
  add_cat062_output(run_cmd, run.asterix_out);
  // Options of some kinds only; each is refused for a kind it does not fit.
  run_cmd->add_option("--associator", run.kind.associator,
                      "PCL: nn, gnn or pda (default nn); several radar targets: nn, gnn or oracle (default gnn)");
  run_cmd->add_option("--manager", run.kind.manager, "PCL: m-of-n (default) or score (sequential log-likelihood ratio)");
  run_cmd->add_option("--gate-tentative", run.kind.gate_tentative,
                      "PCL, several radar targets: gate probability of tentative tracks");
  run_cmd->add_flag("--compare-oracle", run.kind.compare_oracle,
                    "Several radar targets: also the oracle associator on the same seeds");
  run_cmd->add_option("--cutoff", run.kind.cutoff_m, "Several radar targets: OSPA/GOSPA cut-off c, m")
      ->capture_default_str();
  run_cmd->add_option("--order", run.kind.order, "Several radar targets: OSPA/GOSPA order p")->capture_default_str();
  run_cmd->add_option("--persistence", run.kind.persistence_steps,
                      "Several radar targets: steps a changed assignment must hold to count as a swap")
      ->capture_default_str();

  SuiteOptions suite;
  CLI::App* suite_cmd = app.add_subcommand(
      "suite", "The main job: each paper's system (radar S1/S2, MC-001, PCL-002, UW-003) and one report.md");
  suite_cmd->add_option("--parts", suite.parts, "Parts: radar, mc001, pcl, sonar")->capture_default_str();
  suite_cmd->add_option("--scenarios", suite.scenarios, "Radar scenarios")->capture_default_str();
  suite_cmd->add_option("--filters", suite.filters, "Radar filters, NAME or NAME:qj=X")->capture_default_str();
  add_model_options(suite_cmd, suite.options);
  suite_cmd->add_option("--budget-us", suite.budget_us, "Step budget, us")->capture_default_str();
  suite_cmd->add_option("--runs,-n", suite.runs, "Runs per radar entry, of PCL-002 and of UW-003")
      ->capture_default_str();
  suite_cmd->add_option("--mc-runs", suite.mc_runs, "Runs per MC-001 cell")->capture_default_str();
  suite_cmd->add_option("--seed", suite.seed, "Seed of run 0")->capture_default_str();
  suite_cmd->add_option("--jobs,-j", suite.jobs, "Worker threads (0: every core)")->capture_default_str();
  suite_cmd->add_option("--out,-o", suite.out, "Output directory")->capture_default_str();
  suite_cmd->add_flag("!--no-plots", suite.plots, "Do not run the plot scripts");

  SweepOptions sweep;
  CLI::App* sweep_cmd = app.add_subcommand("sweep", "One scenario and filter over values of one parameter (same seeds)");
  sweep_cmd->add_option("--scenario,-s", sweep.scenario, "Scenario (see `list`)")->required();
  add_filter_options(sweep_cmd, sweep.filter, false);
  sweep_cmd->add_option("--set", sweep.filter.sets,
                        "KEY=V1,V2,...: the swept parameter, e.g. qj=1.6,16,160,500; KEY=VALUE, repeatable: a fixed "
                        "one (`list --settings`)")
      ->required();
  sweep_cmd->add_option("--runs,-n", sweep.runs, "Monte Carlo runs per value")->capture_default_str();
  sweep_cmd->add_option("--seed", sweep.seed, "Seed of run 0; run i uses seed + i")->capture_default_str();
  sweep_cmd->add_option("--jobs,-j", sweep.jobs, "Worker threads (results do not depend on it)")->capture_default_str();
  sweep_cmd->add_option("--out,-o", sweep.out, "Output directory (default results/sweep-<scenario>-<filter>)");
  sweep_cmd->add_flag("--plots", sweep.plots, "Draw each value's figures");

  ReplayOptions replay;
  CLI::App* replay_cmd = app.add_subcommand(
      "replay", "Run a tracker over a recorded stream file (radar, PCL or sonar), plot CSV or CAT048 recording");
  auto* stream_opt = replay_cmd->add_option("--stream", replay.stream, "Wire stream file");
  auto* csv_opt = replay_cmd->add_option("--csv", replay.csv, "Radar plot CSV (time_s,range_m,bearing_rad,...)");
  auto* asterix_opt =
      replay_cmd->add_option("--asterix", replay.asterix, "ASTERIX CAT048 data blocks back to back (.ast)");
  stream_opt->excludes(csv_opt);
  csv_opt->excludes(stream_opt);
  asterix_opt->excludes(stream_opt)->excludes(csv_opt);
  replay_cmd->add_option("--truth", replay.truth, "Truth CSV (time_s,x_m,y_m,...): score the run");
  replay_cmd
      ->add_option("--associator", replay.associator,
                   "Radar stream: run the multi-target tracker with this associator, nn or gnn (default: gnn with "
                   "the truth of several targets, else the filter's own tracker)")
      ->check(CLI::IsMember({"nn", "gnn"}));
  replay_cmd->add_option("--scenario,-s", replay.scenario,
                         "PCL or sonar stream: the scenario whose sensor parameters the tracker takes "
                         "(default pcl002 / uw003)");
  add_filter_options(replay_cmd, replay.filter, true, ConfirmedGateDefault::kBoard);
  replay_cmd->add_option("--loss-threshold-m", replay.loss_threshold_m, "L of the track-loss metric, m")
      ->capture_default_str();
  replay_cmd->add_option("--first-scored-step", replay.first_scored_step, "First frame index scored")
      ->capture_default_str();
  replay_cmd->add_option("--out,-o", replay.out, "Output directory")->capture_default_str();
  replay_cmd->add_flag("--ungated", replay.ungated,
                       "Confirmed tracks ungated, as the papers score filters (default: the board's gate)");
  replay_cmd->add_flag("!--no-plots", replay.plots, "Do not run the plot script");
  add_cat062_output(replay_cmd, replay.asterix_out);

  TimingOptions timing;
  CLI::App* timing_cmd = app.add_subcommand("timing", "Per-step latency of the real-time loop");
  timing_cmd->add_option("--scenario,-s", timing.scenario, "Scenario (see `list`)");
  timing_cmd->add_option("--worst-case", timing.worst_case,
                         "Instead of a scenario: the worst-case frame of a board (cortex-m4f, cortex-m7, "
                         "cortex-m0plus, riscv64-linux, host), as its frame budget counts it; --runs: repetitions");
  add_filter_options(timing_cmd, timing.filter);
  timing_cmd->add_option("--runs,-n", timing.runs, "Runs")->capture_default_str();
  timing_cmd->add_option("--seed", timing.seed, "Seed of run 0")->capture_default_str();

  kestrel::sim::R2AekfStudyOptions r2aekf;
  CLI::App* r2aekf_cmd = add_r2aekf_command(app, r2aekf);

  RunOptions sonar_study;
  sonar_study.runs = 200;
  CLI::App* sonar_study_cmd = app.add_subcommand(
      "sonar-study", "Every sonar scenario (uw003 and variants) with the paper's gate k = 2, k = 3 and no gate");
  sonar_study_cmd->add_option("--runs,-n", sonar_study.runs, "Monte Carlo runs per row")->capture_default_str();
  sonar_study_cmd->add_option("--seed", sonar_study.seed, "Seed of run 0; run i uses seed + i")->capture_default_str();
  sonar_study_cmd->add_option("--jobs,-j", sonar_study.jobs, "Worker threads (results do not depend on it)")
      ->capture_default_str();
  sonar_study_cmd->add_option("--out,-o", sonar_study.out, "Output directory (default results/sonar_study)");
  sonar_study_cmd->add_flag("!--no-plots", sonar_study.plots, "Do not run the plot script");
  sonar_study_cmd->add_option("--budget-us", sonar_study.filter.budget_us, "Step budget for overrun counting, us")
      ->capture_default_str();
  sonar_study_cmd->add_option("--config", sonar_study.filter.config,
                              "JSON file of sonar tracker parameters by key (`list --settings`)");
  sonar_study_cmd->add_option("--set", sonar_study.filter.sets,
                              "KEY=VALUE, repeatable: one sonar tracker parameter (each row sets its own gate)");

  ScalarsOptions scalars;
  CLI::App* scalars_cmd = add_scalars_command(app, scalars);

  MonteCarloOptions montecarlo;
  MergeOptions merge;
  CLI::App* montecarlo_cmd = nullptr;
  CLI::App* merge_cmd = nullptr;
  add_montecarlo_commands(app, montecarlo, merge, montecarlo_cmd, merge_cmd);

  app.set_version_flag("--version", "kestrel-sim " KESTREL_VERSION_STRING);
  // CLI11 reports a mistyped subcommand as a missing one; name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    std::string known;
    bool found = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
      known += (known.empty() ? "" : ", ") + sub->get_name();
      found = found || sub->check_name(argv[1]);
    }
    if (!found) {
      std::fprintf(stderr, "kestrel-sim: error: unknown subcommand '%s' (known: %s)\n", argv[1], known.c_str());
      return 2;
    }
  }
  CLI11_PARSE(app, argc, argv);

  // What a PCL or sonar run must refuse rather than ignore (check_filter_fits).
  run.filter.filter_given = run_cmd->count("--filter") > 0;
  // --config and --set take the PCL or sonar tracker's keys on such a run.
  run.filter.radar_only_given =
      given_options(run_cmd, {"--scalar", "--qj", "--gate-d2", "--board-gate", "--robust-gate", "--imm",
                              "--asterix-out", "--sac", "--sic"});
  run.kind.given = given_options(
      run_cmd, {"--associator", "--manager", "--gate-tentative", "--compare-oracle", "--cutoff", "--order", "--persistence"});
  const auto is_radar = [](const std::string& scenario) {
    const std::optional<kestrel::hal::FrameKind> kind = kestrel::sim::scenario_kind(scenario);
    return !kind.has_value() || *kind == kestrel::hal::FrameKind::kRadar;
  };
  const bool run_is_radar = is_radar(run.scenario);
  const bool timing_is_radar = is_radar(timing.scenario);
  timing.filter.filter_given = timing_cmd->count("--filter") > 0;
  timing.filter.radar_only_given =
      given_options(timing_cmd, {"--scalar", "--qj", "--gate-d2", "--board-gate", "--robust-gate", "--imm"});
  sweep.filter.filter_given = sweep_cmd->count("--filter") > 0;
  sweep.filter.radar_only_given =
      given_options(sweep_cmd, {"--scalar", "--qj", "--gate-d2", "--board-gate", "--robust-gate", "--imm"});
  replay.filter.filter_given = replay_cmd->count("--filter") > 0;
  // --config and --set take the keys of the stream's kind (cmd_replay).
  replay.filter.radar_only_given = given_options(
      replay_cmd, {"--scalar", "--qj", "--gate-d2", "--board-gate", "--robust-gate", "--imm", "--asterix-out", "--sac",
                   "--sic", "--ungated", "--loss-threshold-m", "--first-scored-step"});

  try {
    // --scalar picks the filter's build on that scalar (cli/cmd_scalars.hpp).
    for (FilterChoice* f : {&run.filter, &replay.filter, &timing.filter, &sweep.filter}) {
      f->filter = filter_for_scalar(f->filter, f->scalar);
    }
    // --config, then --set, under the options of their own (cli/settings_options.cpp)
    // (sweep resolves its own: one of its --set is the swept parameter).
    // A PCL or sonar run or timing reads its tracker's own keys; replay
    // resolves its own once the stream's kind is known.
    for (FilterChoice* f : {&run.filter, &timing.filter}) {
      if ((f != &run.filter || run_is_radar) && (f != &timing.filter || timing_is_radar)) resolve_settings(*f, f->sets);
    }
    if (app.got_subcommand("list")) return cmd_list(list_settings);
    if (app.got_subcommand(generate)) return cmd_generate(gen);
    if (app.got_subcommand(run_cmd)) return cmd_run(run);
    if (app.got_subcommand(suite_cmd)) return cmd_suite(suite);
    if (app.got_subcommand(sweep_cmd)) return cmd_sweep(sweep);
    if (app.got_subcommand(replay_cmd)) return cmd_replay(replay);
    if (app.got_subcommand(timing_cmd)) return cmd_timing(timing);
    if (app.got_subcommand(montecarlo_cmd)) return cmd_montecarlo(montecarlo);
    if (app.got_subcommand(merge_cmd)) return cmd_merge(merge);
    if (app.got_subcommand(r2aekf_cmd)) return cmd_r2aekf(r2aekf);
    if (app.got_subcommand(sonar_study_cmd)) return cmd_sonar_study(sonar_study);
    if (app.got_subcommand(scalars_cmd)) return cmd_scalars(scalars);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kestrel-sim: error: %s\n", e.what());
    return 1;
  }
  return 2;
}
