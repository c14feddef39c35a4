// SPDX-License-Identifier: Apache-2.0
#include "campaigns/mc001.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "kestrel/filters/crpf.hpp"
#include "kestrel/filters/ekf.hpp"
#include "kestrel/filters/sigma_point_filter.hpp"
#include "kestrel/filters/sr_sigma_point_filter.hpp"
#include "kestrel/math/prng.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "metrics/monte_carlo_stats.hpp"
#include "pipeline/worker_pool.hpp"
#include "plots/plot_runner.hpp"

namespace kestrel::sim::mc001 {

namespace {

using Motion = ConstantVelocity2D<double>;
using Radar = PolarRadar<Motion>;
using State = Motion::State;
using Cov = Motion::Cov;
using Meas = Radar::Measurement;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kT = 1.0;

/// The middle values every filter but the oracle is tuned with (docs/scenarios.md).
constexpr Cell kTuning{0.1, 1.0, 0.1};

constexpr std::array<std::string_view, kFilters> kNames = {"EKF",      "UKF",      "CDKF",     "SR-UKF",    "SR-CDKF",
                                                           "CRPF-100", "CRPF-300", "CRPF-500", "EKF-oracle"};

/// Initial estimate spread, docs/scenarios.md: P0 = diag(50^2, 5^2, 50^2, 5^2).
const State kP0Sigma(50.0, 5.0, 50.0, 5.0);

struct RunData {
  State x0_hat;
  std::array<State, kSteps + 1> truth;
  std::array<Meas, kSteps> z;
};

/// Data of run `run` in `cell`: the draws come from one NormalGenerator
/// seeded with the run index, in a fixed order (initial error, then per
/// step the two accelerations and the two measurement noises).
RunData generate(const Cell& c, std::uint64_t run) {
  NormalGenerator<double> g(run);
  RunData d;
  d.truth[0] = State(1000.0, 10.0, 1000.0, 5.0);
  for (int i = 0; i < 4; ++i) d.x0_hat(i) = d.truth[0](i) + kP0Sigma(i) * g();
  const double sr = c.range_sigma_m;
  const double sb = c.bearing_sigma_deg * kDeg;
  for (int k = 1; k <= kSteps; ++k) {
    const double ax = c.accel_sigma_mps2 * g();
    const double ay = c.accel_sigma_mps2 * g();
    const State& p = d.truth[static_cast<std::size_t>(k - 1)];
    State& x = d.truth[static_cast<std::size_t>(k)];
    // DWNA: the acceleration is held over the step (docs/models.md, CV-2D).
    x(0) = p(0) + p(1) * kT + 0.5 * ax * kT * kT;
    x(1) = p(1) + ax * kT;
    x(2) = p(2) + p(3) * kT + 0.5 * ay * kT * kT;
    x(3) = p(3) + ay * kT;
    const double r = std::hypot(x(0), x(2)) + sr * g();
    const double b = std::atan2(x(2), x(0)) + sb * g();
    d.z[static_cast<std::size_t>(k - 1)] = Meas(r, wrap_angle(b));
  }
  return d;
}

Motion motion_for(const Cell& c) {
  Motion m;
  m.sa = c.accel_sigma_mps2;
  return m;
}

Radar radar_for(const Cell& c) {
  Radar r;
  r.sigma_range_m = c.range_sigma_m;
  r.sigma_bearing_rad = c.bearing_sigma_deg * kDeg;
  return r;
}

std::uint64_t crpf_seed(std::size_t cell, std::uint64_t run, std::size_t filter) {
  std::uint64_t x = (static_cast<std::uint64_t>(cell) << 48) ^ (run << 8) ^ static_cast<std::uint64_t>(filter) ^
                    0x4D43303031ull;  // "MC001"
  return splitmix64(x);
}

/// Runs one filter over one run's data; only the predict/update loop is timed.
template <class F>
Record run_filter(F& f, const RunData& d) {
  Record rec;
  const Cov P0 = kP0Sigma.array().square().matrix().asDiagonal();
  if (f.reset(d.x0_hat, P0) != Status::kOk) ++rec.failures;
  std::array<State, kSteps> est;
  std::uint32_t failures = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < static_cast<std::size_t>(kSteps); ++k) {
    if (f.predict(kT) != Status::kOk) ++failures;
    if (f.update(d.z[k]) != Status::kOk) ++failures;
    est[k] = f.x();
  }
  const auto t1 = std::chrono::steady_clock::now();
  rec.failures += failures;
  rec.step_ns = std::chrono::duration<double, std::nano>(t1 - t0).count() / kSteps;
  double sum = 0.0;
  for (std::size_t k = 0; k < static_cast<std::size_t>(kSteps); ++k) {
    const double ex = est[k](0) - d.truth[k + 1](0);
    const double ey = est[k](2) - d.truth[k + 1](2);
    sum += ex * ex + ey * ey;
  }
  rec.mse_m2 = sum / kSteps;
  const State& last = est[kSteps - 1];
  rec.final_error_m = std::hypot(last(0) - d.truth[kSteps](0), last(2) - d.truth[kSteps](2));
  return rec;
}

template <int kN>
Record run_crpf(std::size_t cell, std::uint64_t run, std::size_t filter, const RunData& d) {
  CrpfConfig<double> params;  // defaults of docs/filters.md: lambda 0.8, beta 2, delta 1, kick 2 m/s^2
  params.seed = crpf_seed(cell, run, filter);
  params.refuse_indefinite = false;  // scored on the estimate alone, as paper 001 does
  auto f = std::make_unique<Crpf<Motion, Radar, kN>>(motion_for(kTuning), radar_for(kTuning), params);
  return run_filter(*f, d);
}

}  // namespace

