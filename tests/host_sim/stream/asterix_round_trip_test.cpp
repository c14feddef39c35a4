// SPDX-License-Identifier: Apache-2.0
// kestrel-sim and ASTERIX (docs/asterix.md, "kestrel-sim and ASTERIX"):
// scenario plots written as CAT048 read back through the board's CAT048
// feed and tracked by the same Runner as a wire stream; every published
// report written as CAT062 by hal's Cat062Sink and re-read here by a
// test-side decoder; a damaged recording counted, never a crash; and the
// whole loop with both ASTERIX ends allocation-free.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <vector>

#include "filters/ekf_ca.hpp"
#include "filters/filter_registry.hpp"
#include "hal/asterix_builder.hpp"
#include "kestrel/hal/asterix_units.hpp"
#include "kestrel/host/asterix_file_feed.hpp"
#include "kestrel/host/board.hpp"
#include "pipeline/stream_run.hpp"
#include "scenarios/registry.hpp"
#include "stream/asterix_stream.hpp"
#include "stream/quantise.hpp"
#include "stream/stream_writer.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::Status;
using kestrel::sim::StreamFormat;
using kestrel::sim::StreamInput;
using kestrel::sim::StreamRunResult;
using Bytes = std::vector<std::uint8_t>;

// Half an LSB of I048/040: RHO 1/256 NM, THETA 2^-16 turn. The wire
// quantises the ASTERIX value again (1 mm, 2^-32 turn): that adds at most
// 0.5 mm and 2^-33 turn.
constexpr double kHalfRhoM = 1852.0 / 512.0 + 0.0005;
constexpr double kHalfThetaRad = std::numbers::pi / 65536.0 + std::numbers::pi / 4294967296.0;

StreamRunResult run_ekf_ca(StreamInput input) {
  return kestrel::sim::find_filter("ekf-ca").run(std::move(input), {}, 1'000'000'000);
}

std::size_t reports_of(const StreamRunResult& r) {
  std::size_t n = 0;
  for (const auto& f : r.frames) n += f.tracks.size();
  return n;
}

double wrap(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

/// Position RMSE of the confirmed track nearest truth, frames 2 onwards.
double rmse_m(const StreamRunResult& r, const std::vector<kestrel::sim::TruthSample>& truth) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 2; k < r.frames.size() && k < truth.size(); ++k) {
    double best = INFINITY;
    for (const auto& t : r.frames[k].tracks) {
      if (t.confirmed) best = std::min(best, std::hypot(t.x_m - truth[k].x_m, t.y_m - truth[k].y_m));
    }
    if (std::isfinite(best)) {
      sum += best * best;
      ++n;
    }
  }
  return n == 0 ? NAN : std::sqrt(sum / static_cast<double>(n));
}

// A test-side CAT062 reader for the record the sink writes: FSPEC 97 0D 01 04
// (I062/010, /070, /100, /185, /040, /080, /500 APC), 27 bytes.
struct Cat062Seen {
  unsigned sac, sic, tod_128, track_number, cnf;
  double x_m, y_m, vx_mps, vy_mps, apc_x_m, apc_y_m;
};

std::int32_t sext(std::uint32_t v, int bits) {
  const std::uint32_t sign = 1u << (bits - 1);
  return static_cast<std::int32_t>((v ^ sign) - sign);
}
std::uint32_t be(const Bytes& b, std::size_t at, int n) {
  std::uint32_t v = 0;
  for (int i = 0; i < n; ++i) v = (v << 8) | b[at + static_cast<std::size_t>(i)];
  return v;
}

