// SPDX-License-Identifier: Apache-2.0
// Channel-gated EKF (docs/filters.md and docs/tracking.md, paper 003 section 3.3.3): with every
// channel it is the EKF; with a subset it equals a reduced-dimension update
// (a removed channel is removed, not zeroed); the per-channel gate drops an
// injected outlier and keeps the good channels; predict-only when every
// channel is gated; the ellipsoidal option; bad input leaves the state
// unchanged; one linearisation narrowed to a subset is, bit for bit, the
// linearisation of that subset; no allocation; the chi-square rows it needs.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>

#include <Eigen/Dense>

#include "kestrel/association/chi_square.hpp"
#include "kestrel/filters/channel_gated_ekf.hpp"
#include "kestrel/filters/ekf.hpp"
#include "kestrel/models/measurement/multipath_toa.hpp"
#include "kestrel/models/motion/constant_velocity_3d_sound_speed.hpp"
#include "support/alloc_guard.hpp"

namespace {

using kestrel::ChannelMask;
using kestrel::Status;
using Motion = kestrel::ConstantVelocity3DSoundSpeed<double>;
using Toa = kestrel::MultipathToa<Motion, 4>;
using Filter = kestrel::ChannelGatedEkf<Motion, Toa>;
using PlainEkf = kestrel::Ekf<Motion, Toa>;

Toa sonar_model() {
  Toa toa;
  toa.config.beacon_count = 4;
  toa.config.beacons_m[0] = Toa::Position(0, 0, 0);
  toa.config.beacons_m[1] = Toa::Position(2000, 0, 0);
  toa.config.beacons_m[2] = Toa::Position(0, 2000, 0);
  toa.config.beacons_m[3] = Toa::Position(2000, 2000, 0);
  toa.config.seabed_depth_m = 150;
  toa.config.sigma_toa_s = 3e-3;
  return toa;
}

Motion sonar_motion() {
  Motion m;
  m.accel_sigma_mps2 = 0.05;
  m.sound_speed_q_m2ps3 = 0.01;
  return m;
}

Motion::State truth_state() {
  Motion::State x;
  x << 500, 800, 60, 1.2, 1.0, -0.2, 1500.8;
  return x;
}

/// A filter whose estimate is off the truth by a few metres, with a
/// covariance that has the position / sound-speed correlations of a real run.
template <class F>
F offset_filter() {
  F f(sonar_motion(), sonar_model());
  Motion::State x0 = truth_state();
  x0(0) += 6;
  x0(1) -= 4;
  x0(2) += 9;
  x0(6) = 1500;
  Motion::Cov P0 = Motion::Cov::Identity();
  P0.diagonal() << 100, 100, 225, 4, 4, 1, 1;
  P0(0, 6) = P0(6, 0) = 3;
  P0(2, 6) = P0(6, 2) = -4;
  REQUIRE(f.reset(x0, P0) == Status::kOk);
  return f;
}

/// Textbook EKF update with only the listed channels, in dynamic Eigen:
/// the reference for "removed from the update".
void reference_update(const Filter& f, const Toa::Measurement& z, ChannelMask keep, Eigen::VectorXd& x,
                      Eigen::MatrixXd& P) {
  const Toa& toa = f.measurement();
  int m = 0;
  for (int i = 0; i < Toa::kMeasDim; ++i) m += kestrel::has_channel(keep, i) ? 1 : 0;
  Eigen::MatrixXd H(m, 7);
  Eigen::VectorXd nu(m);
  const Toa::Jacobian Hf = toa.jacobian(f.x());
  const Toa::Measurement zh = toa.predict(f.x());
  int r = 0;
  for (int i = 0; i < Toa::kMeasDim; ++i) {
    if (!kestrel::has_channel(keep, i)) continue;
    H.row(r) = Hf.row(i);
    nu(r) = z(i) - zh(i);
    ++r;
  }
  const Eigen::MatrixXd R = Eigen::MatrixXd::Identity(m, m) * (3e-3 * 3e-3);
  const Eigen::MatrixXd P0 = f.P();
  const Eigen::MatrixXd S = H * P0 * H.transpose() + R;
  const Eigen::MatrixXd K = P0 * H.transpose() * S.inverse();
  x = f.x() + K * nu;
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(7, 7) - K * H;
  P = A * P0 * A.transpose() + K * R * K.transpose();
}

double max_rel(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1e-300, b.cwiseAbs().maxCoeff());
}

/// Chi-square CDF by the series of the regularised lower incomplete gamma.
double chi_square_cdf(int k, double x) {
  const double a = k / 2.0;
  const double hx = x / 2.0;
  double term = 1.0 / a;
  double sum = term;
  for (int n = 1; n < 800; ++n) {
    term *= hx / (a + n);
    sum += term;
  }
  return sum * std::exp(-hx + a * std::log(hx) - std::lgamma(a));
}

}  // namespace

