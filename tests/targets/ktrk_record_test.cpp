// SPDX-License-Identifier: Apache-2.0
// KTRK v2 (targets/common/include/kestrel/board/ktrk_record.hpp) against the
// layout its header documents: every field at its offset for a Cartesian CA
// radar report, a Cartesian CV report and a bistatic PCL report, in double,
// float and Q31.32, and the CRC. The two golden records at the end are the
// bytes tests/targets/ktrk_decode_test.py feeds tools/ktrk_decode.py, so
// encoder and decoder are held to the same bytes.
#include "kestrel/board/ktrk_record.hpp"

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <string>

#include "kestrel/hal/crc32.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/tracking/pcl_tracker.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace {

using kestrel::TrackReport;
using kestrel::TrackStatus;
using kestrel::board::StateLayout;
namespace rr = kestrel::board::report_record;
namespace w = kestrel::hal::wire;
using Record = std::array<std::uint8_t, rr::kSize>;

template <class Filter>
Record encode(const TrackReport<Filter>& r) {
  Record out{};
  out.fill(0xA5);  // every byte must be written
  kestrel::board::encode_track_record(r, std::span<std::uint8_t, rr::kSize>(out));
  return out;
}

std::span<const std::uint8_t> view(const Record& r) { return {r.data(), r.size()}; }
std::int32_t component(const Record& r, std::size_t k) {
  return w::load_i32(view(r), rr::kComponentsOffset + 4 * k);
}

std::string hex(const Record& r) {
  std::string s;
  char b[3];
  for (const std::uint8_t v : r) {
    std::snprintf(b, sizeof b, "%02x", v);
    s += b;
  }
  return s;
}

/// Common fields every test report carries.
template <class Filter>
void fill_common(TrackReport<Filter>& r) {
  using T = kestrel::ScalarTraits<typename Filter::Scalar>;
  r.t_us = 1'234'567'890'123;
  r.track_id = 0x01020304u;
  r.status = TrackStatus::kConfirmed;
  r.associated = true;
  r.age = 300;
  r.hits = 250;
  r.misses = 2;
  r.measurement_index = 17;
  r.nis = T::from_double(1.5);
}

void check_common(const Record& b, StateLayout layout, std::uint8_t count) {
  const auto v = view(b);
  CHECK(w::load_u32(v, 0) == rr::kMagic);
  CHECK(b[0] == 'K');
  CHECK(b[3] == 'K');
  CHECK(b[4] == 2);
  CHECK(b[5] == static_cast<std::uint8_t>(TrackStatus::kConfirmed));
  CHECK(b[6] == 1);
  CHECK(b[7] == static_cast<std::uint8_t>(layout));
  CHECK(w::load_u32(v, 8) == 0x01020304u);
  CHECK(w::load_i64(v, 12) == 1'234'567'890'123);
  CHECK(w::load_u16(v, 48) == 300);
  CHECK(w::load_u16(v, 50) == 250);
  CHECK(w::load_u16(v, 52) == 2);
  CHECK(w::load_i16(v, 54) == 17);
  CHECK(w::load_u16(v, 56) == 150);
  CHECK(b[58] == count);
  CHECK(b[59] == 0);
  for (std::size_t k = count; k < rr::kMaxComponents; ++k) CHECK(component(b, k) == 0);
  CHECK(w::load_u32(v, rr::kCrcOffset) == kestrel::hal::crc32(v.first(rr::kCrcOffset)));
}

/// A CA radar report with values every scalar represents exactly.
template <class Scalar>
TrackReport<kestrel::EkfCa<Scalar>> ca_report() {
  using T = kestrel::ScalarTraits<Scalar>;
  using L = typename kestrel::EkfCa<Scalar>::Layout;
  TrackReport<kestrel::EkfCa<Scalar>> r;
  fill_common(r);
  r.x(L::kX) = T::from_double(1234.5);
  r.x(L::kY) = T::from_double(-987.25);
  r.x(L::kVx) = T::from_double(-12.375);
  r.x(L::kVy) = T::from_double(7.0);
  r.x(L::kAx) = T::from_double(0.5);
  r.x(L::kAy) = T::from_double(-0.25);
  r.P(L::kX, L::kX) = T::from_double(9.0);
  r.P(L::kY, L::kY) = T::from_double(16.0);
  r.P(L::kVx, L::kVx) = T::from_double(100.0);  // not part of the sigma
  return r;
}

