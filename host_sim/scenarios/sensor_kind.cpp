// SPDX-License-Identifier: Apache-2.0
#include "scenarios/sensor_kind.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "filters/filter_registry.hpp"
#include "scenarios/pcl002.hpp"
#include "scenarios/registry.hpp"
#include "scenarios/uw003.hpp"

namespace kestrel::sim {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& ch : out) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return out;
}

bool contains(const std::vector<std::string>& names, const std::string& key) {
  return std::find(names.begin(), names.end(), key) != names.end();
}

}  // namespace

const char* sensor_kind_name(hal::FrameKind kind) {
  switch (kind) {
    case hal::FrameKind::kRadar: return "radar";
    case hal::FrameKind::kSonar: return "sonar";
    case hal::FrameKind::kPcl: return "PCL";
  }
  return "unknown";
}

std::vector<std::string> scenario_names_of_kind(hal::FrameKind kind) {
  switch (kind) {
    case hal::FrameKind::kPcl: return pcl_scenario_names();
    case hal::FrameKind::kSonar: return sonar_scenario_names();
    case hal::FrameKind::kRadar: break;
  }
  std::vector<std::string> names;
  for (const ScenarioEntry& e : scenario_registry()) names.emplace_back(e.name);
  return names;
}

std::optional<hal::FrameKind> scenario_kind(std::string_view name) {
  const std::string key = lower(name);
  for (const hal::FrameKind k : {hal::FrameKind::kRadar, hal::FrameKind::kPcl, hal::FrameKind::kSonar}) {
    if (contains(scenario_names_of_kind(k), key)) return k;
  }
  return std::nullopt;
}

std::vector<std::string> filters_for_kind(hal::FrameKind kind) {
  if (kind == hal::FrameKind::kPcl) return {std::string(kPclFilterName)};
  if (kind == hal::FrameKind::kSonar) return {std::string(kSonarFilterName)};
  std::vector<std::string> names;
  for (const FilterEntry& f : filter_registry()) {
    if (f.kind == kind) names.emplace_back(f.name);
  }
  return names;
}

std::optional<hal::FrameKind> filter_kind(std::string_view name) {
  const std::string key = lower(name);
  if (key == kPclFilterName) return hal::FrameKind::kPcl;
  if (key == kSonarFilterName) return hal::FrameKind::kSonar;
  for (const FilterEntry& f : filter_registry()) {
    if (key == f.name) return f.kind;
  }
  return std::nullopt;
}

std::string join_names(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::size_t FrameKindCounts::kinds() const {
  return static_cast<std::size_t>(radar > 0) + static_cast<std::size_t>(pcl > 0) +
         static_cast<std::size_t>(sonar > 0);
}

std::string FrameKindCounts::describe() const {
  std::string s;
  const auto add = [&s](std::size_t n, const char* what) {
    if (n == 0) return;
    s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  };
  add(radar, "radar");
  add(pcl, "PCL");
  add(sonar, "sonar");
  return s;
}

FrameKindCounts count_frame_kinds(const std::vector<MeasurementFrame>& frames) {
  FrameKindCounts c;
  for (const MeasurementFrame& f : frames) {
    if (std::isnan(f.t_s)) {
      ++c.undecoded;
      continue;
    }
    switch (f.kind) {
      case hal::FrameKind::kRadar: ++c.radar; break;
      case hal::FrameKind::kPcl: ++c.pcl; break;
      case hal::FrameKind::kSonar: ++c.sonar; break;
    }
  }
  return c;
}

}  // namespace kestrel::sim