SCENARIO("with every channel and no gate the channel-gated EKF is the EKF", "[cgekf]") {
  GIVEN("the same models, prior and frame in both filters") {
    Filter f = offset_filter<Filter>();
    PlainEkf e = offset_filter<PlainEkf>();
    const Toa::Measurement z = sonar_model().predict(truth_state());
    WHEN("both update with all eight arrivals") {
      REQUIRE(f.update(z) == Status::kOk);
      REQUIRE(e.update(z) == Status::kOk);
      THEN("x and P agree to round-off") {
        // Same arithmetic in a different order (masked copies of H): 1e-12 relative.
        CHECK(max_rel(f.x(), e.x()) < 1e-12);
        CHECK(max_rel(f.P(), e.P()) < 1e-12);
        CHECK(f.diagnostics().fused_channels == Filter::kAllChannels);
        CHECK(f.diagnostics().nis == Approx(e.diagnostics().nis).epsilon(1e-9));
      }
    }
  }
}

SCENARIO("a subset update equals the update with only those channels", "[cgekf]") {
  GIVEN("a frame that carries five of the eight channels") {
    Filter f = offset_filter<Filter>();
    Toa::Measurement z = sonar_model().predict(truth_state());
    const ChannelMask present = 0b10110101;
    // What an absent channel holds must not matter, NaN included.
    z(1) = std::numeric_limits<double>::quiet_NaN();
    z(3) = 1e9;
    Eigen::VectorXd xr;
    Eigen::MatrixXd Pr;
    reference_update(f, z, present, xr, Pr);
    WHEN("it updates with that mask") {
      REQUIRE(f.update(z, present) == Status::kOk);
      THEN("x and P equal the 5-channel textbook update") {
        // The reference inverts S explicitly; Cholesky solves differ by a
        // few ulps of condition number ~1e4: 1e-9 relative.
        CHECK(max_rel(f.x(), xr) < 1e-9);
        CHECK(max_rel(f.P(), Pr) < 1e-9);
        CHECK(f.diagnostics().fused_channels == present);
        CHECK(f.diagnostics().present == present);
      }
    }
    WHEN("the absent channels are instead fed as zero-innovation measurements (the paper's 'replace with 0')") {
      Filter zeroed = f;
      Toa::Measurement zz = z;
      const Toa::Measurement zh = sonar_model().predict(zeroed.x());
      for (int i = 0; i < Toa::kMeasDim; ++i) {
        if (!kestrel::has_channel(present, i)) zz(i) = zh(i);
      }
      REQUIRE(zeroed.update(zz) == Status::kOk);
      REQUIRE(f.update(z, present) == Status::kOk);
      THEN("that would shrink P as if they had been measured; removal does not") {
        CHECK(zeroed.P().trace() < f.P().trace());
        CHECK(max_rel(f.P(), Pr) < 1e-9);
      }
    }
  }
}

/// The same bits (a -0 where +0 was expected would differ).
template <class A, class B>
bool same_bits(const A& a, const B& b) {
  static_assert(sizeof(a(0, 0)) == sizeof(b(0, 0)));
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(a(0, 0)) * a.size()) == 0;
}

