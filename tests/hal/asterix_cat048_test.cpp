// SPDX-License-Identifier: Apache-2.0
// CAT048 reader (asterix_cat048.hpp): items decoded from bytes written by
// hand after the specification's layouts, every UAP item skipped by its
// length, the grouping of records into frames, one scenario per malformed
// class with the documented status, and a block through the radar adapter.
#include "kestrel/hal/asterix_cat048.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <span>
#include <vector>

#include "asterix_builder.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "support/alloc_guard.hpp"

using kestrel::Status;
using kestrel::hal::Frame;
using kestrel::hal::asterix::Cat048Reader;
using kestrel::hal::asterix::Cat048Record;
using kestrel::hal::asterix::decode_cat048_record;
using kestrel::test::Bytes;
using kestrel::test::Cat048PlotSpec;

namespace {

// Every frame of one block, and the status that ended the block.
struct BlockResult {
  Status open = Status::kOk;
  std::size_t block_len = 0;
  std::vector<Status> statuses;  ///< next()'s statuses up to kNoData (excluded).
  std::vector<Frame> frames;     ///< The frame of each status.
};

BlockResult read_block(const Bytes& bytes) {
  BlockResult r;
  Cat048Reader reader;
  r.open = reader.open(bytes, r.block_len);
  for (int i = 0; i < 1000; ++i) {
    Frame f{};
    const Status s = reader.next(f);
    if (s == Status::kNoData) break;
    r.statuses.push_back(s);
    r.frames.push_back(f);
  }
  return r;
}

Cat048PlotSpec plot(std::uint32_t tod, std::uint16_t rho, std::uint16_t theta, std::uint8_t sic = 1) {
  Cat048PlotSpec p;
  p.sic = sic;
  p.tod_128 = tod;
  p.rho_256nm = rho;
  p.theta = theta;
  return p;
}

}  // namespace

SCENARIO("a CAT048 record written from the specification decodes item by item", "[hal][asterix]") {
  // FSPEC: FRN 1-4 (0xF0 | FX), FRN 11 (octet 2, 0x10 | FX), FRN 20 (octet 3, 0x04).
  const Bytes rec{0xF1, 0x11, 0x04,
                  0x07, 0x2A,              // I048/010 SAC 7, SIC 42
                  0x54, 0x60, 0x40,        // I048/140 43200.5 s = 5529664 / 128
                  0x20,                    // I048/020 TYP single PSR, no extension
                  0x0A, 0x00, 0x20, 0x00,  // I048/040 RHO 10 NM, THETA 45 deg
                  0x01, 0x23,              // I048/161 track 0x123
                  0x80, 0x03, 0xFB};       // I048/120 CAL only: D 0, -5 m/s
  Cat048Record r;
  std::size_t used = 0;
  REQUIRE(decode_cat048_record(rec, r, used) == Status::kOk);
  CHECK(used == rec.size());
  CHECK(r.has_source);
  CHECK(r.sac == 7);
  CHECK(r.sic == 42);
  CHECK(r.has_time);
  CHECK(r.tod_128 == 5'529'664);
  CHECK(r.has_polar);
  CHECK(r.rho_256nm == 2560);
  CHECK(r.theta == 0x2000);
  CHECK(r.has_track_number);
  CHECK(r.track_number == 0x123);
  CHECK(r.has_doppler);
  CHECK(r.doppler_mps == -5);

  WHEN("the Doppler speed is marked doubtful") {
    Bytes doubtful = rec;
    doubtful[doubtful.size() - 2] |= 0x80;
    REQUIRE(decode_cat048_record(doubtful, r, used) == Status::kOk);
    THEN("it is not used") { CHECK_FALSE(r.has_doppler); }
  }
}

