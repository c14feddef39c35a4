// SPDX-License-Identifier: Apache-2.0
// --config and --set of the commands that run a filter or tracker (cli/commands.hpp).
#include <vector>

#include "cli/commands.hpp"
#include "filters/settings.hpp"

namespace kestrel::sim::cli {

void resolve_settings(FilterChoice& f, const std::vector<std::string>& sets) {
  apply_filter_settings(f, read_settings(f.config, sets));
}

void apply_filter_settings(FilterChoice& f, const std::vector<Setting>& settings) {
  if (settings.empty()) return;
  for (const Setting& s : settings) f.board_gate_set = f.board_gate_set || s.key == "board_gate";
  // CLI11 has already written the flags into f.options: start again from
  // the defaults, apply the settings, then lay the flags given over them.
  const FilterOptions flags = f.options;
  FilterOptions o;
  apply_settings(settings, o);
  if (flags.qj.has_value()) o.qj = flags.qj;
  if (flags.confirmed_gate_d2.has_value()) o.confirmed_gate_d2 = flags.confirmed_gate_d2;
  if (flags.board_gate) o.board_gate = true;
  if (flags.robust_gate_factor.has_value()) o.robust_gate_factor = flags.robust_gate_factor;
  o.imm.insert(o.imm.end(), flags.imm.begin(), flags.imm.end());
  f.options = o;
}

std::vector<Setting> read_settings(const std::string& config, const std::vector<std::string>& sets) {
  std::vector<Setting> settings;
  if (!config.empty()) settings = read_config_file(config);
  for (const std::string& s : sets) settings.push_back(parse_setting(s, "--set"));
  return settings;
}

}  // namespace kestrel::sim::cli