template <class Scalar>
TrackReport<kestrel::PclKf<Scalar>> pcl_report() {
  using T = kestrel::ScalarTraits<Scalar>;
  using L = typename kestrel::PclKf<Scalar>::Layout;
  TrackReport<kestrel::PclKf<Scalar>> r;
  fill_common(r);
  r.x(L::kRb) = T::from_double(45678.25);
  r.x(L::kDRb) = T::from_double(-123.5);
  r.P(L::kRb, L::kRb) = T::from_double(100.0);
  r.P(L::kDRb, L::kDRb) = T::from_double(4.0);  // not part of the sigma
  return r;
}

void check_ca(const Record& b) {
  check_common(b, StateLayout::kCartesian2dCa, 6);
  CHECK(component(b, 0) == 1'234'500);
  CHECK(component(b, 1) == -987'250);
  CHECK(component(b, 2) == -12'375);
  CHECK(component(b, 3) == 7'000);
  CHECK(component(b, 4) == 500);
  CHECK(component(b, 5) == -250);
  CHECK(w::load_u32(view(b), 44) == 5'000);  // sqrt(9 + 16) m
}

void check_pcl(const Record& b) {
  check_common(b, StateLayout::kBistatic1d, 2);
  CHECK(component(b, 0) == 45'678'250);
  CHECK(component(b, 1) == -123'500);
  CHECK(w::load_u32(view(b), 44) == 10'000);  // sqrt(var Rb) = 10 m
}

// Printed by hand once and pasted into tests/targets/ktrk_decode_test.py.
constexpr const char* kGoldenCa =
    "4b54524b0202010204030201cb04fb711f01000044d612008eeff0ffa9cfffff581b0000f401000006ffffff88130000"
    "2c01fa000200110096000600b362bd7b";
constexpr const char* kGoldenPcl =
    "4b54524b0202010304030201cb04fb711f010000aafeb802941dfeff0000000000000000000000000000000010270000"
    "2c01fa0002001100960002005045ca7a";

}  // namespace

TEST_CASE("KTRK v2 puts a CA radar state in layout 2, six components", "[board][ktrk]") {
  const Record d = encode(ca_report<double>());
  check_ca(d);
  CHECK(hex(d) == kGoldenCa);
  SECTION("float and Q31.32 give the same bytes for the same (exact) values") {
    CHECK(encode(ca_report<float>()) == d);
    CHECK(encode(ca_report<kestrel::Q31_32>()) == d);
  }
}

TEST_CASE("KTRK v2 puts a PCL state in layout 3: Rb and its rate, sigma of Rb", "[board][ktrk]") {
  const Record d = encode(pcl_report<double>());
  check_pcl(d);
  CHECK(hex(d) == kGoldenPcl);
  CHECK(kestrel::board::kRecordLayout<kestrel::PclKf<double>> == StateLayout::kBistatic1d);
  SECTION("a float tracker rounds in float: Rb beyond 16.7 km to float's 4 mm spacing at 45 km") {
    const Record f = encode(pcl_report<float>());
    check_common(f, StateLayout::kBistatic1d, 2);
    CHECK(component(f, 0) == 45'678'248);
    CHECK(component(f, 1) == -123'500);
  }
}

TEST_CASE("KTRK v2 puts a CV state in layout 1, four components", "[board][ktrk]") {
  using Motion = kestrel::ConstantVelocity2D<double>;
  using Filter = kestrel::Ekf<Motion, kestrel::PolarRadar<Motion>>;
  using L = Filter::Layout;
  TrackReport<Filter> r;
  fill_common(r);
  r.x(L::kX) = 1.0;
  r.x(L::kY) = 2.0;
  r.x(L::kVx) = 3.0;
  r.x(L::kVy) = -4.0;
  r.P(L::kX, L::kX) = 0.09;
  r.P(L::kY, L::kY) = 0.16;
  const Record b = encode(r);
  check_common(b, StateLayout::kCartesian2dCv, 4);
  CHECK(component(b, 0) == 1000);
  CHECK(component(b, 1) == 2000);
  CHECK(component(b, 2) == 3000);
  CHECK(component(b, 3) == -4000);
  CHECK(w::load_u32(view(b), 44) == 500);
}

TEST_CASE("KTRK v2 saturates and marks NaN per component", "[board][ktrk]") {
  auto r = pcl_report<double>();
  r.x(0) = std::numeric_limits<double>::quiet_NaN();
  r.x(1) = 3.0e7;  // 3e10 mm/s: beyond int32
  r.P(0, 0) = std::numeric_limits<double>::quiet_NaN();
  const Record b = encode(r);
  CHECK(component(b, 0) == INT32_MIN);
  CHECK(component(b, 1) == INT32_MAX);
  CHECK(w::load_u32(view(b), 44) == UINT32_MAX);
  CHECK(w::load_u32(view(b), rr::kCrcOffset) == kestrel::hal::crc32(view(b).first(rr::kCrcOffset)));
}
