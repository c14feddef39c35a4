// SPDX-License-Identifier: Apache-2.0
// Compiles the core's templates for every supported floating scalar under the
// firmware rules (-fno-exceptions -fno-rtti, EIGEN_NO_MALLOC, the warning wall
// with -Werror). Nothing links against it: if core ever needs exceptions,
// RTTI or a heap, or trips a conversion warning, this object fails to build.
#include "kestrel/models/motion/constant_velocity_2d.hpp"
#include "kestrel/tracking/radar_range_rate_tracker.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel {

template class Ekf<CaMotion<double>, CaPolarRadar<double>>;
template class Ekf<CaMotion<float>, CaPolarRadar<float>>;
template class Tracker<EkfCa<double>, TwoPointInitiator<CaMotion<double>, CaPolarRadar<double>>, 8, 32>;
template class Tracker<EkfCa<float>, TwoPointInitiator<CaMotion<float>, CaPolarRadar<float>>, 8, 32>;
// The adaptive measurement noise, a compile-time choice boards leave out.
template class Tracker<EkfCa<double>, TwoPointInitiator<CaMotion<double>, CaPolarRadar<double>>, 8, 32,
                       NearestNeighbour, MOfN, AdaptiveMeasurementNoise>;
template class Tracker<EkfCa<float>, TwoPointInitiator<CaMotion<float>, CaPolarRadar<float>>, 8, 32,
                       NearestNeighbour, MOfN, AdaptiveMeasurementNoise>;
template class Ekf<CaMotion<double>, CaPolarRadarRangeRate<double>>;
template class Ekf<CaMotion<float>, CaPolarRadarRangeRate<float>>;
template class Ekf<ConstantVelocity2D<double>, PolarRadarRangeRate<ConstantVelocity2D<double>>>;
template class Ekf<ConstantVelocity2D<float>, PolarRadarRangeRate<ConstantVelocity2D<float>>>;
template class Tracker<EkfCaRr<double>, TwoPointInitiator<CaMotion<double>, CaPolarRadarRangeRate<double>>, 8, 32>;
template class Tracker<EkfCaRr<float>, TwoPointInitiator<CaMotion<float>, CaPolarRadarRangeRate<float>>, 8, 32>;

}  // namespace kestrel