std::vector<Cat062Seen> read_cat062(const Bytes& b) {
  std::vector<Cat062Seen> out;
  std::size_t pos = 0;
  while (pos < b.size()) {
    REQUIRE(b.size() - pos >= 30);
    REQUIRE(b[pos] == 62);
    REQUIRE(be(b, pos + 1, 2) == 30);  // one record per block
    std::size_t r = pos + 3;
    REQUIRE(be(b, r, 4) == 0x970D0104u);
    r += 4;
    Cat062Seen s{};
    s.sac = b[r];
    s.sic = b[r + 1];
    s.tod_128 = be(b, r + 2, 3);
    s.x_m = 0.5 * sext(be(b, r + 5, 3), 24);
    s.y_m = 0.5 * sext(be(b, r + 8, 3), 24);
    s.vx_mps = 0.25 * sext(be(b, r + 11, 2), 16);
    s.vy_mps = 0.25 * sext(be(b, r + 13, 2), 16);
    s.track_number = be(b, r + 15, 2);
    s.cnf = (b[r + 17] >> 4) & 1u;  // I062/080 first octet: MON SPI MRH SRC(3) CNF FX
    REQUIRE(b[r + 18] == 0x80);      // I062/500 primary subfield: APC only (bit 8)
    s.apc_x_m = 0.5 * be(b, r + 19, 2);
    s.apc_y_m = 0.5 * be(b, r + 21, 2);
    out.push_back(s);
    pos += 30;
  }
  return out;
}

}  // namespace