const std::array<Cell, kCells>& grid() {
  static const std::array<Cell, kCells> cells = [] {
    std::array<Cell, kCells> g{};
    const double sb[3] = {0.01, 0.1, 1.0};
    const double sr[3] = {0.1, 1.0, 10.0};
    const double sa[3] = {0.01, 0.1, 1.0};
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) g[3 * i + j] = Cell{sb[i], sr[j], sa[j]};
    }
    return g;
  }();
  return cells;
}

std::string_view filter_name(std::size_t f) { return f < kFilters ? kNames[f] : "?"; }

Record& Records::at(std::size_t cell, std::uint64_t run, std::size_t filter) {
  return records[(cell * runs() + (run - run_begin)) * kFilters + filter];
}
const Record& Records::at(std::size_t cell, std::uint64_t run, std::size_t filter) const {
  return records[(cell * runs() + (run - run_begin)) * kFilters + filter];
}

std::array<Record, kFilters> run_one(std::size_t cell, std::uint64_t run) {
  const Cell& c = grid()[cell];
  const RunData d = generate(c, run);
  const Motion m = motion_for(kTuning);
  const Radar r = radar_for(kTuning);
  std::array<Record, kFilters> out{};
  {
    Ekf<Motion, Radar> f(m, r);
    out[0] = run_filter(f, d);
  }
  {
    Ukf<Motion, Radar> f(m, r);
    out[1] = run_filter(f, d);
  }
  {
    Cdkf<Motion, Radar> f(m, r);
    out[2] = run_filter(f, d);
  }
  {
    SrUkf<Motion, Radar> f(m, r);
    out[3] = run_filter(f, d);
  }
  {
    SrCdkf<Motion, Radar> f(m, r);
    out[4] = run_filter(f, d);
  }
  out[5] = run_crpf<100>(cell, run, 5, d);
  out[6] = run_crpf<300>(cell, run, 6, d);
  out[7] = run_crpf<500>(cell, run, 7, d);
  {
    Ekf<Motion, Radar> f(motion_for(c), radar_for(c));
    out[8] = run_filter(f, d);
  }
  return out;
}

