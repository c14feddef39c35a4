// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim list`: the registered scenarios and filters.
#include <cstdio>
#include <string>

#include "cli/commands.hpp"
#include "filters/filter_registry.hpp"
#include "scenarios/registry.hpp"

namespace kestrel::sim::cli {

int cmd_list() {
  std::printf("scenarios:\n");
  for (const ScenarioEntry& e : scenario_registry()) {
    const auto s = e.make();
    const ScenarioInfo& i = s->info();
    std::printf("  %-6s %s (L = %g m)\n", std::string(e.name).c_str(), i.description.c_str(), i.loss_threshold_m);
  }
  std::printf("filters:\n");
  for (const FilterEntry& f : filter_registry()) {
    std::printf("  %-11s %s\n", std::string(f.name).c_str(), std::string(f.description).c_str());
  }
  return 0;
}

}  // namespace kestrel::sim::cli
