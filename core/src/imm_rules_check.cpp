// SPDX-License-Identifier: Apache-2.0
// Compiles the IMM (kestrel/filters/imm.hpp) with its CV/CA/CT radar modes
// (kestrel/filters/imm_radar.hpp) for double and float under the firmware
// rules (-fno-exceptions -fno-rtti, EIGEN_NO_MALLOC, the warning wall with
// -Werror), alone and inside the radar Tracker, so it stays fit for a
// board. Nothing links against this object.
#include "kestrel/filters/imm.hpp"
#include "kestrel/filters/imm_radar.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel {

template struct CoordinatedTurn2D<double>;
template struct CoordinatedTurn2D<float>;
template class Ekf<CoordinatedTurn2D<float>, PolarRadar<CoordinatedTurn2D<float>>>;
template class Imm<ConstantAcceleration2D<double>, PolarRadar<ConstantAcceleration2D<double>>, ImmCvMode<double>,
                   ImmCaMode<double>, ImmCtMode<double>>;
template class Imm<ConstantAcceleration2D<float>, PolarRadar<ConstantAcceleration2D<float>>, ImmCvMode<float>,
                   ImmCaMode<float>, ImmCtMode<float>>;
template class Tracker<RadarImm<double>, TwoPointInitiator<CaMotion<double>, CaPolarRadar<double>>, 8, 32>;
template class Tracker<RadarImm<float>, TwoPointInitiator<CaMotion<float>, CaPolarRadar<float>>, 8, 32>;
template class Tracker<RadarImm<float>, TwoPointInitiator<CaMotion<float>, CaPolarRadar<float>>, 8, 32,
                       NearestNeighbour, MOfN, AdaptiveMeasurementNoise>;
static_assert(ScalesMeasurementNoise<RadarImm<double>>);
static_assert(ScalesMeasurementNoise<RadarImm<float>>);

static_assert(TrackingFilter<RadarImm<double>>);
static_assert(TrackingFilter<RadarImm<float>>);

/// make_radar_imm instantiated for both scalars.
RadarImm<double> imm_rules_check_double(const RadarImmParams& p) { return make_radar_imm<double>(p); }
RadarImm<float> imm_rules_check_float(const RadarImmParams& p) { return make_radar_imm<float>(p); }

}  // namespace kestrel