SCENARIO("S1 written as CAT048 replays to the tracks of the wire replay", "[host_sim][asterix]") {
  GIVEN("S1 seed 0 as a wire stream and as CAT048 data blocks") {
    const auto scenario = kestrel::sim::make_scenario("s1");
    const kestrel::sim::ScenarioRun run = scenario->generate(0);
    const Bytes ast = kestrel::sim::encode_cat048_stream(run.frames, 25);
    std::size_t skipped = 0;
    kestrel::sim::AsterixReadCounts counts;
    const auto read_back = kestrel::sim::decode_cat048_stream(ast, skipped, counts);

    THEN("the encoder writes what the specification builder writes") {
      kestrel::test::Cat048PlotSpec p;
      p.sac = 25;
      p.sic = 0;
      p.tod_128 = 0;
      p.rho_256nm = kestrel::hal::asterix::rho_from_range_mm(kestrel::sim::to_wire_range_mm(run.frames[0].radar[0].range_m));
      p.theta = kestrel::hal::asterix::azimuth_from_bearing_bam(
          kestrel::sim::to_wire_bearing_bam(run.frames[0].radar[0].bearing_rad));
      const Bytes want = kestrel::test::cat048_block({p});
      REQUIRE(ast.size() == 300 * want.size());
      CHECK(Bytes(ast.begin(), ast.begin() + static_cast<std::ptrdiff_t>(want.size())) == want);
    }
    THEN("every plot comes back within half an ASTERIX LSB, at its time") {
      REQUIRE(skipped == 0);
      REQUIRE(read_back.size() == run.frames.size());
      CHECK(counts.feed.blocks == 300);
      CHECK(counts.reader.plots == 300);
      CHECK(counts.feed.unknown_category + counts.feed.malformed + counts.feed.truncated == 0);
      double worst_range = 0.0, worst_bearing = 0.0;
      for (std::size_t k = 0; k < run.frames.size(); ++k) {
        REQUIRE(read_back[k].radar.size() == 1);
        CHECK(read_back[k].t_s == run.frames[k].t_s);  // multiples of 0.5 s: exact in 1/128 s
        worst_range = std::max(worst_range, std::abs(read_back[k].radar[0].range_m - run.frames[k].radar[0].range_m));
        worst_bearing =
            std::max(worst_bearing, std::abs(wrap(read_back[k].radar[0].bearing_rad - run.frames[k].radar[0].bearing_rad)));
      }
      CHECK(worst_range <= kHalfRhoM);
      CHECK(worst_bearing <= kHalfThetaRad);
      CHECK(worst_range > 0.5);  // the quantisation is really there
    }
    WHEN("the CAT048 file and a wire stream of the plots read back from it are replayed") {
      const StreamRunResult via_asterix = run_ekf_ca(StreamInput(ast, StreamFormat::kAsterixCat048));
      const StreamRunResult via_wire = run_ekf_ca(StreamInput(kestrel::sim::encode_stream(read_back)));
      THEN("the board loop gives the same reports, bit for bit") {
        REQUIRE(via_asterix.frames.size() == 300);
        REQUIRE(via_asterix.stats.steps == 300);
        REQUIRE(via_asterix.asterix.has_value());
        CHECK(via_asterix.asterix->frames == 300);
        REQUIRE(via_wire.frames.size() == via_asterix.frames.size());
        for (std::size_t k = 0; k < via_wire.frames.size(); ++k) {
          const auto& a = via_asterix.frames[k];
          const auto& w = via_wire.frames[k];
          REQUIRE(a.t_us == w.t_us);
          REQUIRE(a.tracks.size() == w.tracks.size());
          for (std::size_t i = 0; i < a.tracks.size(); ++i) {
            CHECK(a.tracks[i].track_id == w.tracks[i].track_id);
            CHECK(a.tracks[i].x_m == w.tracks[i].x_m);
            CHECK(a.tracks[i].y_m == w.tracks[i].y_m);
            CHECK(a.tracks[i].vx_mps == w.tracks[i].vx_mps);
            CHECK(a.tracks[i].p_xx == w.tracks[i].p_xx);
          }
        }
      }
    }
    WHEN("the CAT048 replay is compared with the wire replay of the original plots") {
      const StreamRunResult via_asterix = run_ekf_ca(StreamInput(ast, StreamFormat::kAsterixCat048));
      const StreamRunResult via_wire = run_ekf_ca(StreamInput(kestrel::sim::encode_stream(run.frames)));
      const double rmse_ast = rmse_m(via_asterix, run.truth);
      const double rmse_wire = rmse_m(via_wire, run.truth);
      UNSCOPED_INFO("RMSE wire " << rmse_wire << " m, CAT048 " << rmse_ast << " m");
      THEN("the same tracks up to the quantisation: one confirmed track id, RMSE within 1 m") {
        REQUIRE(via_asterix.frames.size() == via_wire.frames.size());
        double worst = 0.0;
        for (std::size_t k = 0; k < via_wire.frames.size(); ++k) {
          REQUIRE(via_asterix.frames[k].tracks.size() == via_wire.frames[k].tracks.size());
          for (std::size_t i = 0; i < via_wire.frames[k].tracks.size(); ++i) {
            const auto& a = via_asterix.frames[k].tracks[i];
            const auto& w = via_wire.frames[k].tracks[i];
            CHECK(a.track_id == w.track_id);
            CHECK(a.confirmed == w.confirmed);
            worst = std::max(worst, std::hypot(a.x_m - w.x_m, a.y_m - w.y_m));
          }
        }
        UNSCOPED_INFO("largest position difference between the replays " << worst << " m");
        // The plot errors the quantisation adds (range sd 2.1 m, bearing
        // sd 28 urad = 0.6 m at 20 km) are 1/20 of the sensor noise
        // (50 m, 1 mrad); the filter averages them further.
        CHECK(worst < 10.0);
        CHECK(std::abs(rmse_ast - rmse_wire) < 1.0);
      }
    }
  }
}

