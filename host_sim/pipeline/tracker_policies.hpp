// SPDX-License-Identifier: Apache-2.0
// The tracker's associator and track manager as the command line names
// them. The core composes them at compile time (tracking/tracker.hpp); a
// run picks one of the instantiated compositions here, once per run, never
// inside a step.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>

namespace kestrel::sim {

enum class AssociatorChoice { kNearestNeighbour, kGlobalNearestNeighbour, kPda };
enum class ManagerChoice { kMOfN, kScore };

struct TrackerPolicies {
  AssociatorChoice associator = AssociatorChoice::kNearestNeighbour;
  ManagerChoice manager = ManagerChoice::kMOfN;
};

inline constexpr std::array<std::pair<std::string_view, AssociatorChoice>, 3> kAssociatorNames{{
    {"nn", AssociatorChoice::kNearestNeighbour},
    {"gnn", AssociatorChoice::kGlobalNearestNeighbour},
    {"pda", AssociatorChoice::kPda},
}};
inline constexpr std::array<std::pair<std::string_view, ManagerChoice>, 2> kManagerNames{{
    {"m-of-n", ManagerChoice::kMOfN},
    {"score", ManagerChoice::kScore},
}};

/// By name; throws std::invalid_argument listing the known names.
template <class Choice, std::size_t kN>
Choice policy_by_name(const std::array<std::pair<std::string_view, Choice>, kN>& names, const std::string& name,
                      const char* what) {
  std::string known;
  for (const auto& [n, c] : names) {
    if (n == name) return c;
    known += (known.empty() ? "" : ", ") + std::string(n);
  }
  throw std::invalid_argument(std::string("unknown ") + what + " '" + name + "' (known: " + known + ")");
}

template <class Choice, std::size_t kN>
std::string_view policy_name(const std::array<std::pair<std::string_view, Choice>, kN>& names, Choice c) {
  for (const auto& [n, v] : names) {
    if (v == c) return n;
  }
  return "?";
}

}  // namespace kestrel::sim
