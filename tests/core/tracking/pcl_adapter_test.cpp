// SPDX-License-Identifier: Apache-2.0
// The PCL front end (kestrel/hal/pcl_adapter.hpp), tested here beside the
// tracker it ranks against: wire units to [Rb, dRb] (sign and magnitude of
// dRb = -lambda fD), wrong kind and malformed counts, and the over-capacity
// rule (farthest from every track first, then lowest SNR, then latest),
// allocation-free.
#include <catch2/catch.hpp>
#include <cstring>

#include "kestrel/hal/pcl_adapter.hpp"
#include "kestrel/tracking/pcl_tracker.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::Status;
using kestrel::hal::Frame;
using kestrel::hal::FrameKind;
using kestrel::hal::PclCandidate;
using PclT = kestrel::PclTracker<kestrel::PclKf<double>, kestrel::kPclMaxTracks, kestrel::kPclMaxCandidates>;
using Scan = PclT::Scan;

Frame pcl_frame(std::int64_t t_us) {
  Frame f;
  std::memset(&f, 0, sizeof f);
  f.kind = FrameKind::kPcl;
  f.t_us = t_us;
  f.count = 0;
  return f;
}

void add(Frame& f, std::uint32_t rb_mm, std::int32_t fd_mhz, std::int16_t snr_cdb) {
  f.pcl[f.count++] = PclCandidate{rb_mm, fd_mhz, snr_cdb};
}

const double kLambda = 299792458.0 / 701.0e6;

/// Doppler in mHz of a range rate in m/s (rounded).
std::int32_t fd_mhz(double range_rate_mps) {
  return static_cast<std::int32_t>(std::lround(-range_rate_mps / kLambda * 1000.0));
}

}  // namespace

SCENARIO("a PCL frame becomes [Rb m, dRb m/s] with dRb = -lambda fD", "[pcl][adapter]") {
  Frame f = pcl_frame(1500000);
  add(f, 1234567, 28062, 1200);    // 1234.567 m, +28.062 Hz: closing at 12 m/s
  add(f, 0, -122000, 900);         // on the baseline, opening at 52 m/s
  add(f, 4000000000u, 0, -50);     // far, zero Doppler
  GIVEN("a double scan") {
    Scan scan;
    REQUIRE(kestrel::hal::to_pcl_scan(f, kestrel::wavelength_m(701.0e6), scan) == Status::kOk);
    THEN("every candidate is converted, in frame order") {
      REQUIRE(scan.count == 3);
      CHECK(scan.t_us == 1500000);
      CHECK(scan.z[0](0) == Approx(1234.567).epsilon(1e-15));
      CHECK(scan.z[0](1) == Approx(-28.062 * kLambda).epsilon(1e-12));
      CHECK(scan.z[0](1) == Approx(-12.0).epsilon(1e-4));
      CHECK(scan.z[1](0) == 0.0);
      CHECK(scan.z[1](1) == Approx(122.0 * kLambda).epsilon(1e-12));
      CHECK(scan.z[2](0) == Approx(4.0e6).epsilon(1e-15));
      CHECK(scan.z[2](1) == 0.0);
    }
  }
  GIVEN("a float scan through the Runner adapter object") {
    using PclF = kestrel::PclTracker<kestrel::PclKf<float>, 16, 8>;
    const kestrel::hal::PclAdapter<PclF> adapter(nullptr, kestrel::hal::PclAdapterParams{});
    PclF::Scan scan;
    REQUIRE(adapter(f, scan) == Status::kOk);
    THEN("the same values to float precision") {
      CHECK(static_cast<double>(adapter.lambda_m()) == Approx(kLambda).epsilon(1e-7));
      REQUIRE(scan.count == 3);
      CHECK(static_cast<double>(scan.z[0](1)) == Approx(-28.062 * kLambda).epsilon(1e-6));
    }
  }
}

SCENARIO("frames that are not PCL, or announce more than 64 candidates, leave the scan untouched",
         "[pcl][adapter][status]") {
  Scan scan;
  scan.t_us = 7;
  scan.count = 1;
  scan.z[0] = kestrel::Vec<double, 2>(1.0, 2.0);
  Frame f = pcl_frame(1000);
  add(f, 1000, 1000, 0);
  WHEN("the frame is a radar frame") {
    f.kind = FrameKind::kRadar;
    CHECK(kestrel::hal::to_pcl_scan(f, kLambda, scan) == Status::kWrongKind);
  }
  WHEN("the count exceeds the frame capacity") {
    f.count = kestrel::hal::kMaxPclCandidates + 1;
    CHECK(kestrel::hal::to_pcl_scan(f, kLambda, scan) == Status::kMalformedFrame);
  }
  THEN("the scan is as before") {
    CHECK(scan.t_us == 7);
    CHECK(scan.count == 1);
    CHECK(scan.z[0] == kestrel::Vec<double, 2>(1.0, 2.0));
  }
}

