// SPDX-License-Identifier: Apache-2.0
// Compiles the core's templates for every supported floating scalar under the
// firmware rules (-fno-exceptions -fno-rtti, EIGEN_NO_MALLOC, the warning wall
// with -Werror). Nothing links against it: if core ever needs exceptions,
// RTTI or a heap, or trips a conversion warning, this object fails to build.
#include "kestrel/tracking/radar_tracker.hpp"

namespace kestrel {

template class Ekf<CaMotion<double>, CaPolarRadar<double>>;
template class Ekf<CaMotion<float>, CaPolarRadar<float>>;
template class Tracker<EkfCa<double>, TwoPointInitiator<CaMotion<double>, CaPolarRadar<double>>, 8, 32>;
template class Tracker<EkfCa<float>, TwoPointInitiator<CaMotion<float>, CaPolarRadar<float>>, 8, 32>;

}  // namespace kestrel