Records run_campaign(const CampaignParams& config) {
  if (config.run_end <= config.run_begin || config.run_end > config.total_runs) {
    throw std::invalid_argument("mc001: empty or out-of-range run range");
  }
  Records out;
  out.total_runs = config.total_runs;
  out.run_begin = config.run_begin;
  out.run_end = config.run_end;
  out.threads = std::max(1u, config.threads);
  const std::uint64_t runs = out.runs();
  const std::uint64_t items = runs * kCells;
  out.records.resize(static_cast<std::size_t>(items) * kFilters);

  for_each_index(
      static_cast<std::size_t>(items), out.threads,
      [&](std::size_t i) {
        const std::size_t cell = static_cast<std::size_t>(i / runs);
        const std::uint64_t run = config.run_begin + i % runs;
        const auto recs = run_one(cell, run);
        for (std::size_t f = 0; f < kFilters; ++f) out.at(cell, run, f) = recs[f];
      },
      config.progress ? Progress{"mc001", "cell-runs"} : Progress{});
  return out;
}

void shard_range(std::uint64_t total_runs, unsigned k, unsigned n, std::uint64_t& begin, std::uint64_t& end) {
  if (n == 0 || k == 0 || k > n) throw std::invalid_argument("--shard K/N needs 1 <= K <= N");
  if (n > total_runs) throw std::invalid_argument("--shard: more shards than runs");
  begin = total_runs * (k - 1) / n;
  end = total_runs * k / n;
}

namespace {

constexpr char kMagic[8] = {'K', 'E', 'S', 'T', 'M', 'C', '0', '1'};
constexpr std::uint32_t kVersion = 1;

struct FileHeader {
  char magic[8];
  std::uint32_t version;
  std::uint32_t cells;
  std::uint32_t filters;
  std::uint32_t steps;
  std::uint64_t total_runs;
  std::uint64_t run_begin;
  std::uint64_t run_end;
  std::uint32_t threads;
  std::uint32_t record_size;
};
static_assert(sizeof(FileHeader) == 56, "fixed on-disk header");
static_assert(sizeof(Record) == 32, "fixed on-disk record");

}  // namespace

void write_records(const std::filesystem::path& path, const Records& r) {
  FileHeader h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.version = kVersion;
  h.cells = kCells;
  h.filters = kFilters;
  h.steps = kSteps;
  h.total_runs = r.total_runs;
  h.run_begin = r.run_begin;
  h.run_end = r.run_end;
  h.threads = r.threads;
  h.record_size = sizeof(Record);
  std::ofstream os(path, std::ios::binary | std::ios::trunc);
  if (!os) throw std::runtime_error("cannot write " + path.string());
  os.write(reinterpret_cast<const char*>(&h), sizeof h);
  os.write(reinterpret_cast<const char*>(r.records.data()),
           static_cast<std::streamsize>(r.records.size() * sizeof(Record)));
  if (!os) throw std::runtime_error("write failed: " + path.string());
}

Records read_records(const std::filesystem::path& path) {
  std::ifstream is(path, std::ios::binary);
  if (!is) throw std::runtime_error("cannot read " + path.string());
  FileHeader h{};
  is.read(reinterpret_cast<char*>(&h), sizeof h);
  if (!is || std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) {
    throw std::runtime_error(path.string() + ": not an MC-001 record file");
  }
  if (h.version != kVersion || h.cells != kCells || h.filters != kFilters || h.steps != kSteps ||
      h.record_size != sizeof(Record)) {
    throw std::runtime_error(path.string() + ": record file of another layout (version " +
                             std::to_string(h.version) + ")");
  }
  if (h.run_end <= h.run_begin || h.run_end > h.total_runs) {
    throw std::runtime_error(path.string() + ": bad run range");
  }
  Records r;
  r.total_runs = h.total_runs;
  r.run_begin = h.run_begin;
  r.run_end = h.run_end;
  r.threads = h.threads;
  r.records.resize(static_cast<std::size_t>(r.runs()) * kCells * kFilters);
  is.read(reinterpret_cast<char*>(r.records.data()), static_cast<std::streamsize>(r.records.size() * sizeof(Record)));
  if (!is) throw std::runtime_error(path.string() + ": truncated");
  return r;
}

