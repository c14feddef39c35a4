// SPDX-License-Identifier: Apache-2.0
// Compiles the R2-AEKF (kestrel/filters/r2aekf.hpp) for double, float and
// Q31.32 under the firmware rules (-fno-exceptions -fno-rtti, EIGEN_NO_MALLOC, the
// warning wall with -Werror), in both Q forms, and inside the radar Tracker,
// so the filter stays fit for a board. Nothing links against this object.
#include "kestrel/filters/r2aekf.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/scalar/fixed_point_math.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel {

template class R2Aekf<CaMotion<double>, CaPolarRadar<double>>;
template class R2Aekf<CaMotion<float>, CaPolarRadar<float>>;
template class R2Aekf<CaMotion<Q31_32>, CaPolarRadar<Q31_32>>;
template class Tracker<R2AekfCa<double>, TwoPointInitiator<CaMotion<double>, CaPolarRadar<double>>, 8, 32>;
template class Tracker<R2AekfCa<float>, TwoPointInitiator<CaMotion<float>, CaPolarRadar<float>>, 8, 32>;
template class Tracker<R2AekfCa<Q31_32>, TwoPointInitiator<CaMotion<Q31_32>, CaPolarRadar<Q31_32>>, 8, 32>;

static_assert(TrackingFilter<R2AekfCa<double>>);
static_assert(TrackingFilter<R2AekfCa<float>>);
static_assert(TrackingFilter<R2AekfCa<Q31_32>>);
static_assert(R2AekfConfig<Q31_32>{}.valid());
static_assert(R2AekfConfig<float>{}.valid());
static_assert(R2AekfConfig<double>::paper().valid());

}  // namespace kestrel
