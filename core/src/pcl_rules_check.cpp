// SPDX-License-Identifier: Apache-2.0
// Compiles the passive-radar (PCL) tracker of kestrel/tracking/pcl_tracker.hpp
// for every supported floating scalar under the firmware rules
// (-fno-exceptions -fno-rtti, EIGEN_NO_MALLOC, the warning wall with -Werror),
// at the PCL-002 capacities and at the hard variant's 64 candidates, plus the
// track-distance ranking the PCL front end uses on over-capacity frames.
// Nothing links against it.
#include "kestrel/models/measurement/bistatic_geometry.hpp"
#include "kestrel/tracking/nearest_track.hpp"
#include "kestrel/tracking/pcl_tracker.hpp"

namespace kestrel {

template class Ekf<PclMotion<double>, PclMeasurement<double>>;
template class Ekf<PclMotion<float>, PclMeasurement<float>>;
template class Tracker<PclKf<double>, PclInitiator<double>, kPclMaxTracks, kPclMaxCandidates>;
template class Tracker<PclKf<float>, PclInitiator<float>, kPclMaxTracks, kPclMaxCandidates>;
template class Tracker<PclKf<double>, PclInitiator<double>, 256, 64>;
template struct SinglePointInitiator<PclMotion<float>, PclMeasurement<float>>;

using PclTableD = Tracker<PclKf<double>, PclInitiator<double>, kPclMaxTracks, kPclMaxCandidates>::Table;
template void nearest_track_d2<Track<PclKf<double>>, kPclMaxTracks, Vec<double, 2>, double, 64>(
    const PclTableD&, std::int64_t, const Vec<double, 2> (&)[64], std::size_t, double (&)[64]);
template double bistatic_range<double>(const Vec<double, 3>&, const Vec<double, 3>&, const Vec<double, 3>&);
template float bistatic_range_rate<float>(const Vec<float, 3>&, const Vec<float, 3>&, const Vec<float, 3>&,
                                          const Vec<float, 3>&);

}  // namespace kestrel
