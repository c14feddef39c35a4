// SPDX-License-Identifier: Apache-2.0
// The kestrel-sim subcommands. main.cpp parses the command line (CLI11)
// into these option structs and calls the matching function; each returns
// the process exit status. Errors in input files throw (std::runtime_error,
// CsvError with its line number): main prints them and exits with 1.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "filters/filter_registry.hpp"
#include "filters/settings.hpp"
#include "scenarios/scenario.hpp"

namespace kestrel::sim::cli {

/// Options every command that runs a filter shares.
struct FilterChoice {
  std::string filter = "ekf-ca";
  std::string scalar;              ///< --scalar (cli/cmd_scalars.hpp); empty: as `filter` names it.
  FilterOptions options;           ///< --qj, --gate-d2 overrides.
  std::string config;              ///< --config: JSON file of settings (filters/settings.hpp).
  std::vector<std::string> sets;   ///< --set KEY=VALUE, in order.
  /// board_gate came from --set or --config (replay's default then yields).
  bool board_gate_set = false;
  double budget_us = 1000.0;       ///< Step overrun threshold, us.
  bool filter_given = false;       ///< -f was on the command line (not the default).
  /// Options given that only the radar filters take (--qj, --set, ...):
  /// for a PCL or sonar run they are an error, never ignored.
  std::vector<std::string> radar_only_given;
};

/// Throws std::invalid_argument naming the filters of `kind` when -f names
/// one of another kind (`what` says whose kind: "scenario 'pcl002'", a
/// stream file), and naming `radar_only_given` when `kind` is not radar.
void check_filter_fits(const FilterChoice& f, hal::FrameKind kind, const std::string& what);

/// Folds --config and then `sets` into f.options, under the options that
/// have their own flag (--qj, --gate-d2, --board-gate, --robust-gate, --imm):
/// a flag wins over --set, which wins over --config. Throws
/// std::invalid_argument or std::runtime_error for a bad file, key or value.
void resolve_settings(FilterChoice& f, const std::vector<std::string>& sets);

/// resolve_settings() of settings already read (replay reads them before
/// it knows the stream's kind, whose keys they must be).
void apply_filter_settings(FilterChoice& f, const std::vector<Setting>& settings);

/// The settings of --config FILE (if not empty) and then of each --set, in
/// order (filters/settings.hpp). Throws as read_config_file and parse_setting.
std::vector<Setting> read_settings(const std::string& config, const std::vector<std::string>& sets);

/// The registries; with `settings`, the parameter keys instead.
int cmd_list(bool settings);

struct GenerateOptions {
  std::string scenario;
  std::uint64_t seed = 0;
  std::string out;  ///< Stream file; FILE.truth.csv and FILE.plots.csv beside it.
  bool asterix = false;     ///< --asterix: also FILE.ast, the plots as CAT048 data blocks.
  unsigned asterix_sac = 0; ///< --sac: I048/010 SAC of those blocks (SIC = the plot's sensor_id).
};

/// --asterix-out of `run` and `replay`: every published report also as a
/// CAT062 data block (one record per block) in this file.
struct Cat062Output {
  std::string path;   ///< Empty: not written.
  unsigned sac = 0;   ///< I062/010 SAC.
  unsigned sic = 1;   ///< I062/010 SIC.
};
int cmd_generate(const GenerateOptions& o);

/// `run`'s options for some scenario kinds only; given for a scenario they
/// do not apply to, they are an error.
struct KindOptions {
  std::string associator;  ///< PCL: nn, gnn or pda (nn); several radar targets: nn, gnn or oracle (gnn).
  std::string manager;     ///< PCL: m-of-n or score (m-of-n).
  std::optional<double> gate_tentative;  ///< PCL, several targets: 0.90, 0.95, 0.99, 0.995 or 0.999.
  bool compare_oracle = false;           ///< Several targets: the oracle associator on the same seeds too.
  double cutoff_m = 500.0;               ///< Several targets: OSPA/GOSPA cut-off c.
  double order = 2.0;                    ///< Several targets: OSPA/GOSPA order p.
  std::size_t persistence_steps = 3;     ///< Several targets: steps a swap must hold.
  std::vector<std::string> given;        ///< Which of these the command line gave (as spelt there).
};

struct RunOptions {
  std::string scenario;
  FilterChoice filter;
  KindOptions kind;
  std::size_t runs = 20;
  std::uint64_t seed = 0;   ///< Seed of run 0; run i uses seed + i.
  unsigned jobs = 1;
  std::string out;          ///< Default results/<scenario>.
  bool plots = true;
  Cat062Output asterix_out; ///< CAT062 of run 0's reports (the run of the track CSV).
};
int cmd_run(const RunOptions& o);

/// `run` of a PCL scenario: the PCL tracker's Monte Carlo with run's
/// scenario, runs, seed, jobs, out (default results/<scenario>), plots,
/// budget, --config/--set (the keys of filters/sensor_settings.hpp),
/// --associator, --manager and --gate-tentative. cli/run_pcl.cpp.
int run_pcl(const RunOptions& o);

/// `run` of a sonar scenario: the sonar tracker's Monte Carlo with run's
/// scenario, runs, seed, jobs, out, plots, budget and --config/--set.
/// cli/run_sonar.cpp.
int run_sonar(const RunOptions& o);

/// `sonar-study`: every sonar scenario with the paper's gate (k = 2), k = 3
/// and no gate, over run's runs, seed, jobs, out (default
/// results/sonar_study), plots, budget and --config/--set; writes
/// sonar_study.md / .json and one folder per row. cli/run_sonar.cpp.
int cmd_sonar_study(const RunOptions& o);

/// `run` of a PCL or sonar scenario (`kind`): run_pcl or run_sonar, after
/// refusing the options of KindOptions the kind does not take. Suite's pcl
/// and sonar parts and sweep come through it too.
int run_sensor_scenario(const RunOptions& o, hal::FrameKind kind);

/// `run` of a multi-target scenario (crossing, raid, formation-split): the
/// multi-target tracker's Monte Carlo with run's scenario, runs, seed, jobs,
/// out (default results/<scenario>-multi), plots, budget, filter (ekf-ca or
/// imm), resolved filter options and KindOptions. cli/run_multi.cpp.
int run_multi_target_scenario(const RunOptions& o);

/// "wrote N CAT062 blocks ..." for --asterix-out (cmd_run.cpp).
void print_cat062_written(const std::string& path, const StreamRunResult& r);

/// The main job (`bash run.sh sim`): the four papers' systems in one
/// report, results/report.md (cli/cmd_suite.cpp).
struct SuiteOptions {
  /// Parts to run: radar (S1/S2 filters, paper 000), mc001 (paper 001's
  /// filter comparison), pcl (paper 002), sonar (paper 003).
  std::vector<std::string> parts{"radar", "mc001", "pcl", "sonar"};
  std::vector<std::string> scenarios{"s1", "s2"};  ///< Radar scenarios.
  /// Radar filters, each NAME or NAME:qj=X (a tuned EKF-CA beside the
  /// paper's qj 1.6; the IMM, Kestrel's own best).
  std::vector<std::string> filters{"ekf-ca", "ekf-ca:qj=160", "r2aekf", "imm"};
  FilterOptions options;          ///< --qj, --gate-d2 for entries without their own.
  double budget_us = 1000.0;
  std::size_t runs = 50;          ///< Runs per radar entry, PCL and UW.
  std::uint64_t mc_runs = 100;    ///< Runs per MC-001 cell.
  std::uint64_t seed = 0;
  unsigned jobs = 0;              ///< 0: every core.
  std::string out = "results";
  bool plots = true;
};
int cmd_suite(const SuiteOptions& o);

/// `sweep`: one scenario and filter over values of one parameter.
struct SweepOptions {
  std::string scenario;
  FilterChoice filter;      ///< Its `sets`: the swept KEY=V1,V2,... and fixed KEY=VALUEs.
  std::size_t runs = 20;
  std::uint64_t seed = 0;
  unsigned jobs = 1;
  std::string out;          ///< Default results/sweep-<scenario>-<filter>.
  bool plots = false;
};
int cmd_sweep(const SweepOptions& o);

struct ReplayOptions {
  std::string stream;       ///< Wire stream file, or
  std::string csv;          ///< radar plot CSV, or
  std::string asterix;      ///< ASTERIX CAT048 data blocks back to back (.ast).
  std::string truth;        ///< Optional truth CSV: enables scoring.
  FilterChoice filter;
  double loss_threshold_m = 300.0;
  std::size_t first_scored_step = 2;
  std::string out = "results/replay";
  /// --scenario: whose sensor parameters a PCL or sonar stream is run with
  /// (default pcl002 / uw003); a radar stream takes none. --config and --set
  /// (filter.config, filter.sets) are read with the keys of the stream's
  /// kind, in cmd_replay, not by resolve_settings().
  std::string scenario;
  bool plots = true;
  /// Score as the papers score filters: confirmed tracks ungated. The
  /// default gates them as a board does (FilterOptions::board_gate).
  bool ungated = false;
  Cat062Output asterix_out;
  /// --associator nn|gnn: a radar stream runs the multi-target tracker with
  /// this associator, scored when a truth is given, tracks only without.
  /// Empty: the multi-target tracker (GNN) only with the truth of several
  /// targets, else the filter's own single-target tracker.
  std::string associator;
};
/// `replay` of a radar stream by the multi-target tracker `run` uses for a
/// multi-target scenario (o.associator, GNN by default; the board's gate;
/// `filter` ekf-ca or imm with its resolved options) over `input`: against
/// the truth of several targets (`target` column, what `generate` writes
/// for such a scenario; or one target's) scored with multi's metrics at
/// each frame every target has a truth for, with the track CSV,
/// multi_steps.csv and a summary.json entry; with `targets` empty the track
/// CSV and the entry without metrics. cli/run_multi.cpp.
int replay_multi_target(const ReplayOptions& o, const FilterChoice& filter, StreamInput input,
                        const std::vector<std::vector<TruthSample>>& targets, const std::string& source);
/// replay's options given that a multi-target replay does not take.
std::vector<std::string> multi_target_replay_refuses(const ReplayOptions& o);

/// Exit status of `replay` when its input held no frames (a 0-byte stream,
/// a stream of which no frame decodes, a CSV with only its header): a
/// warning, not an error (exit 1), but not a run either, so not 0.
inline constexpr int kExitNoFrames = 3;
int cmd_replay(const ReplayOptions& o);

struct TimingOptions {
  std::string scenario;
  FilterChoice filter;
  std::size_t runs = 20;
  std::uint64_t seed = 0;
  std::string worst_case;  ///< --worst-case: a board's worst-case frame instead of a scenario.
};
int cmd_timing(const TimingOptions& o);
/// timing of a multi-target scenario: the step times (adapter + step, ns,
/// every stepped frame) of the tracker `run` uses for it (GNN,
/// kMultiMaxTracks tracks) over o.runs seeds, one job; `what` names it.
/// cli/run_multi.cpp.
std::vector<std::uint64_t> multi_target_step_times(const TimingOptions& o, std::string& what);
/// The worst-case frame of `board` (cortex-m4f, cortex-m7, cortex-m0plus,
/// riscv64-linux or host), adapter + step timed `reps` times per counted frame.
int cmd_timing_worst_case(const std::string& board, std::size_t reps);

}  // namespace kestrel::sim::cli
