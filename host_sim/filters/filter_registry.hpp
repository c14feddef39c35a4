// SPDX-License-Identifier: Apache-2.0
// The filter registry: every tracker configuration kestrel-sim can run, by
// name. Each entry builds its tracker (a concrete core Tracker type on the
// host board) and runs it over a stream with pipeline/stream_run.hpp; the
// type is erased only at this per-run boundary, never inside a step. A new
// filter (R2-AEKF, UKF, ...) adds one file with its run function and one
// line to the table in filter_registry.cpp.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/hal/frame.hpp"
#include "kestrel/scalar/scalar_traits.hpp"
#include "pipeline/stream_run_result.hpp"

namespace kestrel::sim {

/// Command-line overrides of a filter's defaults (unset = the filter's default).
struct FilterOptions {
  std::optional<double> qj;  ///< White-jerk PSD of CA models, m^2/s^5.
  /// Gate of confirmed tracks in d2 = nu^T S^-1 nu units. Unset: ungated,
  /// as the papers score filters (one target, no clutter: docs/scenarios.md); a
  /// gate there only turns filter lag into a dropped and restarted track.
  std::optional<double> confirmed_gate_d2;
  /// Without confirmed_gate_d2: gate confirmed tracks as a board does (the
  /// chi-square quantile of TrackerConfig::gate_confirmed) instead of not
  /// at all. `replay` sets it: recorded data has outliers, and an ungated
  /// track follows them.
  bool board_gate = false;
  /// With the board's gate: TrackerConfig::robust_gate_factor (0 turns the
  /// robust gate off). Unset: the radar tracker's default.
  std::optional<double> robust_gate_factor;
  /// Parameter overrides of the IMM filters, KEY=VALUE each
  /// (filters/imm_filters.hpp lists the keys); other filters ignore them.
  std::vector<std::string> imm;
  /// Radar tracker parameters by key (filters/settings.hpp), checked when
  /// set; unset keys keep RadarTrackerParams' defaults.
  std::map<std::string, double> radar;
};

/// TrackerConfig::gate_confirmed_threshold for these options: the d2
/// given, 0 (the board's chi-square gate), or the largest value (ungated).
template <class Scalar>
Scalar confirmed_gate_threshold(const FilterOptions& options) {
  using T = ScalarTraits<Scalar>;
  if (options.confirmed_gate_d2.has_value()) return T::from_double(*options.confirmed_gate_d2);
  if (options.board_gate) return Scalar{};
  return T::max_value();
}

/// The gate options into a tracker configuration built from the board's
/// defaults: the confirmed gate's threshold and, if given, the robust
/// gate's factor (which acts with the board's gate only).
template <class Scalar, class Config>
void apply_gate_options(const FilterOptions& options, Config& config) {
  config.gate_confirmed_threshold = confirmed_gate_threshold<Scalar>(options);
  if (options.robust_gate_factor.has_value()) {
    config.robust_gate_factor = ScalarTraits<Scalar>::from_double(*options.robust_gate_factor);
  }
}

/// The gate in a filter's label: ", gate d2 13.8", ", board gate (robust x25)"
/// or "".
std::string gate_label(const FilterOptions& options);

/// The gate parameters of summary.json: confirmed_gate_d2 (infinity when
/// ungated or when the board's gate applies), board_gate (0 or 1) and
/// robust_gate_factor (0 unless the board's gate applies).
void add_gate_parameters(const FilterOptions& options, std::map<std::string, double>& parameters);

/// The parameters a run actually used, for summary.json and the table.
struct FilterSetup {
  std::string label;                         ///< e.g. "EKF-CA (double), qj 1.6".
  std::map<std::string, double> parameters;  ///< Numeric parameters by name.
};

struct FilterEntry {
  std::string_view name;         ///< Registry key ("ekf-ca").
  std::string_view description;  ///< One line for `kestrel-sim list`.
  hal::FrameKind kind;           ///< Frames it consumes.
  /// Parameters the options resolve to.
  FilterSetup (*setup)(const FilterOptions& options);
  /// Build a fresh tracker and run it over `stream` (a wire stream, or a
  /// CAT048 recording; optionally also writing CAT062: StreamInput).
  StreamRunResult (*run)(StreamInput stream, const FilterOptions& options,
                         std::uint64_t budget_ns);
};

/// Every registered filter, in listing order.
std::span<const FilterEntry> filter_registry();

/// The filter called `name` (case-insensitive). Throws std::invalid_argument
/// listing the known names when there is none.
const FilterEntry& find_filter(std::string_view name);

}  // namespace kestrel::sim
