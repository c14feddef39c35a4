// SPDX-License-Identifier: Apache-2.0
// CAT062 writer (asterix_cat062.hpp): a block compared byte for byte with
// one written by hand from the specification's layouts, a tracker report
// turned into a record, a round trip through an independent test-side
// decoder, and every refusal (range, non-finite, buffer size).
#include "kestrel/hal/asterix_cat062.hpp"

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "kestrel/tracking/radar_tracker.hpp"
#include "support/alloc_guard.hpp"

using kestrel::Status;
using kestrel::hal::asterix::Cat062Source;
using kestrel::hal::asterix::Cat062Track;
using kestrel::hal::asterix::encode_cat062;
using kestrel::hal::asterix::to_cat062;
using Bytes = std::vector<std::uint8_t>;
using Report = kestrel::TrackReport<kestrel::EkfCa<double>>;
using Layout = kestrel::CaMotion<double>::Layout;

namespace {

Cat062Track sample_track() {
  Cat062Track t;
  t.tod_128 = 5'529'664;   // 43200.5 s
  t.x_half_m = -2;         // -1 m
  t.y_half_m = 0x012345;   // 37282.5 m
  t.vx_quarter_mps = -4;   // -1 m/s
  t.vy_quarter_mps = 256;  // 64 m/s
  t.track_number = 0x0102;
  t.tentative = true;
  t.apc_x_half_m = 10;      // 5 m
  t.apc_y_half_m = 0x0203;  // 257.5 m
  return t;
}

Bytes encode(const Cat062Source& src, const std::vector<Cat062Track>& tracks, std::size_t capacity = 4096) {
  Bytes out(capacity, 0xEE);
  std::size_t written = 99;
  const Status s = encode_cat062(src, tracks, out, written);
  REQUIRE(s == Status::kOk);
  out.resize(written);
  return out;
}

std::int32_t signed_be(const Bytes& b, std::size_t at, int bytes) {
  std::uint32_t u = 0;
  for (int i = 0; i < bytes; ++i) u = (u << 8) | b[at + static_cast<std::size_t>(i)];
  const std::uint32_t sign = 1u << (8 * bytes - 1);
  return static_cast<std::int32_t>(u ^ sign) - static_cast<std::int32_t>(sign);
}
std::uint32_t unsigned_be(const Bytes& b, std::size_t at, int bytes) {
  std::uint32_t u = 0;
  for (int i = 0; i < bytes; ++i) u = (u << 8) | b[at + static_cast<std::size_t>(i)];
  return u;
}

// An independent reading of the records this writer produces: the FSPEC
// is taken bit by bit, so a wrong FRN order or length fails the round trip.
std::vector<Cat062Track> decode_block(const Bytes& b, Cat062Source& src) {
  std::vector<Cat062Track> out;
  REQUIRE(b.size() >= 3);
  REQUIRE(b[0] == 62);
  REQUIRE(unsigned_be(b, 1, 2) == b.size());
  std::size_t pos = 3;
  while (pos < b.size()) {
    std::array<std::uint8_t, 4> fs{};
    std::size_t n = 0;
    do {
      REQUIRE(n < fs.size());
      fs[n] = b[pos++];
    } while ((fs[n++] & 1u) != 0);
    const auto has = [&](int frn) {
      const auto o = static_cast<std::size_t>((frn - 1) / 7);
      return o < n && (fs[o] & (0x80u >> ((frn - 1) % 7))) != 0;
    };
    Cat062Track t;
    REQUIRE(has(1));
    src.sac = b[pos];
    src.sic = b[pos + 1];
    pos += 2;
    src.has_service_id = has(3);
    if (has(3)) src.service_id = b[pos++];
    REQUIRE(has(4));
    t.tod_128 = unsigned_be(b, pos, 3);
    pos += 3;
    CHECK_FALSE(has(5));
    REQUIRE(has(6));
    t.x_half_m = signed_be(b, pos, 3);
    t.y_half_m = signed_be(b, pos + 3, 3);
    pos += 6;
    REQUIRE(has(7));
    t.vx_quarter_mps = signed_be(b, pos, 2);
    t.vy_quarter_mps = signed_be(b, pos + 2, 2);
    pos += 4;
    REQUIRE(has(12));
    t.track_number = unsigned_be(b, pos, 2);
    pos += 2;
    REQUIRE(has(13));
    CHECK((b[pos] & 0x81u) == 0x80u);  // MON set, FX clear
    t.tentative = (b[pos] & 0x02u) != 0;
    pos += 1;
    REQUIRE(has(27));
    CHECK(b[pos] == 0x80);  // APC only
    t.apc_x_half_m = unsigned_be(b, pos + 1, 2);
    t.apc_y_half_m = unsigned_be(b, pos + 3, 2);
    pos += 5;
    out.push_back(t);
  }
  REQUIRE(pos == b.size());
  return out;
}

bool same(const Cat062Track& a, const Cat062Track& b) {
  return a.tod_128 == b.tod_128 && a.x_half_m == b.x_half_m && a.y_half_m == b.y_half_m &&
         a.vx_quarter_mps == b.vx_quarter_mps && a.vy_quarter_mps == b.vy_quarter_mps &&
         a.track_number == b.track_number && a.tentative == b.tentative && a.apc_x_half_m == b.apc_x_half_m &&
         a.apc_y_half_m == b.apc_y_half_m;
}

Report sample_report() {
  Report r;
  r.t_us = 43'200'500'000;  // 12:00:00.5
  r.track_id = 77;
  r.status = kestrel::TrackStatus::kConfirmed;
  r.x.setZero();
  r.x(Layout::kX) = 1500.0;
  r.x(Layout::kY) = -2500.5;
  r.x(Layout::kVx) = 120.25;
  r.x(Layout::kVy) = -33.5;
  r.P.setIdentity();
  r.P(Layout::kX, Layout::kX) = 100.0;  // sigma 10 m
  r.P(Layout::kY, Layout::kY) = 6.25;   // sigma 2.5 m
  return r;
}

}  // namespace

