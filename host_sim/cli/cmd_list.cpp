// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim list`: the registered scenarios and filters; with
// --settings, the parameter keys of --set and --config.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "filters/filter_registry.hpp"
#include "filters/sensor_settings.hpp"
#include "filters/settings.hpp"
#include "scenarios/registry.hpp"
#include "scenarios/pcl002.hpp"
#include "scenarios/sensor_kind.hpp"
#include "scenarios/uw003.hpp"

namespace kestrel::sim::cli {

int cmd_list(bool settings) {
  if (settings) {
    std::printf("keys of --set KEY=VALUE and --config FILE (radar filters; docs/parameters.md):\n");
    std::printf("  %-25s %-34s %-28s %s\n", "key", "default", "range", "meaning");
    for (const SettingInfo& i : setting_table()) {
      std::printf("  %-25s %-34s %-28s %s\n", i.key.c_str(), i.default_text.c_str(), i.range.c_str(),
                  i.meaning.c_str());
    }
    const struct {
      const char* title;
      std::vector<SettingInfo> table;
    } others[] = {{"the PCL tracker (run -s pcl002|pcl002-hard, replay of a PCL stream)", pcl_setting_table()},
                  {"the sonar tracker (run -s uw003..., sonar-study, replay of a sonar stream)", sonar_setting_table()}};
    for (const auto& t : others) {
      std::printf("keys of --set KEY=VALUE and --config FILE for %s:\n", t.title);
      for (const SettingInfo& i : t.table) {
        std::printf("  %-33s %-34s %-30s %s\n", i.key.c_str(), i.default_text.c_str(), i.range.c_str(),
                    i.meaning.c_str());
      }
    }
    return 0;
  }
  // Which commands take each kind: run and replay dispatch on it
  // (scenarios/sensor_kind.hpp); timing, sweep and suite's radar part are radar only.
  std::printf("radar scenarios (run, timing, sweep, generate, replay of their streams; every radar filter below):\n");
  for (const ScenarioEntry& e : scenario_registry()) {
    const auto s = e.make();
    const ScenarioInfo& i = s->info();
    std::printf("  %-6s %s (L = %g m)\n", std::string(e.name).c_str(), i.description.c_str(), i.loss_threshold_m);
  }
  std::printf("radar filters (run, replay of radar streams, plot CSVs and CAT048, timing, suite):\n");
  for (const FilterEntry& f : filter_registry()) {
    std::printf("  %-13s %s\n", std::string(f.name).c_str(), std::string(f.description).c_str());
  }
  std::printf("PCL scenarios (run, generate; replay --stream of their streams, --scenario picks the sensor; "
              "timing):\n ");
  for (const std::string& n : pcl_scenario_names()) std::printf(" %s", n.c_str());
  std::printf("\n  filter %s: the PCL tracker (keys: list --settings; run: --associator nn|gnn|pda, "
              "--manager m-of-n|score, --gate-tentative)\n",
              std::string(kPclFilterName).c_str());
  std::printf("sonar scenarios (run, generate; replay --stream of their streams, --scenario picks the "
              "installation; timing):\n ");
  for (const std::string& n : sonar_scenario_names()) std::printf(" %s", n.c_str());
  std::printf("\n  filter %s: the sonar tracker (keys: list --settings; sonar-study: the gate study)\n",
              std::string(kSonarFilterName).c_str());
  std::printf("multi-target radar scenarios (crossing, raid, formation-split above): run with ekf-ca or imm, "
              "scored with OSPA, GOSPA, swaps, false tracks; run: --associator nn|gnn|oracle, "
              "--gate-tentative, --compare-oracle, --cutoff, --order, --persistence; generate writes every target's "
              "truth, which replay --truth scores the same way");
  std::printf("\ncampaigns (montecarlo): mc001, paper 001's noise grid with EKF, UKF, CDKF, SR-UKF, SR-CDKF, "
              "CRPF-100/300/500\n");
  return 0;
}

}  // namespace kestrel::sim::cli
