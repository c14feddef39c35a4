// SPDX-License-Identifier: Apache-2.0
#include "cli/cmd_montecarlo.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "campaigns/mc001.hpp"

namespace kestrel::sim::cli {

namespace {

void parse_shard(const std::string& s, unsigned& k, unsigned& n) {
  const auto slash = s.find('/');
  if (slash == std::string::npos) throw std::invalid_argument("--shard must be K/N, e.g. 1/2");
  try {
    k = static_cast<unsigned>(std::stoul(s.substr(0, slash)));
    n = static_cast<unsigned>(std::stoul(s.substr(slash + 1)));
  } catch (const std::exception&) {
    throw std::invalid_argument("--shard must be K/N, e.g. 1/2");
  }
}

void finish(const std::filesystem::path& dir, const mc001::Records& records, bool plots) {
  const mc001::Summary s = mc001::summarise(records);
  mc001::write_tables(dir, s);
  mc001::print_summary(s);
  const bool plotted = plots && mc001::plot(dir);
  std::printf("wrote %s/{mc001_runs.bin, mc001_mse.csv, mc001_table.md, mc001_timing.csv%s}\n", dir.c_str(),
              plotted ? ", mc001_mse.png, mc001_time.png" : "");
}

}  // namespace

void add_montecarlo_commands(CLI::App& app, MonteCarloOptions& o, MergeOptions& m, CLI::App*& mc_cmd,
                             CLI::App*& merge_cmd) {
  mc_cmd = app.add_subcommand("montecarlo", "Monte Carlo campaign over a grid of cells and filters (mc001)");
  mc_cmd->add_option("--campaign", o.campaign, "Campaign (mc001: paper 001's noise grid, docs/scenarios.md)")
      ->capture_default_str();
  mc_cmd->add_option("--runs,-n", o.runs, "Runs per cell (seeds 0..runs-1)")->capture_default_str();
  mc_cmd->add_option("--jobs,-j,--threads", o.threads, "Worker threads (default: every core; results do not depend on it; --threads is the old name)");
  mc_cmd->add_option("--shard", o.shard, "Run only shard K of N (1-based, e.g. 2/8); join the outputs with merge");
  mc_cmd->add_option("--out,-o", o.out, "Output directory (default results/mc001, a shard results/mc001/shard-K-of-N)");
  mc_cmd->add_flag("!--no-plots", o.plots, "Do not run the plot script");
  mc_cmd->add_flag("!--no-progress", o.progress, "No progress line on stderr");

  merge_cmd = app.add_subcommand("merge", "Join the outputs of montecarlo --shard runs into one table");
  merge_cmd->add_option("dirs", m.dirs, "Shard output directories (each holds mc001_runs.bin)")->required();
  merge_cmd->add_option("--out,-o", m.out, "Output directory")->capture_default_str();
  merge_cmd->add_flag("!--no-plots", m.plots, "Do not run the plot script");
}

int cmd_montecarlo(const MonteCarloOptions& o) {
  if (o.campaign != "mc001") throw std::invalid_argument("unknown campaign '" + o.campaign + "' (known: mc001)");
  if (o.runs == 0) throw std::invalid_argument("--runs must be at least 1");
  mc001::CampaignParams config;
  config.total_runs = o.runs;
  config.run_begin = 0;
  config.run_end = o.runs;
  config.threads = o.threads != 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  config.progress = o.progress;
  std::filesystem::path dir = o.out.empty() ? std::filesystem::path("results") / "mc001" : std::filesystem::path(o.out);
  unsigned k = 0, n = 0;
  if (!o.shard.empty()) {
    parse_shard(o.shard, k, n);
    mc001::shard_range(o.runs, k, n, config.run_begin, config.run_end);
    if (o.out.empty()) dir /= "shard-" + std::to_string(k) + "-of-" + std::to_string(n);
  }
  const mc001::Records records = mc001::run_campaign(config);
  std::filesystem::create_directories(dir);
  mc001::write_records(dir / "mc001_runs.bin", records);
  if (!o.shard.empty() && n > 1) {
    std::printf("mc001 shard %u/%u: runs %llu..%llu of %llu, %u thread%s; wrote %s/mc001_runs.bin "
                "(kestrel-sim merge DIR... makes the table)\n",
                k, n, static_cast<unsigned long long>(config.run_begin),
                static_cast<unsigned long long>(config.run_end - 1), static_cast<unsigned long long>(o.runs),
                config.threads, config.threads == 1 ? "" : "s", dir.c_str());
    return 0;
  }
  finish(dir, records, o.plots);
  return 0;
}

int cmd_merge(const MergeOptions& m) {
  std::vector<mc001::Records> shards;
  for (const std::string& d : m.dirs) shards.push_back(mc001::read_records(std::filesystem::path(d) / "mc001_runs.bin"));
  const mc001::Records all = mc001::merge(shards);
  const std::filesystem::path dir(m.out);
  std::filesystem::create_directories(dir);
  mc001::write_records(dir / "mc001_runs.bin", all);
  std::printf("merged %zu shard%s: %llu runs per cell\n", shards.size(), shards.size() == 1 ? "" : "s",
              static_cast<unsigned long long>(all.total_runs));
  finish(dir, all, m.plots);
  return 0;
}

}  // namespace kestrel::sim::cli