SCENARIO("a CAT062 block matches one written by hand from the specification", "[hal][asterix]") {
  Cat062Source src;
  src.sac = 7;
  src.sic = 42;
  GIVEN("a service identification") {
    src.has_service_id = true;
    src.service_id = 5;
    const Bytes expected{0x3E, 0x00, 0x1F,        // CAT 62, LEN 31
                         0xB7, 0x0D, 0x01, 0x04,  // FSPEC: FRN 1 3 4 6 7 / 12 13 / - / 27
                         0x07, 0x2A,              // I062/010
                         0x05,                    // I062/015
                         0x54, 0x60, 0x40,        // I062/070
                         0xFF, 0xFF, 0xFE, 0x01, 0x23, 0x45,  // I062/100
                         0xFF, 0xFC, 0x01, 0x00,              // I062/185
                         0x01, 0x02,                          // I062/040
                         0x82,                                // I062/080 MON, CNF tentative
                         0x80, 0x00, 0x0A, 0x02, 0x03};       // I062/500 APC
    CHECK(encode(src, {sample_track()}) == expected);
  }
  GIVEN("no service identification") {
    const Bytes b = encode(src, {sample_track()});
    CHECK(b.size() == 30);
    CHECK(b[3] == 0x97);  // FRN 3 bit cleared
    CHECK(b[9] == 0x54);  // I062/070 follows I062/010 directly
  }
}

SCENARIO("a tracker report becomes a CAT062 record", "[hal][asterix]") {
  Cat062Track t;
  REQUIRE(to_cat062(sample_report(), t) == Status::kOk);
  CHECK(t.tod_128 == 5'529'664);
  CHECK(t.x_half_m == 3000);
  CHECK(t.y_half_m == -5001);
  CHECK(t.vx_quarter_mps == 481);
  CHECK(t.vy_quarter_mps == -134);
  CHECK(t.track_number == 77);
  CHECK_FALSE(t.tentative);
  CHECK(t.apc_x_half_m == 20);
  CHECK(t.apc_y_half_m == 5);
  WHEN("the track is tentative") {
    Report r = sample_report();
    r.status = kestrel::TrackStatus::kTentative;
    REQUIRE(to_cat062(r, t) == Status::kOk);
    THEN("CNF says so") { CHECK(t.tentative); }
  }
}