SCENARIO("Every published report is also written as a CAT062 block", "[host_sim][asterix]") {
  GIVEN("S1 seed 2 replayed with a CAT062 output, SAC 7, SIC 9") {
    const auto run = kestrel::sim::make_scenario("s1")->generate(2);
    StreamInput input(kestrel::sim::encode_stream(run.frames));
    input.cat062 = kestrel::hal::asterix::Cat062Source{7, 9, false, 0};
    const StreamRunResult r = run_ekf_ca(std::move(input));
    const std::vector<Cat062Seen> seen = read_cat062(r.cat062);
    THEN("one block per report, each field within half its LSB of the report") {
      REQUIRE(r.cat062_refused == 0);
      REQUIRE(seen.size() == reports_of(r));
      REQUIRE(seen.size() >= 299);  // S1 is 300 frames; the track is reported from the second on
      std::size_t i = 0;
      for (const auto& f : r.frames) {
        for (const auto& t : f.tracks) {
          const Cat062Seen& s = seen[i++];
          CHECK(s.sac == 7);
          CHECK(s.sic == 9);
          CHECK(s.tod_128 == static_cast<unsigned>(std::lround(t.time_s * 128.0)));
          CHECK(s.track_number == t.track_id);
          CHECK(s.cnf == (t.confirmed ? 0u : 1u));
          CHECK(std::abs(s.x_m - t.x_m) <= 0.25);
          CHECK(std::abs(s.y_m - t.y_m) <= 0.25);
          CHECK(std::abs(s.vx_mps - t.vx_mps) <= 0.125);
          CHECK(std::abs(s.vy_mps - t.vy_mps) <= 0.125);
          CHECK(std::abs(s.apc_x_m - std::sqrt(t.p_xx)) <= 0.25);
          CHECK(std::abs(s.apc_y_m - std::sqrt(t.p_yy)) <= 0.25);
        }
      }
    }
    THEN("without a CAT062 source nothing is written") {
      CHECK(run_ekf_ca(StreamInput(kestrel::sim::encode_stream(run.frames))).cat062.empty());
    }
  }
}

SCENARIO("A damaged CAT048 recording is counted and the good blocks are tracked", "[host_sim][asterix]") {
  GIVEN("S1 blocks with a CAT034 block, a malformed record and a block cut at the end") {
    auto frames = kestrel::sim::make_scenario("s1")->generate(3).frames;
    frames.resize(40);
    const Bytes first = kestrel::sim::encode_cat048_stream({frames.begin(), frames.begin() + 20}, 1);
    const Bytes second = kestrel::sim::encode_cat048_stream({frames.begin() + 20, frames.end()}, 1);
    Bytes bytes(first);
    const Bytes cat034 = kestrel::test::asterix_block(34, {{0x80, 0x01, 0x02}});
    bytes.insert(bytes.end(), cat034.begin(), cat034.end());
    // A CAT048 block whose one record announces I048/010 but ends before it.
    bytes.insert(bytes.end(), {48, 0x00, 0x05, 0x80, 0x01});
    bytes.insert(bytes.end(), second.begin(), second.end());
    bytes.insert(bytes.end(), {48, 0x00, 0x40, 0xF0});  // LEN 64, 4 bytes there
    std::size_t skipped = 0;
    kestrel::sim::AsterixReadCounts counts;
    const auto read_back = kestrel::sim::decode_cat048_stream(bytes, skipped, counts);
    const StreamRunResult r = run_ekf_ca(StreamInput(bytes, StreamFormat::kAsterixCat048));

    THEN("each damage is counted once and the 40 good frames are tracked") {
      CHECK(counts.feed.unknown_category == 1);
      CHECK(counts.feed.malformed == 1);
      CHECK(counts.feed.truncated == 1);
      CHECK(counts.feed.frames == 40);
      CHECK(skipped == 3);
      CHECK(read_back.size() == 43);
      REQUIRE(r.asterix.has_value());
      CHECK(r.stats.frames == 43);
      CHECK(r.stats.steps == 40);
      CHECK(r.stats.by_status[static_cast<std::size_t>(Status::kUnknownKind)] == 1);
      CHECK(r.stats.by_status[static_cast<std::size_t>(Status::kMalformedFrame)] == 1);
      CHECK(r.stats.by_status[static_cast<std::size_t>(Status::kTruncated)] == 1);
      CHECK(r.frames.back().tracks.empty());  // the truncated block's placeholder
    }
  }
  GIVEN("a file that is not ASTERIX (a wire stream)") {
    const auto frames = kestrel::sim::make_scenario("s1")->generate(0).frames;
    std::size_t skipped = 0;
    kestrel::sim::AsterixReadCounts counts;
    (void)kestrel::sim::decode_cat048_stream(kestrel::sim::encode_stream(frames), skipped, counts);
    THEN("no plot is found") {
      CHECK(counts.reader.plots == 0);
      CHECK(counts.feed.frames == 0);
    }
  }
  GIVEN("a value CAT048 cannot carry") {
    auto frames = kestrel::sim::make_scenario("s1")->generate(0).frames;
    frames.resize(1);
    THEN("a time before midnight, a range beyond 256 NM and a Doppler over 511 m/s are refused") {
      auto f = frames;
      f[0].t_s = -1.0;
      CHECK_THROWS_AS(kestrel::sim::encode_cat048_stream(f, 0), std::out_of_range);
      f = frames;
      f[0].t_s = 86400.0;
      CHECK_THROWS_AS(kestrel::sim::encode_cat048_stream(f, 0), std::out_of_range);
      f = frames;
      f[0].radar[0].range_m = 474200.0;
      CHECK_THROWS_AS(kestrel::sim::encode_cat048_stream(f, 0), std::out_of_range);
      f = frames;
      f[0].radar[0].range_rate_mps = 511.6;
      CHECK_THROWS_AS(kestrel::sim::encode_cat048_stream(f, 0), std::out_of_range);
      f[0].radar[0].range_rate_mps = -512.4;
      CHECK_NOTHROW(kestrel::sim::encode_cat048_stream(f, 0));
    }
  }
}