SCENARIO("every item of the CAT048 UAP is skipped by its length", "[hal][asterix]") {
  // All 28 FRNs, each item in its own structure; the record after it must
  // decode, which it does only if every length was right.
  Bytes all{0xFF, 0xFF, 0xFF, 0xFE};
  const std::vector<Bytes> items{
      {0x01, 0x02},                                            // 010 fixed 2
      {0x00, 0x00, 0x80},                                      // 140 fixed 3
      {0x21, 0x01, 0x00},                                      // 020 extended, 3 octets
      {0x01, 0x00, 0x40, 0x00},                                // 040 fixed 4
      {0x0F, 0xFF},                                            // 070
      {0x01, 0x90},                                            // 090
      {0xFE, 1, 2, 3, 4, 5, 6, 7},                             // 130 compound, all 7 subfields
      {0xAB, 0xCD, 0xEF},                                      // 220
      {1, 2, 3, 4, 5, 6},                                      // 240
      {2, 1, 2, 3, 4, 5, 6, 7, 0x40, 1, 2, 3, 4, 5, 6, 7, 0x50},  // 250 repetitive, 2 x 8
      {0x0F, 0xFF},                                            // 161
      {0, 1, 0, 2},                                            // 042
      {0, 3, 0, 4},                                            // 200
      {0x01, 0x00},                                            // 170 extended, 2 octets
      {1, 2, 3, 4},                                            // 210
      {0x03, 0x05, 0x04},                                      // 030 extended, 3 octets
      {0, 0},                                                  // 080
      {0, 0, 0, 0},                                            // 100
      {0, 9},                                                  // 110
      {0xC0, 0x00, 0x07, 1, 0, 1, 0, 2, 0, 3},                 // 120 CAL and RDS (1 x 6)
      {0, 0},                                                  // 230
      {1, 2, 3, 4, 5, 6, 7},                                   // 260
      {1},                                                     // 055
      {1, 2},                                                  // 050
      {1},                                                     // 065
      {1, 2},                                                  // 060
      {3, 0xAA, 0xBB},                                         // SP explicit, 3 bytes
      {1},                                                     // RE explicit, LEN only
  };
  REQUIRE(items.size() == 28);
  for (const Bytes& item : items) all.insert(all.end(), item.begin(), item.end());

  Cat048Record r;
  std::size_t used = 0;
  REQUIRE(decode_cat048_record(all, r, used) == Status::kOk);
  CHECK(used == all.size());
  CHECK(r.tod_128 == 0x80);
  CHECK(r.rho_256nm == 0x0100);
  CHECK(r.theta == 0x4000);
  CHECK(r.track_number == 0xFFF);
  CHECK(r.doppler_mps == 7);

  const Bytes next = kestrel::test::cat048_record(plot(640, 512, 0x8000, 9));
  const Bytes block = kestrel::test::asterix_block(48, {all, next});
  const BlockResult b = read_block(block);
  REQUIRE(b.open == Status::kOk);
  REQUIRE(b.statuses.size() == 2);
  CHECK(b.statuses[0] == Status::kOk);
  CHECK(b.statuses[1] == Status::kOk);
  CHECK(b.frames[1].count == 1);
  CHECK(b.frames[1].t_us == 5'000'000);
  CHECK(b.frames[1].radar[0].range_mm == 3'704'000);
  CHECK(b.frames[1].radar[0].sensor_id == 9);
}

