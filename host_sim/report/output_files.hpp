// SPDX-License-Identifier: Apache-2.0
// What every result file of kestrel-sim is written with: the output stream
// (10 significant digits), a CSV cell, the JSON of a number, an interval
// (NaN as null) or step times, a JSON file, and the text of a number or an interval in
// tables and printed lines.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "metrics/monte_carlo_stats.hpp"
#include "timing/step_timing.hpp"

namespace kestrel::sim {

/// A new (truncated) file printing doubles with 10 significant digits;
/// throws std::runtime_error naming `path` if it cannot be created.
std::ofstream open_out(const std::filesystem::path& path);

/// A number ("%.10g"), or an empty cell for NaN and infinities.
std::string csv_cell(double v);

/// The number, or null where it is not finite (JSON has no NaN).
nlohmann::json number_or_null(double v);

/// {mean, ci95_low, ci95_high, n}, non-finite bounds as null.
nlohmann::json interval_json(const MeanCi& m);

/// {min, median, p99, max, mean, steps, budget_ns, overruns}: the step_ns
/// object of every summary.json entry.
nlohmann::json step_ns_json(const StepTiming& t);

/// `j` indented by 2 and a newline; throws std::runtime_error naming `path`
/// if it cannot be created or written.
void write_json_file(const std::filesystem::path& path, const nlohmann::json& j);

/// `v` printed with the printf `format` (one double), "-" where it is not
/// finite.
std::string format_number(const char* format, double v);

/// "mean [ci95_low, ci95_high]", each printed as format_number does; "-"
/// without a finite mean.
std::string interval_text(const MeanCi& m, const char* format);

}  // namespace kestrel::sim
