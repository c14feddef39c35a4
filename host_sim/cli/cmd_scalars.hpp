// SPDX-License-Identifier: Apache-2.0
// The scalar choice of kestrel-sim (docs/fixed-point.md):
//   - `--scalar double|float|q31_32|q23_40` on run, replay and timing picks
//     the registry entry of the chosen filter built on that scalar
//     ("ekf-ca" + q31_32 -> "ekf-ca-q31_32");
//   - `kestrel-sim scalars`: the comparison table. Every scalar runs the same
//     seeded streams of one scenario; per scalar the mean RMSE, the largest
//     relative RMSE difference to double, the largest position difference to
//     the double filter's tracks (matched by track id, every frame), the
//     frames whose report set differs from double's, the fixed-point
//     saturation count and the median step time.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "filters/filter_registry.hpp"

namespace CLI {
class App;
}

namespace kestrel::sim::cli {

/// The scalars a filter may be built on, in table order.
inline constexpr std::string_view kScalarNames[] = {"double", "float", "q31_32", "q23_40"};

/// Add `--scalar` to `cmd`, stored in `scalar` (empty when not given).
void add_scalar_option(CLI::App* cmd, std::string& scalar);

/// The registry name of `filter` built on `scalar`: its base name (without
/// -f32, -q31_32 or -q23_40) plus the scalar's suffix (none for double).
/// An empty scalar returns `filter` unchanged. Throws std::invalid_argument
/// when the filter has no build on that scalar.
std::string filter_for_scalar(std::string_view filter, std::string_view scalar);

struct ScalarsOptions {
  std::string scenario;
  std::string filter = "ekf-ca";  ///< Any scalar variant of it names the same family.
  FilterOptions options;          ///< --qj, --gate-d2.
  double budget_us = 1000.0;
  std::size_t runs = 20;
  std::uint64_t seed = 0;
};

/// Register the `scalars` subcommand on `app`.
CLI::App* add_scalars_command(CLI::App& app, ScalarsOptions& options);

int cmd_scalars(const ScalarsOptions& options);

}  // namespace kestrel::sim::cli
