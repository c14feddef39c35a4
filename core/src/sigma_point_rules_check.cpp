// Compiles the sigma-point and particle filters (UKF, CDKF, SR-UKF, SR-CDKF,
// CRPF) and their helpers for double and float under the firmware rules
// (-fno-exceptions -fno-rtti, EIGEN_NO_MALLOC, the warning wall with
// -Werror), on both motion models with the polar radar. Nothing links
// against it: a heap use, an exception, RTTI or a conversion warning in any
// of these templates fails this object.
#include "kestrel/filters/cdkf.hpp"
#include "kestrel/filters/crpf.hpp"
#include "kestrel/filters/sr_cdkf.hpp"
#include "kestrel/filters/sr_ukf.hpp"
#include "kestrel/filters/ukf.hpp"
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

#define KESTREL_INSTANTIATE_SIGMA_FILTERS(S)                                            \
  template class Ukf<ConstantVelocity2D<S>, CvRadar<S>>;                                \
  template class Cdkf<ConstantVelocity2D<S>, CvRadar<S>>;                               \
  template class SrUkf<ConstantVelocity2D<S>, CvRadar<S>>;                              \
  template class SrCdkf<ConstantVelocity2D<S>, CvRadar<S>>;                             \
  template class Crpf<ConstantVelocity2D<S>, CvRadar<S>, 100>;                          \
  template class Ukf<ConstantAcceleration2D<S>, CaRadar<S>>;                            \
  template class Cdkf<ConstantAcceleration2D<S>, CaRadar<S>>;                           \
  template class SrUkf<ConstantAcceleration2D<S>, CaRadar<S>>;                          \
  template class SrCdkf<ConstantAcceleration2D<S>, CaRadar<S>>;                         \
  template class Crpf<ConstantAcceleration2D<S>, CaRadar<S>, 16>;                       \
  template class NormalGenerator<S>;                                                    \
  static_assert(TrackingFilter<Ukf<ConstantVelocity2D<S>, CvRadar<S>>>);                \
  static_assert(TrackingFilter<Cdkf<ConstantVelocity2D<S>, CvRadar<S>>>);               \
  static_assert(TrackingFilter<SrUkf<ConstantVelocity2D<S>, CvRadar<S>>>);              \
  static_assert(TrackingFilter<SrCdkf<ConstantVelocity2D<S>, CvRadar<S>>>);             \
  static_assert(TrackingFilter<Crpf<ConstantVelocity2D<S>, CvRadar<S>, 100>>);          \
  template Status cholesky_rank1_update<S, 4>(Mat<S, 4, 4>&, const Vec<S, 4>&, S);      \
  template Status cholesky_semidefinite<S, 4>(const Mat<S, 4, 4>&, Mat<S, 4, 4>&);      \
  template Mat<S, 4, 4> triangularise<S, 4, 12>(const Mat<S, 4, 12>&);

KESTREL_INSTANTIATE_SIGMA_FILTERS(double)
KESTREL_INSTANTIATE_SIGMA_FILTERS(float)

#undef KESTREL_INSTANTIATE_SIGMA_FILTERS

}  // namespace kestrel