SCENARIO("A Doppler plot survives CAT048 as a range rate in whole m/s", "[host_sim][asterix]") {
  GIVEN("one frame with a range rate of -37.4 m/s") {
    auto frames = kestrel::sim::make_scenario("s1")->generate(0).frames;
    frames.resize(1);
    frames[0].radar[0].range_rate_mps = -37.4;
    std::size_t skipped = 0;
    kestrel::sim::AsterixReadCounts counts;
    const auto back =
        kestrel::sim::decode_cat048_stream(kestrel::sim::encode_cat048_stream(frames, 0), skipped, counts);
    THEN("it reads back as -37 m/s") {
      REQUIRE(back.size() == 1);
      REQUIRE(back[0].radar[0].range_rate_mps.has_value());
      CHECK(*back[0].radar[0].range_rate_mps == -37.0);
    }
  }
}

SCENARIO("The board loop with a CAT048 feed and a CAT062 sink allocates nothing", "[host_sim][asterix][alloc]") {
  GIVEN("S1 as CAT048 and a run that writes CAT062") {
    using Tracker = kestrel::host::BoardRadarTracker<kestrel::EkfCa<double>>;
    const Bytes ast = kestrel::sim::encode_cat048_stream(kestrel::sim::make_scenario("s1")->generate(0).frames, 0);
    auto tracker = std::make_unique<Tracker>(
        kestrel::make_radar_tracker<double, kestrel::host::kMaxTracks, kestrel::host::kMaxPlots>(
            kestrel::sim::radar_tracker_params({})));
    kestrel::sim::StreamRun<Tracker, kestrel::host::AsterixFileFeed> run(
        *tracker, ast, 1'000'000, kestrel::hal::asterix::Cat062Source{0, 1, false, 0});
    std::size_t allocations = 0;
    {
      kestrel::test::AllocationGuard guard;
      run.run_to_end();
      allocations = guard.allocations();
    }
    THEN("300 steps, CAT062 written, zero allocations") {
      REQUIRE(run.stats().steps == 300);
      CHECK(run.stats().publish_failures == 0);
      CHECK_FALSE(run.result().cat062.empty());
      CHECK(allocations == 0);
    }
  }
}