Records merge(const std::vector<Records>& shards) {
  if (shards.empty()) throw std::runtime_error("merge: no shards");
  Records out;
  out.total_runs = shards.front().total_runs;
  out.run_begin = 0;
  out.run_end = out.total_runs;
  out.threads = shards.front().threads;
  out.records.resize(static_cast<std::size_t>(out.total_runs) * kCells * kFilters);
  std::vector<bool> seen(static_cast<std::size_t>(out.total_runs), false);
  for (const Records& s : shards) {
    if (s.total_runs != out.total_runs) throw std::runtime_error("merge: shards of campaigns with different --runs");
    out.threads = std::max(out.threads, s.threads);
    for (std::uint64_t run = s.run_begin; run < s.run_end; ++run) {
      if (seen[static_cast<std::size_t>(run)]) {
        throw std::runtime_error("merge: run " + std::to_string(run) + " appears in two shards");
      }
      seen[static_cast<std::size_t>(run)] = true;
      for (std::size_t c = 0; c < kCells; ++c) {
        for (std::size_t f = 0; f < kFilters; ++f) out.at(c, run, f) = s.at(c, run, f);
      }
    }
  }
  const auto missing = std::find(seen.begin(), seen.end(), false);
  if (missing != seen.end()) {
    throw std::runtime_error("merge: run " + std::to_string(missing - seen.begin()) + " of " +
                             std::to_string(out.total_runs) + " is in no shard");
  }
  return out;
}

Summary summarise(const Records& r) {
  if (r.run_begin != 0 || r.run_end != r.total_runs) {
    throw std::runtime_error("summarise: records cover only part of the runs (merge the shards first)");
  }
  Summary s;
  s.total_runs = r.total_runs;
  s.threads = r.threads;
  std::vector<double> mse(static_cast<std::size_t>(r.runs()));
  std::array<double, kFilters> ns_sum{};
  for (std::size_t c = 0; c < kCells; ++c) {
    for (std::size_t f = 0; f < kFilters; ++f) {
      CellSummary& cs = s.cells[c][f];
      double final_sum = 0.0;
      for (std::uint64_t run = 0; run < r.runs(); ++run) {
        const Record& rec = r.at(c, run, f);
        mse[static_cast<std::size_t>(run)] = rec.mse_m2;
        final_sum += rec.final_error_m;
        cs.diverged += rec.final_error_m > kDivergedM || !std::isfinite(rec.final_error_m) ? 1 : 0;
        cs.failures += rec.failures;
        ns_sum[f] += rec.step_ns;
      }
      const MeanCi m = mean_ci95(mse);
      cs.mse_mean = m.mean;
      cs.ci95_low = m.ci95_low;
      cs.ci95_high = m.ci95_high;
      cs.runs = r.runs();
      cs.final_error_mean_m = final_sum / static_cast<double>(r.runs());
    }
  }
  for (std::size_t f = 0; f < kFilters; ++f) {
    s.ns_per_step[f] = ns_sum[f] / static_cast<double>(r.runs() * kCells);
  }
  return s;
}

