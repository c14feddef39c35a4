// SPDX-License-Identifier: Apache-2.0
// Compiles the fixed-point scalar and the EKF-CA radar tracker on it under the
// firmware rules (-fno-exceptions -fno-rtti, EIGEN_NO_MALLOC, the warning wall
// with -Werror), for both formats. Nothing links against it.
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel {

template class fixed::FixedPoint<32>;
template class fixed::FixedPoint<40>;
template class Ekf<CaMotion<Q31_32>, CaPolarRadar<Q31_32>>;
template class Ekf<CaMotion<Q23_40>, CaPolarRadar<Q23_40>>;
template class Tracker<EkfCa<Q31_32>, TwoPointInitiator<CaMotion<Q31_32>, CaPolarRadar<Q31_32>>, 8, 32>;
template class Tracker<EkfCa<Q23_40>, TwoPointInitiator<CaMotion<Q23_40>, CaPolarRadar<Q23_40>>, 8, 32>;
// The sequential whitened update in floating point as well (tests compare it
// with the batch form).
template class Ekf<CaMotion<double>, CaPolarRadar<double>, EkfUpdateForm::kSequentialWhitened>;
template class Ekf<CaMotion<float>, CaPolarRadar<float>, EkfUpdateForm::kSequentialWhitened>;

// The board path: every real constant converted at compile time.
inline constexpr RadarTrackerConfig<Q31_32> kQ31Config = radar_tracker_config<Q31_32>(RadarTrackerParams{});
inline constexpr RadarTrackerConfig<Q23_40> kQ23Config = radar_tracker_config<Q23_40>(RadarTrackerParams{});
static_assert(kQ31Config.sigma_range_m == Q31_32(3));
static_assert(kQ23Config.max_position_variance_m2 == Q23_40(1000000));

}  // namespace kestrel