SCENARIO("values outside their CAT062 item are refused not clamped", "[hal][asterix]") {
  Cat062Track t = sample_track();
  const Cat062Track before = t;
  const auto refused = [&](const Report& r) {
    const Status s = to_cat062(r, t);
    CHECK(same(t, before));  // untouched
    return s;
  };
  Report r = sample_report();
  r.x(Layout::kX) = 4'194'304.0;  // 2^23 x 0.5 m
  CHECK(refused(r) == Status::kOutOfRange);
  r = sample_report();
  r.x(Layout::kY) = -4'194'304.5;
  CHECK(refused(r) == Status::kOutOfRange);
  r = sample_report();
  r.x(Layout::kVx) = 8192.0;  // 2^15 x 0.25 m/s
  CHECK(refused(r) == Status::kOutOfRange);
  r = sample_report();
  r.P(Layout::kY, Layout::kY) = 32768.0 * 32768.0;  // sigma past 65535 x 0.5 m
  CHECK(refused(r) == Status::kOutOfRange);
  r = sample_report();
  r.track_id = 65'536;
  CHECK(refused(r) == Status::kOutOfRange);
  r = sample_report();
  r.t_us = -1;
  CHECK(refused(r) == Status::kOutOfRange);
  r.t_us = 86'400'000'000 - 1000;  // rounds to 86400 s, not a time of day
  CHECK(refused(r) == Status::kOutOfRange);
  r = sample_report();
  r.x(Layout::kVy) = std::numeric_limits<double>::quiet_NaN();
  CHECK(refused(r) == Status::kNonFinite);
  r = sample_report();
  r.P(Layout::kX, Layout::kX) = -1.0;
  CHECK(refused(r) == Status::kNonFinite);

  GIVEN("the largest values each item holds") {
    r = sample_report();
    r.x(Layout::kX) = 4'194'303.5;
    r.x(Layout::kY) = -4'194'304.0;
    r.x(Layout::kVx) = 8191.75;
    r.x(Layout::kVy) = -8192.0;
    r.P(Layout::kX, Layout::kX) = 32767.5 * 32767.5;
    r.track_id = 65'535;
    REQUIRE(to_cat062(r, t) == Status::kOk);
    THEN("they are written exactly") {
      const Bytes b = encode(Cat062Source{}, {t});
      Cat062Source src;
      const std::vector<Cat062Track> back = decode_block(b, src);
      REQUIRE(back.size() == 1);
      CHECK(back[0].x_half_m == 8'388'607);
      CHECK(back[0].y_half_m == -8'388'608);
      CHECK(back[0].vx_quarter_mps == 32'767);
      CHECK(back[0].vy_quarter_mps == -32'768);
      CHECK(back[0].apc_x_half_m == 65'535);
      CHECK(back[0].track_number == 65'535);
    }
  }
  GIVEN("a record filled by hand past an item") {
    Cat062Track bad = sample_track();
    bad.x_half_m = 1 << 23;
    Bytes out(100, 0xEE);
    std::size_t written = 5;
    CHECK(encode_cat062(Cat062Source{}, std::vector<Cat062Track>{bad}, out, written) == Status::kOutOfRange);
    CHECK(written == 0);
    CHECK(out == Bytes(100, 0xEE));
    bad = sample_track();
    bad.tod_128 = 86'400u * 128u;
    CHECK(encode_cat062(Cat062Source{}, std::vector<Cat062Track>{bad}, out, written) == Status::kOutOfRange);
    bad = sample_track();
    bad.apc_y_half_m = 65'536;
    CHECK(encode_cat062(Cat062Source{}, std::vector<Cat062Track>{bad}, out, written) == Status::kOutOfRange);
  }
  GIVEN("more records than LEN can count") {
    const std::vector<Cat062Track> many(65'535 / 27 + 1, sample_track());
    Bytes out(70'000);
    std::size_t written = 5;
    CHECK(encode_cat062(Cat062Source{}, many, out, written) == Status::kOutOfRange);
    CHECK(written == 0);
  }
}

SCENARIO("a CAT062 block that does not fit its buffer is refused untouched", "[hal][asterix]") {
  const std::vector<Cat062Track> tracks{sample_track(), sample_track()};
  const std::size_t size = 3 + 2 * 27;
  for (std::size_t cap = 0; cap < size; ++cap) {
    Bytes out(cap, 0xEE);
    std::size_t written = 5;
    CHECK(encode_cat062(Cat062Source{}, tracks, out, written) == Status::kBufferTooSmall);
    CHECK(written == 0);
    CHECK(out == Bytes(cap, 0xEE));
  }
  Bytes out(size);
  std::size_t written = 0;
  CHECK(encode_cat062(Cat062Source{}, tracks, out, written) == Status::kOk);
  CHECK(written == size);
}

SCENARIO("random CAT062 records round-trip through an independent decoder", "[hal][asterix]") {
  std::mt19937 rng(62);
  for (int round = 0; round < 200; ++round) {
    Cat062Source src;
    src.sac = static_cast<std::uint8_t>(rng());
    src.sic = static_cast<std::uint8_t>(rng());
    src.has_service_id = rng() % 2 == 0;
    src.service_id = static_cast<std::uint8_t>(rng());
    std::vector<Cat062Track> tracks(rng() % 5);
    for (Cat062Track& t : tracks) {
      t.tod_128 = static_cast<std::uint32_t>(rng() % (86'400u * 128u));
      t.x_half_m = static_cast<std::int32_t>(rng() % (1u << 24)) - (1 << 23);
      t.y_half_m = static_cast<std::int32_t>(rng() % (1u << 24)) - (1 << 23);
      t.vx_quarter_mps = static_cast<std::int32_t>(rng() % (1u << 16)) - (1 << 15);
      t.vy_quarter_mps = static_cast<std::int32_t>(rng() % (1u << 16)) - (1 << 15);
      t.track_number = rng() % 65'536u;
      t.tentative = rng() % 2 == 0;
      t.apc_x_half_m = rng() % 65'536u;
      t.apc_y_half_m = rng() % 65'536u;
    }
    Bytes out(4096);
    std::size_t written = 0;
    {
      kestrel::test::AllocationGuard guard;
      REQUIRE(encode_cat062(src, tracks, out, written) == Status::kOk);
      REQUIRE(guard.allocations() == 0);
    }
    out.resize(written);
    Cat062Source src_back;
    const std::vector<Cat062Track> back = decode_block(out, src_back);
    REQUIRE(back.size() == tracks.size());
    if (!tracks.empty()) {  // the source is in each record
      CHECK(src_back.sac == src.sac);
      CHECK(src_back.sic == src.sic);
      CHECK(src_back.has_service_id == src.has_service_id);
    }
    for (std::size_t i = 0; i < tracks.size(); ++i) CHECK(same(back[i], tracks[i]));
  }
}