TEMPLATE_TEST_CASE("a channel linearisation narrowed to a subset is that subset's linearisation, bit for bit",
                   "[cgekf]", double, float) {
  using S = TestType;
  using M = kestrel::ConstantVelocity3DSoundSpeed<S>;
  using T = kestrel::MultipathToa<M, 4>;
  using E = kestrel::Ekf<M, T>;
  T toa;
  const Toa model = sonar_model();
  toa.config.beacon_count = model.config.beacon_count;
  for (int b = 0; b < 4; ++b) toa.config.beacons_m[b] = model.config.beacons_m[b].template cast<S>();
  toa.config.seabed_depth_m = static_cast<S>(model.config.seabed_depth_m);
  toa.config.sigma_toa_s = static_cast<S>(model.config.sigma_toa_s);
  M motion;
  motion.accel_sigma_mps2 = S(0.05);
  motion.sound_speed_q_m2ps3 = S(0.01);
  const Filter reference = offset_filter<Filter>();  // its x and P, in S
  E e(motion, toa);
  REQUIRE(e.reset(reference.x().template cast<S>(), reference.P().template cast<S>()) == Status::kOk);
  REQUIRE(e.predict(S(2)) == Status::kOk);  // correlations everywhere
  typename E::MeasVec z = toa.predict(truth_state().template cast<S>());
  z(1) = std::numeric_limits<S>::quiet_NaN();  // absent: never read
  const ChannelMask present = 0b11111101;
  const auto R = toa.noise();

  const auto full = e.linearise_channels(z, R, present);
  REQUIRE(full.status == Status::kOk);
  for (const ChannelMask keep : {ChannelMask{0b10110100}, ChannelMask{0b00000001}, ChannelMask{0b11111101},
                                 ChannelMask{0b01000000}}) {
    INFO("keep " << int(keep));
    const auto narrowed = full.narrowed(keep);
    const auto direct = e.linearise_channels(z, R, present & keep);
    CHECK(narrowed.channels == direct.channels);
    CHECK(narrowed.status == direct.status);
    CHECK(same_bits(narrowed.nu, direct.nu));
    CHECK(same_bits(narrowed.H, direct.H));
    CHECK(same_bits(narrowed.R, direct.R));
    CHECK(same_bits(narrowed.S, direct.S));
    const auto in_narrowed = e.innovation(narrowed);
    const auto in_direct = e.innovation(z, R, present & keep);
    CHECK(in_narrowed.status == in_direct.status);
    CHECK(std::memcmp(&in_narrowed.d2, &in_direct.d2, sizeof(S)) == 0);

    E a = e;
    E b = e;
    REQUIRE(a.update(narrowed) == Status::kOk);
    REQUIRE(b.update(z, R, present & keep) == Status::kOk);
    CHECK(same_bits(a.x(), b.x()));
    CHECK(same_bits(a.P(), b.P()));
    CHECK(a.diagnostics().fused_channels == (present & keep));
    CHECK(!same_bits(a.P(), e.P()));  // it did update
  }
}

SCENARIO("the per-channel gate drops an injected outlier and keeps the good arrivals", "[cgekf][gate]") {
  GIVEN("a noise-free frame with a +30 ms outlier on beacon 2's reflected arrival") {
    Filter f = offset_filter<Filter>();
    Toa::Measurement z = sonar_model().predict(truth_state());
    const int bad = Toa::channel(2, kestrel::ArrivalPath::kReflected);
    z(bad) += 30e-3;
    Filter::GateConfig gate;  // per-channel, k = 2
    Eigen::VectorXd xr;
    Eigen::MatrixXd Pr;
    const ChannelMask good = kestrel::without_channel(Filter::kAllChannels, bad);
    reference_update(f, z, good, xr, Pr);
    WHEN("it updates through the gate") {
      REQUIRE(f.update_gated(z, Filter::kAllChannels, gate) == Status::kOk);
      const auto& d = f.diagnostics();
      THEN("only the outlier is gated, the seven others are fused") {
        CHECK(d.rejected == (ChannelMask{1} << bad));
        CHECK(d.fused_channels == good);
        CHECK(d.test_ratio(bad) > 1.0);
        for (int i = 0; i < Toa::kMeasDim; ++i) {
          if (i != bad) CHECK(d.test_ratio(i) <= 1.0);
        }
        CHECK(d.innovation_variance(bad) > 0.0);
        CHECK(d.fused);
      }
      THEN("the update is the one without the outlier") {
        CHECK(max_rel(f.x(), xr) < 1e-9);
        CHECK(max_rel(f.P(), Pr) < 1e-9);
      }
      THEN("the estimate moved towards the truth (it started 11.5 m off)") {
        CHECK((f.x().head<3>() - truth_state().head<3>()).norm() < 5.0);
      }
    }
    WHEN("the gate is off") {
      Filter::GateConfig none;
      none.per_channel = false;
      Filter ungated = f;
      Filter gated = f;
      REQUIRE(ungated.update_gated(z, Filter::kAllChannels, none) == Status::kOk);
      REQUIRE(gated.update_gated(z, Filter::kAllChannels, gate) == Status::kOk);
      THEN("the outlier pulls the estimate further from the truth") {
        const double e_ungated = (ungated.x().head<3>() - truth_state().head<3>()).norm();
        const double e_gated = (gated.x().head<3>() - truth_state().head<3>()).norm();
        CHECK(e_gated < e_ungated);
        CHECK(ungated.diagnostics().fused_channels == Filter::kAllChannels);
      }
    }
    WHEN("only the ellipsoidal gate is on") {
      Filter::GateConfig ell;
      ell.per_channel = false;
      ell.ellipsoidal = true;
      ell.ellipsoid_probability = kestrel::GateProbability::k99;
      REQUIRE(f.update_gated(z, Filter::kAllChannels, ell) == Status::kOk);
      THEN("it peels the outlier and fuses the rest") {
        CHECK(f.diagnostics().rejected == (ChannelMask{1} << bad));
        CHECK(f.diagnostics().fused_channels == good);
        CHECK(max_rel(f.x(), xr) < 1e-9);
      }
    }
  }
  GIVEN("a frame in which every arrival is 40 ms late") {
    Filter f = offset_filter<Filter>();
    const Filter::State x_before = f.x();
    const Filter::Cov P_before = f.P();
    Toa::Measurement z = sonar_model().predict(truth_state());
    z.array() += 40e-3;
    WHEN("it updates through the gate") {
      REQUIRE(f.update_gated(z, Filter::kAllChannels, Filter::GateConfig{}) == Status::kOk);
      THEN("every channel is gated and the step is predict-only") {
        CHECK(f.diagnostics().rejected == Filter::kAllChannels);
        CHECK(f.diagnostics().fused_channels == 0u);
        CHECK_FALSE(f.diagnostics().fused);
        CHECK(f.x() == x_before);
        CHECK(f.P() == P_before);
      }
    }
  }
  GIVEN("an empty frame") {
    Filter f = offset_filter<Filter>();
    const Filter::State x_before = f.x();
    THEN("the update is predict-only") {
      REQUIRE(f.update_gated(Toa::Measurement::Zero(), 0, Filter::GateConfig{}) == Status::kOk);
      CHECK(f.x() == x_before);
      CHECK_FALSE(f.diagnostics().fused);
    }
  }
}