SCENARIO("an over-capacity frame without tracks drops the lowest SNR first, then the latest",
         "[pcl][adapter][capacity]") {
  Frame f = pcl_frame(0);
  // 40 candidates; SNR 100 + j, except candidates 5, 6, 7 at SNR 0 and
  // candidates 30..39 all at SNR 50 (ties broken by frame order).
  for (int j = 0; j < 40; ++j) {
    std::int16_t snr = static_cast<std::int16_t>(100 + j);
    if (j >= 5 && j <= 7) snr = 0;
    if (j >= 30) snr = 50;
    add(f, static_cast<std::uint32_t>(100000 + 1000 * j), 10000, snr);
  }
  Scan scan;
  REQUIRE(kestrel::hal::to_pcl_scan(f, kLambda, scan) == Status::kTooManyCandidates);
  THEN("32 are kept in frame order: 5, 6, 7 and the last five of the SNR-50 ties are gone") {
    REQUIRE(scan.count == 32);
    int expected[32];
    int n = 0;
    for (int j = 0; j < 40; ++j) {
      if ((j >= 5 && j <= 7) || j >= 35) continue;
      expected[n++] = j;
    }
    REQUIRE(n == 32);
    for (int i = 0; i < 32; ++i) CHECK(scan.z[i](0) == Approx(100.0 + expected[i]));
  }
}

SCENARIO("an over-capacity frame drops the candidates farthest from every track first", "[pcl][adapter][capacity]") {
  auto tracker = kestrel::make_pcl_tracker<double>(kestrel::PclTrackerParams{});
  const kestrel::hal::PclAdapter<PclT> adapter(&tracker, kestrel::hal::PclAdapterParams{});
  // A confirmed track closing at 12 m/s from 1500 m.
  auto truth = [](int k) { return 1500.0 - 6.0 * k; };
  for (int k = 0; k < 6; ++k) {
    Frame f = pcl_frame(k * 500000LL);
    add(f, static_cast<std::uint32_t>(truth(k) * 1000.0), fd_mhz(-12.0), 1000);
    Scan scan;
    REQUIRE(adapter(f, scan) == Status::kOk);
    REQUIRE(tracker.step(scan) == Status::kOk);
  }
  REQUIRE(tracker.reports().size() == 1);

  // Frame 6: the target's detection has the lowest SNR of all and comes last;
  // 40 clutter candidates, 20 of them near the track (within 60 m and a
  // Doppler within 10 Hz), 20 far from it.
  Frame f = pcl_frame(6 * 500000LL);
  for (int j = 0; j < 20; ++j) {
    add(f, static_cast<std::uint32_t>((truth(6) + 3.0 * j - 31.0) * 1000.0), fd_mhz(-12.0) + 500 * (j % 5), 2000);
  }
  for (int j = 0; j < 20; ++j) {
    add(f, static_cast<std::uint32_t>((2500.0 + 10.0 * j) * 1000.0), 60000, 3000);
  }
  add(f, static_cast<std::uint32_t>(truth(6) * 1000.0), fd_mhz(-12.0), -100);
  REQUIRE(f.count == 41);
  Scan scan;
  std::size_t allocations = 0;
  Status s = Status::kOk;
  {
    kestrel::test::AllocationGuard guard;
    s = adapter(f, scan);
    allocations = guard.allocations();
  }
  THEN("the 9 dropped are far clutter; the target's detection and the near ones stay") {
    CHECK(s == Status::kTooManyCandidates);
    CHECK(allocations == 0);
    REQUIRE(scan.count == 32);
    CHECK(scan.z[31](0) == Approx(truth(6)));
    int far = 0;
    for (std::size_t i = 0; i < scan.count; ++i) far += scan.z[i](0) >= 2500.0 ? 1 : 0;
    CHECK(far == 11);
    AND_THEN("the tracker takes the target's detection from the trimmed scan") {
      REQUIRE(tracker.step(scan) == Status::kOk);
      REQUIRE(tracker.reports().size() == 1);
      CHECK(tracker.reports()[0].measurement_index == 31);
    }
  }
}
