// SPDX-License-Identifier: Apache-2.0
#include "csv/sensor_truth_csv.hpp"

#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>

#include "csv/csv_reader.hpp"
#include "stream/quantise.hpp"

namespace kestrel::sim {

namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File create(const std::filesystem::path& path) {
  File f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw std::runtime_error("cannot create truth CSV '" + path.string() + "'");
  return f;
}

void finish(const File& f, const std::filesystem::path& path) {
  if (std::ferror(f.get()) != 0) throw std::runtime_error("cannot write truth CSV '" + path.string() + "'");
}

std::ifstream open_in(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open truth CSV '" + path.string() + "'");
  return in;
}

/// A time the wire can carry, later than the previous row's (truth is
/// matched to frames in wire microseconds, as a radar truth is).
double read_time(const CsvReader& csv, std::size_t col, double previous, bool first) {
  const double t = csv.number(col);
  if (!try_wire_time_us(t).has_value()) {
    csv.fail_cell(col, "is outside what the wire can carry, " + std::string(kWireTimeSpan));
  }
  if (!first && t <= previous) csv.fail("time_s must increase from row to row");
  return t;
}

/// The time, position and velocity columns of every sensor's truth CSV.
struct KinematicColumns {
  explicit KinematicColumns(const CsvReader& csv)
      : t(csv.require_column("time_s")),
        x(csv.require_column("x_m")),
        y(csv.require_column("y_m")),
        z(csv.require_column("z_m")),
        vx(csv.require_column("vx_mps")),
        vy(csv.require_column("vy_mps")),
        vz(csv.require_column("vz_mps")) {}

  /// The current row's time (after the rows read so far) and kinematics into `truth`.
  template <class Rows, class Truth>
  void read(const CsvReader& csv, const Rows& rows, Truth& truth) const {
    truth.t_s = read_time(csv, t, rows.empty() ? 0.0 : rows.back().truth.t_s, rows.empty());
    truth.x_m = csv.number(x);
    truth.y_m = csv.number(y);
    truth.z_m = csv.number(z);
    truth.vx_mps = csv.number(vx);
    truth.vy_mps = csv.number(vy);
    truth.vz_mps = csv.number(vz);
  }

  std::size_t t, x, y, z, vx, vy, vz;
};

constexpr long long kChannelMask = (1LL << (2 * 8)) - 1;  // 8 beacons x 2 paths

}  // namespace

hal::FrameKind truth_csv_kind(const std::filesystem::path& path) {
  std::ifstream in = open_in(path);
  const CsvReader csv(in, path.string());
  if (csv.find_column("rb_m").has_value() && csv.find_column("drb_mps").has_value()) return hal::FrameKind::kPcl;
  if (csv.find_column("c_mps").has_value()) return hal::FrameKind::kSonar;
  return hal::FrameKind::kRadar;
}

void write_pcl_truth_csv(const std::filesystem::path& path, const PclScenarioRun& run) {
  const File f = create(path);
  std::fprintf(f.get(),
               "time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,rb_m,drb_mps,fd_hz,detected,target_rb_mm,"
               "target_doppler_mhz,target_snr_cdb\n");
  for (std::size_t k = 0; k < run.truth.size(); ++k) {
    const PclTruth& t = run.truth[k];
    std::fprintf(f.get(), "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", t.t_s, t.x_m, t.y_m, t.z_m,
                 t.vx_mps, t.vy_mps, t.vz_mps, t.rb_m, t.drb_mps, t.fd_hz);
    const PclFrameRecord* rec = k < run.frames.size() ? &run.frames[k] : nullptr;
    if (rec != nullptr && rec->target_index >= 0) {
      const hal::PclCandidate& c = rec->wire.pcl[static_cast<std::size_t>(rec->target_index)];
      std::fprintf(f.get(), ",%d,%lu,%ld,%d\n", rec->detected ? 1 : 0, static_cast<unsigned long>(c.bistatic_range_mm),
                   static_cast<long>(c.doppler_mhz), static_cast<int>(c.snr_cdb));
    } else {
      std::fprintf(f.get(), ",%d,,,\n", rec != nullptr && rec->detected ? 1 : 0);
    }
  }
  finish(f, path);
}

