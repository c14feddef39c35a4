// SPDX-License-Identifier: Apache-2.0
// The scenario registry: every scenario kestrel-sim knows, by name. A new
// scenario lives in its own file with a make_*() function and adds one line
// to the table in registry.cpp.
#pragma once

#include <memory>
#include <span>
#include <string_view>

#include "scenarios/scenario.hpp"

namespace kestrel::sim {

struct ScenarioEntry {
  std::string_view name;                  ///< Lower-case key ("s1").
  std::unique_ptr<Scenario> (*make)();    ///< Builds the scenario (truth computed here).
};

/// Every registered scenario, in listing order.
std::span<const ScenarioEntry> scenario_registry();

/// The scenario called `name` (case-insensitive). Throws std::invalid_argument
/// listing the known names when there is none.
std::unique_ptr<Scenario> make_scenario(std::string_view name);

}  // namespace kestrel::sim