SCENARIO("the channel-gated EKF refuses bad input and keeps its state", "[cgekf][status]") {
  Filter f = offset_filter<Filter>();
  const Filter::State x_before = f.x();
  const Filter::Cov P_before = f.P();
  Toa::Measurement z = sonar_model().predict(truth_state());
  GIVEN("a NaN in a present channel") {
    z(4) = std::numeric_limits<double>::quiet_NaN();
    THEN("kNonFinite, x and P unchanged") {
      CHECK(f.update_gated(z, Filter::kAllChannels, Filter::GateConfig{}) == Status::kNonFinite);
      CHECK(f.innovation(z).status == Status::kNonFinite);
      CHECK(f.x() == x_before);
      CHECK(f.P() == P_before);
      CHECK(f.diagnostics().status == Status::kNonFinite);
      CHECK_FALSE(f.diagnostics().fused);
    }
  }
  GIVEN("a noise covariance that makes S indefinite") {
    Filter::MeasCov R = Filter::MeasCov::Identity() * 9e-6;
    R(2, 2) = -1.0;
    THEN("kNotPositiveDefinite, x and P unchanged") {
      Filter::GateConfig none;
      none.per_channel = false;
      CHECK(f.update_gated(z, Filter::kAllChannels, none, R) == Status::kNotPositiveDefinite);
      CHECK(f.x() == x_before);
      CHECK(f.P() == P_before);
    }
  }
  GIVEN("a state on a beacon (the direct path has no direction)") {
    Filter::State xb = x_before;
    xb.head<3>().setZero();
    REQUIRE(f.reset(xb, P_before) == Status::kOk);
    THEN("kNonFinite and nothing changes") {
      CHECK(f.update(z) == Status::kNonFinite);
      CHECK(f.x() == xb);
    }
  }
  GIVEN("a good frame") {
    THEN("predict and gated update allocate nothing") {
      std::size_t allocations = 0;
      Status p, u;
      {
        kestrel::test::AllocationGuard guard;
        p = f.predict(1.0);
        u = f.update_gated(z, Filter::kAllChannels, Filter::GateConfig{});
        allocations = guard.allocations();
      }
      REQUIRE(p == Status::kOk);
      REQUIRE(u == Status::kOk);
      CHECK(allocations == 0);
      CHECK((f.P() - f.P().transpose()).cwiseAbs().maxCoeff() == 0.0);
    }
  }
}

SCENARIO("the chi-square table covers every subset size up to 16 channels", "[gate][chi2]") {
  const struct {
    kestrel::GateProbability p;
    double prob;
  } probs[] = {{kestrel::GateProbability::k90, 0.90}, {kestrel::GateProbability::k95, 0.95},
               {kestrel::GateProbability::k99, 0.99}, {kestrel::GateProbability::k995, 0.995},
               {kestrel::GateProbability::k999, 0.999}};
  for (const auto& pr : probs) {
    for (int k = 1; k <= kestrel::kChiSquareMaxDim; ++k) {
      INFO("dimension " << k << " probability " << pr.prob);
      // 3-decimal table: the CDF at the tabulated value is within 2e-4 of p.
      CHECK(chi_square_cdf(k, kestrel::chi_square_quantile(k, pr.p)) == Approx(pr.prob).margin(2e-4));
    }
    CHECK(kestrel::chi_square_quantile(16, pr.p) == kestrel::chi_square_quantile<16>(pr.p));
    CHECK(kestrel::chi_square_quantile(3, pr.p) == kestrel::chi_square_quantile<3>(pr.p));
  }
}