void write_tables(const std::filesystem::path& dir, const Summary& s) {
  std::filesystem::create_directories(dir);
  {
    std::FILE* f = std::fopen((dir / "mc001_mse.csv").c_str(), "w");
    if (f == nullptr) throw std::runtime_error("cannot write " + (dir / "mc001_mse.csv").string());
    std::fprintf(f,
                 "cell,bearing_sigma_deg,range_sigma_m,accel_sigma_mps2,filter,runs,mse_m2,ci95_low_m2,ci95_high_m2,"
                 "final_error_mean_m,diverged,failures\n");
    for (std::size_t c = 0; c < kCells; ++c) {
      const Cell& g = grid()[c];
      for (std::size_t k = 0; k < kFilters; ++k) {
        const CellSummary& cs = s.cells[c][k];
        std::fprintf(f, "%zu,%g,%g,%g,%s,%llu,%.17g,%.17g,%.17g,%.17g,%llu,%llu\n", c, g.bearing_sigma_deg,
                     g.range_sigma_m, g.accel_sigma_mps2, std::string(filter_name(k)).c_str(),
                     static_cast<unsigned long long>(cs.runs), cs.mse_mean, cs.ci95_low, cs.ci95_high,
                     cs.final_error_mean_m, static_cast<unsigned long long>(cs.diverged),
                     static_cast<unsigned long long>(cs.failures));
      }
    }
    std::fclose(f);
  }
  {
    std::FILE* f = std::fopen((dir / "mc001_table.md").c_str(), "w");
    if (f == nullptr) throw std::runtime_error("cannot write " + (dir / "mc001_table.md").string());
    std::fprintf(f,
                 "MC-001 position MSE (m^2), mean over %llu runs per cell +- half-width of the 95 %% interval; "
                 "(n) = runs whose final error exceeds %.0f m.\n\n",
                 static_cast<unsigned long long>(s.total_runs), kDivergedM);
    std::fprintf(f, "| sb (deg) | sr (m) | sa (m/s^2) |");
    for (std::size_t k = 0; k < kFilters; ++k) std::fprintf(f, " %s |", std::string(filter_name(k)).c_str());
    std::fprintf(f, "\n|---|---|---|");
    for (std::size_t k = 0; k < kFilters; ++k) std::fprintf(f, "---|");
    std::fprintf(f, "\n");
    for (std::size_t c = 0; c < kCells; ++c) {
      const Cell& g = grid()[c];
      std::fprintf(f, "| %g | %g | %g |", g.bearing_sigma_deg, g.range_sigma_m, g.accel_sigma_mps2);
      for (std::size_t k = 0; k < kFilters; ++k) {
        const CellSummary& cs = s.cells[c][k];
        std::fprintf(f, " %.4g +- %.2g", cs.mse_mean, 0.5 * (cs.ci95_high - cs.ci95_low));
        if (cs.diverged > 0) std::fprintf(f, " (%llu)", static_cast<unsigned long long>(cs.diverged));
        if (cs.failures > 0) std::fprintf(f, " [%llu failed calls]", static_cast<unsigned long long>(cs.failures));
        std::fprintf(f, " |");
      }
      std::fprintf(f, "\n");
    }
    std::fclose(f);
  }
  {
    std::FILE* f = std::fopen((dir / "mc001_timing.csv").c_str(), "w");
    if (f == nullptr) throw std::runtime_error("cannot write " + (dir / "mc001_timing.csv").string());
    std::fprintf(f, "filter,ns_per_step,steps,threads\n");
    for (std::size_t k = 0; k < kFilters; ++k) {
      std::fprintf(f, "%s,%.1f,%llu,%u\n", std::string(filter_name(k)).c_str(), s.ns_per_step[k],
                   static_cast<unsigned long long>(s.total_runs * kCells * kSteps), s.threads);
    }
    std::fclose(f);
  }
}

void print_summary(const Summary& s) {
  std::printf("MC-001: %llu runs per cell, position MSE m^2 (mean, 95 %% half-width; diverged: final error > %.0f m)\n",
              static_cast<unsigned long long>(s.total_runs), kDivergedM);
  std::printf("%-5s %-5s %-5s", "sb", "sr", "sa");
  for (std::size_t k = 0; k < kFilters; ++k) std::printf(" %18s", std::string(filter_name(k)).c_str());
  std::printf("\n");
  for (std::size_t c = 0; c < kCells; ++c) {
    const Cell& g = grid()[c];
    std::printf("%-5g %-5g %-5g", g.bearing_sigma_deg, g.range_sigma_m, g.accel_sigma_mps2);
    for (std::size_t k = 0; k < kFilters; ++k) {
      const CellSummary& cs = s.cells[c][k];
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.4g+-%.2g/%llu", cs.mse_mean, 0.5 * (cs.ci95_high - cs.ci95_low),
                    static_cast<unsigned long long>(cs.diverged));
      std::printf(" %18s", buf);
    }
    std::printf("\n");
  }
  std::printf("time per step (predict + update), mean over all runs, %u thread%s measuring:\n", s.threads,
              s.threads == 1 ? "" : "s");
  for (std::size_t k = 0; k < kFilters; ++k) {
    std::printf("  %-11s %9.2f us\n", std::string(filter_name(k)).c_str(), s.ns_per_step[k] / 1000.0);
  }
}

bool plot(const std::filesystem::path& dir) { return run_named_plot_script("mc001_plots.py", {"--dir", dir.string()}); }

}  // namespace kestrel::sim::mc001