SCENARIO("records with the same SAC SIC and time of day form one frame", "[hal][asterix]") {
  GIVEN("two plots at one time, one from another radar, two at a later time") {
    const Bytes block = kestrel::test::cat048_block({plot(1280, 256, 0x0000), plot(1280, 512, 0x4000),
                                                     plot(1280, 768, 0x8000, 2), plot(1408, 1024, 0xC000),
                                                     plot(1408, 1280, 0x2000)});
    const BlockResult b = read_block(block);
    REQUIRE(b.open == Status::kOk);
    CHECK(b.block_len == block.size());
    THEN("three frames come out, in order, with exact wire units") {
      REQUIRE(b.statuses == std::vector<Status>{Status::kOk, Status::kOk, Status::kOk});
      CHECK(b.frames[0].kind == kestrel::hal::FrameKind::kRadar);
      CHECK(b.frames[0].count == 2);
      CHECK(b.frames[0].t_us == 10'000'000);
      CHECK(b.frames[0].radar[0].range_mm == 1'852'000);
      CHECK(b.frames[0].radar[0].bearing_bam == 0x40000000);  // north
      CHECK(b.frames[0].radar[1].bearing_bam == 0);           // east
      CHECK(b.frames[0].radar[0].has_range_rate == 0);
      CHECK(b.frames[1].count == 1);
      CHECK(b.frames[1].radar[0].sensor_id == 2);
      CHECK(b.frames[1].radar[0].bearing_bam == -0x40000000);  // south
      CHECK(b.frames[2].count == 2);
      CHECK(b.frames[2].t_us == 11'000'000);
      CHECK(b.frames[2].radar[0].bearing_bam == INT32_MIN);  // west
      CHECK(b.frames[2].radar[1].range_mm == 9'260'000);
    }
  }
  GIVEN("a plot with a valid Doppler speed") {
    Cat048PlotSpec p = plot(0, 256, 0);
    p.with_doppler = true;
    p.doppler_mps = -300;
    const BlockResult b = read_block(kestrel::test::cat048_block({p}));
    REQUIRE(b.statuses.size() == 1);
    THEN("it becomes the range rate in mm/s") {
      CHECK(b.frames[0].radar[0].has_range_rate == 1);
      CHECK(b.frames[0].radar[0].range_rate_mmps == -300'000);
    }
  }
}

SCENARIO("records without time of day or position are skipped and counted", "[hal][asterix]") {
  Bytes no_position = kestrel::test::fspec({1, 2});
  no_position.insert(no_position.end(), {0, 1, 0, 0, 5});
  Bytes no_time = kestrel::test::fspec({1, 4});
  no_time.insert(no_time.end(), {0, 1, 1, 0, 0, 0});
  const Bytes good = kestrel::test::cat048_record(plot(5, 256, 0));
  const Bytes block = kestrel::test::asterix_block(48, {no_position, good, no_time});
  Cat048Reader reader;
  std::size_t len = 0;
  REQUIRE(reader.open(block, len) == Status::kOk);
  Frame f{};
  REQUIRE(reader.next(f) == Status::kOk);
  CHECK(f.count == 1);
  CHECK(reader.next(f) == Status::kNoData);
  CHECK(f.count == 0);
  CHECK(reader.counters().records == 3);
  CHECK(reader.counters().skipped_no_plot == 2);
  CHECK(reader.counters().plots == 1);
}

SCENARIO("a bad data block header gives the documented status", "[hal][asterix]") {
  const Bytes good = kestrel::test::cat048_block({plot(1, 256, 0)});
  Cat048Reader reader;
  std::size_t len = 99;
  WHEN("fewer than three bytes arrived") {
    CHECK(reader.open(std::span(good).first(2), len) == Status::kTruncated);
    CHECK(len == 0);
  }
  WHEN("LEN is more than the bytes at hand") {
    CHECK(reader.open(std::span(good).first(good.size() - 1), len) == Status::kTruncated);
    CHECK(len == good.size());
  }
  WHEN("LEN is less than the block header") {
    for (std::uint8_t bad = 0; bad < 3; ++bad) {
      Bytes b = good;
      b[1] = 0;
      b[2] = bad;
      CHECK(reader.open(b, len) == Status::kMalformedFrame);
      CHECK(len == 0);
    }
  }
  WHEN("the category is not 48") {
    Bytes b = good;
    b[0] = 34;
    CHECK(reader.open(b, len) == Status::kUnknownKind);
    THEN("LEN says how far to skip and no frame comes out") {
      CHECK(len == good.size());
      Frame f{};
      CHECK(reader.next(f) == Status::kNoData);
    }
  }
  WHEN("the block holds no record") {
    const Bytes empty{48, 0, 3};
    REQUIRE(reader.open(empty, len) == Status::kOk);
    Frame f{};
    CHECK(reader.next(f) == Status::kNoData);
  }
}

SCENARIO("a record that runs past its block is kMalformedFrame", "[hal][asterix]") {
  Cat048Record r;
  std::size_t used = 7;
  WHEN("the FSPEC's FX bit points past the block") {
    CHECK(decode_cat048_record(Bytes{0xF1}, r, used) == Status::kMalformedFrame);
    CHECK(used == 0);
    CHECK(decode_cat048_record(Bytes{}, r, used) == Status::kMalformedFrame);
  }
  WHEN("the FSPEC extends beyond the UAP's 28 items") {
    CHECK(decode_cat048_record(Bytes{0x01, 0x01, 0x01, 0x01, 0x00}, r, used) == Status::kMalformedFrame);
  }
  WHEN("a fixed item is cut short") {
    CHECK(decode_cat048_record(Bytes{0x10, 0x01, 0x00}, r, used) == Status::kMalformedFrame);  // 040 needs 4
  }
  WHEN("an extended item never clears FX") {
    CHECK(decode_cat048_record(Bytes{0x20, 0x21, 0x01}, r, used) == Status::kMalformedFrame);  // 020
  }
  WHEN("a repetitive item counts more than is there") {
    CHECK(decode_cat048_record(Bytes{0x01, 0x20, 2, 1, 2, 3, 4, 5, 6, 7, 8}, r, used) == Status::kMalformedFrame);
  }
  WHEN("an explicit-length item has LEN 0 or LEN past the end") {
    CHECK(decode_cat048_record(Bytes{0x01, 0x01, 0x01, 0x04, 0}, r, used) == Status::kMalformedFrame);  // SP
    CHECK(decode_cat048_record(Bytes{0x01, 0x01, 0x01, 0x02, 5, 1}, r, used) == Status::kMalformedFrame);  // RE
  }
  WHEN("a compound item announces subfields the edition does not define") {
    CHECK(decode_cat048_record(Bytes{0x02, 0x81, 1, 2, 3, 4, 5, 6, 7, 8}, r, used) == Status::kMalformedFrame);  // 130 with FX
    CHECK(decode_cat048_record(Bytes{0x01, 0x01, 0x04, 0x20, 1, 2, 3, 4, 5, 6, 7, 8}, r, used) == Status::kMalformedFrame);  // 120 spare bit
  }
  WHEN("a compound item's subfield is cut short") {
    CHECK(decode_cat048_record(Bytes{0x01, 0x01, 0x04, 0x80, 0x00}, r, used) == Status::kMalformedFrame);  // CAL 1 of 2
  }
  WHEN("the same items are complete") {
    CHECK(decode_cat048_record(Bytes{0x01, 0x01, 0x04, 0x80, 0x00, 0x01}, r, used) == Status::kOk);
    CHECK(used == 6);
  }
}

SCENARIO("a block cut anywhere gives plots only for whole records", "[hal][asterix]") {
  const std::vector<Cat048PlotSpec> plots{plot(1, 256, 0), plot(1, 512, 0x1000), plot(2, 768, 0x2000)};
  std::vector<std::size_t> boundaries{3};
  for (const auto& p : plots) boundaries.push_back(boundaries.back() + kestrel::test::cat048_record(p).size());
  const Bytes full = kestrel::test::cat048_block(plots);
  for (std::size_t cut = 4; cut < full.size(); ++cut) {
    Bytes b(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(cut));
    b[1] = static_cast<std::uint8_t>(cut >> 8);
    b[2] = static_cast<std::uint8_t>(cut);
    const BlockResult r = read_block(b);
    REQUIRE(r.open == Status::kOk);
    const bool at_boundary = std::find(boundaries.begin(), boundaries.end(), cut) != boundaries.end();
    INFO("cut " << cut);
    REQUIRE_FALSE(r.statuses.empty());
    CHECK((r.statuses.back() == Status::kMalformedFrame) == !at_boundary);
    std::size_t plots_out = 0;
    for (std::size_t i = 0; i < r.statuses.size(); ++i) {
      if (r.statuses[i] == Status::kOk) plots_out += r.frames[i].count;
    }
    // The whole records before the cut, and only those.
    std::size_t whole = 0;
    while (whole + 1 < boundaries.size() && boundaries[whole + 1] <= cut) ++whole;
    CHECK(plots_out == whole);
  }
}

SCENARIO("plots of a malformed block read before the bad record are delivered first", "[hal][asterix]") {
  const Bytes good = kestrel::test::cat048_record(plot(3, 256, 0));
  const Bytes bad{0xF0, 0, 1};  // announces 010, 140, 020 and 040: cut in 140
  const BlockResult r = read_block(kestrel::test::asterix_block(48, {good, good, bad}));
  REQUIRE(r.statuses == std::vector<Status>{Status::kOk, Status::kMalformedFrame});
  CHECK(r.frames[0].count == 2);
  CHECK(r.frames[1].count == 0);
}

SCENARIO("more plots at one time than a frame holds keep the first ones", "[hal][asterix]") {
  std::vector<Cat048PlotSpec> plots;
  for (std::uint16_t i = 0; i < kestrel::hal::kMaxRadarPlots + 8; ++i) plots.push_back(plot(7, static_cast<std::uint16_t>(100 + i), 0));
  plots.push_back(plot(8, 50, 0));
  Cat048Reader reader;
  std::size_t len = 0;
  const Bytes block = kestrel::test::cat048_block(plots);
  REQUIRE(reader.open(block, len) == Status::kOk);
  Frame f{};
  REQUIRE(reader.next(f) == Status::kTooManyCandidates);
  CHECK(f.count == kestrel::hal::kMaxRadarPlots);
  CHECK(f.radar[0].range_mm == kestrel::hal::asterix::range_mm_from_rho(100));
  CHECK(f.radar[31].range_mm == kestrel::hal::asterix::range_mm_from_rho(131));
  CHECK(reader.counters().dropped_over_capacity == 8);
  THEN("the next time's plots are the next frame") {
    REQUIRE(reader.next(f) == Status::kOk);
    CHECK(f.count == 1);
    CHECK(f.radar[0].range_mm == kestrel::hal::asterix::range_mm_from_rho(50));
    CHECK(reader.next(f) == Status::kNoData);
  }
}

SCENARIO("a CAT048 frame goes through the radar adapter into a scan", "[hal][asterix]") {
  const Bytes block = kestrel::test::cat048_block({plot(128 * 3600, 2560, 0x0000), plot(128 * 3600, 1280, 0xC000)});
  Cat048Reader reader;
  std::size_t len = 0;
  REQUIRE(reader.open(block, len) == Status::kOk);
  Frame f{};
  kestrel::MeasurementScan<double, 2, 8> scan;
  {
    kestrel::test::AllocationGuard guard;
    REQUIRE(reader.next(f) == Status::kOk);
    REQUIRE(kestrel::hal::RadarAdapter{}(f, scan) == Status::kOk);
    CHECK(guard.allocations() == 0);
  }
  REQUIRE(scan.count == 2);
  CHECK(scan.t_us == 3'600'000'000);
  // 10 NM north: bearing +pi/2; 5 NM west: bearing -pi. Exact in double.
  CHECK(scan.z[0](0) == Approx(18'520.0).margin(1e-9));
  CHECK(scan.z[0](1) == Approx(3.14159265358979323846 / 2).margin(1e-12));
  CHECK(scan.z[1](0) == Approx(9'260.0).margin(1e-9));
  CHECK(scan.z[1](1) == Approx(-3.14159265358979323846).margin(1e-12));
}
