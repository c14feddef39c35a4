// SPDX-License-Identifier: Apache-2.0
#include "scenarios/registry.hpp"

#include <cctype>
#include <stdexcept>
#include <string>

#include "scenarios/multi_target.hpp"
#include "scenarios/s1_zigzag.hpp"
#include "scenarios/s2_scurve.hpp"

namespace kestrel::sim {

namespace {
// One line per scenario.
const ScenarioEntry kScenarios[] = {
    {"s1", &make_s1},
    {"s2", &make_s2},
    {"s1n", &make_s1n},
    {"s2n", &make_s2n},
    {"s1rr", &make_s1rr},
    {"s2rr", &make_s2rr},
    {"s1-outliers", &make_s1_outliers},
    {"s2-outliers", &make_s2_outliers},
    {"s1-burst", &make_s1_burst},
    {"s2-burst", &make_s2_burst},
    {"crossing", &make_crossing},
    {"raid", &make_raid},
    {"formation-split", &make_formation_split},
};
}  // namespace

std::span<const ScenarioEntry> scenario_registry() { return kScenarios; }

std::unique_ptr<Scenario> make_scenario(std::string_view name) {
  std::string key(name);
  for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string known;
  for (const ScenarioEntry& e : kScenarios) {
    if (e.name == key) return e.make();
    known += known.empty() ? "" : ", ";
    known += e.name;
  }
  throw std::invalid_argument("unknown scenario '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace kestrel::sim