std::vector<PclTruthRow> read_pcl_truth_csv(const std::filesystem::path& path) {
  std::ifstream in = open_in(path);
  CsvReader csv(in, path.string());
  const KinematicColumns kinematics(csv);
  const std::size_t c_rb = csv.require_column("rb_m"), c_drb = csv.require_column("drb_mps");
  const std::size_t c_fd = csv.require_column("fd_hz"), c_det = csv.require_column("detected");
  const std::size_t c_trb = csv.require_column("target_rb_mm"), c_tfd = csv.require_column("target_doppler_mhz"),
                    c_tsnr = csv.require_column("target_snr_cdb");
  std::vector<PclTruthRow> rows;
  while (csv.next()) {
    PclTruthRow r;
    kinematics.read(csv, rows, r.truth);
    r.truth.rb_m = csv.number(c_rb);
    r.truth.drb_mps = csv.number(c_drb);
    r.truth.fd_hz = csv.number(c_fd);
    r.detected = csv.integer(c_det, 0, 1) == 1;
    const bool any = !csv.cell(c_trb).empty() || !csv.cell(c_tfd).empty() || !csv.cell(c_tsnr).empty();
    if (any) {
      hal::PclCandidate c{};
      c.bistatic_range_mm = static_cast<std::uint32_t>(csv.integer(c_trb, 0, std::numeric_limits<std::uint32_t>::max()));
      c.doppler_mhz = static_cast<std::int32_t>(
          csv.integer(c_tfd, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()));
      c.snr_cdb = static_cast<std::int16_t>(
          csv.integer(c_tsnr, std::numeric_limits<std::int16_t>::min(), std::numeric_limits<std::int16_t>::max()));
      if (!r.detected) csv.fail("a target detection is given but detected is 0");
      r.detection = c;
    }
    rows.push_back(r);
  }
  return rows;
}

void write_sonar_truth_csv(const std::filesystem::path& path, const SonarScenarioRun& run) {
  const File f = create(path);
  std::fprintf(f.get(), "time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,c_mps,channels,outlier_channels\n");
  for (std::size_t k = 0; k < run.truth.size(); ++k) {
    const SonarTruth& t = run.truth[k];
    std::uint32_t channels = 0, outliers = 0;
    if (k < run.frames.size()) {
      for (const SonarArrivalRecord& a : run.frames[k].arrivals) {
        const std::uint32_t bit = 1u << (2u * a.beacon + static_cast<std::uint32_t>(a.path));
        channels |= bit;
        if (a.outlier) outliers |= bit;
      }
    }
    std::fprintf(f.get(), "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%lu,%lu\n", t.t_s, t.x_m, t.y_m, t.z_m,
                 t.vx_mps, t.vy_mps, t.vz_mps, t.c_mps, static_cast<unsigned long>(channels),
                 static_cast<unsigned long>(outliers));
  }
  finish(f, path);
}

std::vector<SonarTruthRow> read_sonar_truth_csv(const std::filesystem::path& path) {
  std::ifstream in = open_in(path);
  CsvReader csv(in, path.string());
  const KinematicColumns kinematics(csv);
  const std::size_t c_c = csv.require_column("c_mps");
  const std::size_t c_ch = csv.require_column("channels"), c_out = csv.require_column("outlier_channels");
  std::vector<SonarTruthRow> rows;
  while (csv.next()) {
    SonarTruthRow r;
    kinematics.read(csv, rows, r.truth);
    r.truth.c_mps = csv.number(c_c);
    r.channels = static_cast<std::uint32_t>(csv.integer(c_ch, 0, kChannelMask));
    r.outlier_channels = static_cast<std::uint32_t>(csv.integer(c_out, 0, kChannelMask));
    if ((r.outlier_channels & ~r.channels) != 0) csv.fail("outlier_channels names a channel that channels does not");
    rows.push_back(r);
  }
  return rows;
}

}  // namespace kestrel::sim
