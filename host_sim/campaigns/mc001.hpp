// SPDX-License-Identifier: Apache-2.0
// MC-001 (paper 001 section 4; docs/scenarios.md, "MC-001"): the 3 x 3 grid
// of bearing and range noise, 100 steps of a CV-2D target seen by a polar
// radar, every filter of paper 001 tuned with the middle values plus an EKF
// tuned to each cell's true noise (the oracle); position MSE per cell and
// filter with its 95 % interval, the divergence count and the time per step.
// The filters are driven directly, not through the HAL and the Tracker,
// because MC-001 starts each filter at truth + N(0, P0). A run depends only
// on its seeds (data seeded with r, each CRPF with a SplitMix64 hash of cell,
// run and filter) and the summary reduces records in (cell, run, filter)
// order, so any --jobs and merged shards give the same table bit for bit;
// only the measured timing differs (docs/filters.md, "MC-001 campaign").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace kestrel::sim::mc001 {

inline constexpr int kSteps = 100;           ///< Measurements k = 1..100, T = 1 s.
inline constexpr double kDivergedM = 100.0;  ///< docs/scenarios.md: final error over 100 m.
inline constexpr std::size_t kCells = 9;

/// One cell of the grid: the true noise of the data.
struct Cell {
  double bearing_sigma_deg;  ///< sb, degrees.
  double range_sigma_m;      ///< sr, metres.
  double accel_sigma_mps2;   ///< sa of the truth, tied to the range level (docs/scenarios.md).
};

/// The grid, bearing-major: cells 0-2 have sb = 0.01 deg, 3-5 0.1 deg, 6-8 1 deg;
/// within each, sr = 0.1, 1, 10 m with sa = 0.01, 0.1, 1 m/s^2.
const std::array<Cell, kCells>& grid();

/// The filters, in table order.
enum class FilterId : std::uint8_t { kEkf, kUkf, kCdkf, kSrUkf, kSrCdkf, kCrpf100, kCrpf300, kCrpf500, kOracleEkf };
inline constexpr std::size_t kFilters = 9;
std::string_view filter_name(std::size_t f);

/// One filter on one run of one cell.
struct Record {
  double mse_m2 = 0.0;         ///< Mean over k = 1..100 of |p_hat_k - p_k|^2.
  double final_error_m = 0.0;  ///< |p_hat_100 - p_100|.
  double step_ns = 0.0;        ///< Wall time of the 100 predict + update calls, ns.
  std::uint32_t failures = 0;  ///< predict/update calls that returned a status other than kOk.
  std::uint32_t reserved = 0;
};

/// The records of runs [run_begin, run_end) of every cell, of a campaign of
/// total_runs runs per cell. Indexing: ((cell * (run_end - run_begin)) + run - run_begin) * kFilters + filter.
struct Records {
  std::uint64_t total_runs = 0;
  std::uint64_t run_begin = 0;
  std::uint64_t run_end = 0;
  unsigned threads = 1;  ///< Threads that measured the times (for the timing note).
  std::vector<Record> records;

  std::uint64_t runs() const { return run_end - run_begin; }
  Record& at(std::size_t cell, std::uint64_t run, std::size_t filter);
  const Record& at(std::size_t cell, std::uint64_t run, std::size_t filter) const;
};

struct CampaignParams {
  std::uint64_t total_runs = 3000;
  std::uint64_t run_begin = 0;  ///< This shard's runs: [run_begin, run_end).
  std::uint64_t run_end = 3000;
  unsigned threads = 1;
  bool progress = true;  ///< Progress line on stderr.
};

/// Runs [run_begin, run_end) of every cell with every filter.
Records run_campaign(const CampaignParams& config);

/// One run of one cell, all filters (exposed for tests).
std::array<Record, kFilters> run_one(std::size_t cell, std::uint64_t run);

/// Shard K of N (1-based) of total runs: [floor((K-1) R / N), floor(K R / N)).
void shard_range(std::uint64_t total_runs, unsigned k, unsigned n, std::uint64_t& begin, std::uint64_t& end);

/// Binary record file (documented in docs/filters.md): the header then the
/// records in index order, little-endian as on the host.
void write_records(const std::filesystem::path& path, const Records& r);
Records read_records(const std::filesystem::path& path);

/// Joins shards into one set of records covering [0, total_runs): every run
/// exactly once, same total. Throws std::runtime_error otherwise.
Records merge(const std::vector<Records>& shards);

/// Mean and 95 % interval of a cell x filter MSE, divergences, failures.
struct CellSummary {
  double mse_mean = 0.0;
  double ci95_low = 0.0;
  double ci95_high = 0.0;
  std::uint64_t runs = 0;
  std::uint64_t diverged = 0;
  std::uint64_t failures = 0;
  double final_error_mean_m = 0.0;
};
struct Summary {
  std::array<std::array<CellSummary, kFilters>, kCells> cells{};
  std::array<double, kFilters> ns_per_step{};  ///< Mean over every step of every cell.
  std::uint64_t total_runs = 0;
  unsigned threads = 1;
};

/// Requires complete records (run_begin = 0, run_end = total_runs).
Summary summarise(const Records& r);

/// mc001_mse.csv, mc001_table.md (accuracy only: identical for any threads
/// or shards), mc001_timing.csv (measured).
void write_tables(const std::filesystem::path& dir, const Summary& s);

/// Print the MSE table and the timing to stdout.
void print_summary(const Summary& s);

/// Runs plots/mc001_plots.py (best effort): mc001_mse.png, mc001_time.png.
bool plot(const std::filesystem::path& dir);

}  // namespace kestrel::sim::mc001
