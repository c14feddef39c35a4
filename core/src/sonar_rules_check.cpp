// SPDX-License-Identifier: Apache-2.0
// Compiles the sonar tracker of kestrel/tracking/sonar_tracker.hpp
// (CV-3D + sound speed, multipath TOA, channel-gated EKF, multilateration)
// for both floating scalars under the firmware rules (-fno-exceptions
// -fno-rtti, EIGEN_NO_MALLOC, the warning wall with -Werror): float at the
// UW-003 size (4 beacons), double at the most a sonar frame can name
// (8 beacons, 16 channels). Nothing links against it.
#include "kestrel/filters/channel_gated_ekf.hpp"
#include "kestrel/models/measurement/multipath_toa.hpp"
#include "kestrel/models/motion/constant_velocity_3d_sound_speed.hpp"
#include "kestrel/tracking/multilateration.hpp"
#include "kestrel/tracking/tracker.hpp"
#include "kestrel/tracking/sonar_tracker.hpp"

namespace kestrel {

// Each scalar once and each size once: the templates' code does not depend
// on the pairing, and every instantiation here costs tens of seconds of
// compile time.
template struct ConstantVelocity3DSoundSpeed<double>;
template struct ConstantVelocity3DSoundSpeed<float>;
template struct MultipathToa<ConstantVelocity3DSoundSpeed<double>, 8>;
template struct MultipathToa<ConstantVelocity3DSoundSpeed<float>, 4>;
template class ChannelGatedEkf<ConstantVelocity3DSoundSpeed<float>, MultipathToa<ConstantVelocity3DSoundSpeed<float>, 4>>;
template class ChannelGatedEkf<ConstantVelocity3DSoundSpeed<double>, MultipathToa<ConstantVelocity3DSoundSpeed<double>, 8>>;
template class SonarTracker<float, 4>;
template class SonarTracker<double, 8>;
template SonarTracker<float, 4> make_sonar_tracker<float, 4>(const SonarTrackerParams&);
template MultilaterationResult<float> multilaterate<MultipathToa<ConstantVelocity3DSoundSpeed<float>, 4>>(
    const MultipathToa<ConstantVelocity3DSoundSpeed<float>, 4>&,
    const MultipathToa<ConstantVelocity3DSoundSpeed<float>, 4>::Measurement&, ChannelMask,
    const MultilaterationConfig<float>&);

// With every channel present the channel-gated EKF is a drop-in tracking filter.
static_assert(TrackingFilter<SonarTracker<float, 4>::Filter>);
static_assert(TrackingFilter<SonarTracker<double, 8>::Filter>);

}  // namespace kestrel
