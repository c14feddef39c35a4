// SPDX-License-Identifier: Apache-2.0
// Compiles the sigma-point and particle filters (UKF, CDKF, SR-UKF, SR-CDKF,
// CRPF) and their helpers for double and float under the firmware rules
// (-fno-exceptions -fno-rtti, EIGEN_NO_MALLOC, the warning wall with
// -Werror), on both motion models with the polar radar. Nothing links
// against it: a heap use, an exception, RTTI or a conversion warning in any
// of these templates fails this object.
#include "kestrel/filters/crpf.hpp"
#include "kestrel/filters/sigma_point_filter.hpp"
#include "kestrel/filters/sr_sigma_point_filter.hpp"
#include "kestrel/math/cholesky_update.hpp"
#include "kestrel/math/prng.hpp"
#include "kestrel/math/triangular.hpp"
#include "kestrel/models/measurement/polar_radar.hpp"
#include "kestrel/models/motion/constant_acceleration_2d.hpp"
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "kestrel/tracking/tracker.hpp"

namespace kestrel {

template <class S>
using CvRadar = PolarRadar<ConstantVelocity2D<S>>;
template <class S>
using CaRadar = PolarRadar<ConstantAcceleration2D<S>>;

// Every filter in both scalars and on both motion models, each pairing
// once (CV-2D with one scalar, CA-2D with the other): the filters' code does
// not depend on the pairing, and each instantiation costs ten to twenty
// seconds of compile time. Explicit instantiation names the class template,
// not its alias (Ukf = SigmaPointFilter<..., UnscentedPoints>).
template class SigmaPointFilter<ConstantVelocity2D<double>, CvRadar<double>, UnscentedPoints>;
template class SigmaPointFilter<ConstantAcceleration2D<float>, CaRadar<float>, UnscentedPoints>;
template class SigmaPointFilter<ConstantVelocity2D<float>, CvRadar<float>, CentralDifferencePoints>;
template class SigmaPointFilter<ConstantAcceleration2D<double>, CaRadar<double>, CentralDifferencePoints>;
template class SrSigmaPointFilter<ConstantVelocity2D<double>, CvRadar<double>, UnscentedPoints>;
template class SrSigmaPointFilter<ConstantAcceleration2D<float>, CaRadar<float>, UnscentedPoints>;
template class SrSigmaPointFilter<ConstantVelocity2D<float>, CvRadar<float>, CentralDifferencePoints>;
template class SrSigmaPointFilter<ConstantAcceleration2D<double>, CaRadar<double>, CentralDifferencePoints>;
template class Crpf<ConstantVelocity2D<double>, CvRadar<double>, 100>;
template class Crpf<ConstantAcceleration2D<float>, CaRadar<float>, 16>;
static_assert(TrackingFilter<Ukf<ConstantVelocity2D<double>, CvRadar<double>>>);
static_assert(TrackingFilter<Cdkf<ConstantVelocity2D<float>, CvRadar<float>>>);
static_assert(TrackingFilter<SrUkf<ConstantVelocity2D<double>, CvRadar<double>>>);
static_assert(TrackingFilter<SrCdkf<ConstantVelocity2D<float>, CvRadar<float>>>);
static_assert(TrackingFilter<Crpf<ConstantVelocity2D<double>, CvRadar<double>, 100>>);

#define KESTREL_INSTANTIATE_SIGMA_HELPERS(S)                                       \
  template class NormalGenerator<S>;                                               \
  template Status cholesky_rank1_update<S, 4>(Mat<S, 4, 4>&, const Vec<S, 4>&, S); \
  template Status cholesky_semidefinite<S, 4>(const Mat<S, 4, 4>&, Mat<S, 4, 4>&); \
  template Mat<S, 4, 4> triangularise<S, 4, 12>(const Mat<S, 4, 12>&);

KESTREL_INSTANTIATE_SIGMA_HELPERS(double)
KESTREL_INSTANTIATE_SIGMA_HELPERS(float)

#undef KESTREL_INSTANTIATE_SIGMA_HELPERS

}  // namespace kestrel
