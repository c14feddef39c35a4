// SPDX-License-Identifier: Apache-2.0
// Compiles the association and track-management policies (GNN solver,
// GlobalNearestNeighbour, ProbabilisticDataAssociation, SequentialLlr) for the floating scalars under the
// firmware rules (-fno-exceptions -fno-rtti, EIGEN_NO_MALLOC, the warning
// wall with -Werror), composed into the radar and PCL trackers. Nothing
// links against it.
#include "kestrel/association/global_nearest_neighbour.hpp"
#include "kestrel/association/gnn.hpp"
#include "kestrel/association/pda.hpp"
#include "kestrel/tracking/pcl_tracker.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "kestrel/tracking/sequential_llr.hpp"

namespace kestrel {

template class Gnn<double, 16, 64>;
template class Gnn<float, 8, 32>;
template class Tracker<EkfCa<float>, TwoPointInitiator<CaMotion<float>, CaPolarRadar<float>>, 8, 32,
                       GlobalNearestNeighbour, SequentialLlr>;
template class Tracker<EkfCa<double>, TwoPointInitiator<CaMotion<double>, CaPolarRadar<double>>, 8, 32,
                       ProbabilisticDataAssociation, SequentialLlr>;
template class Tracker<PclKf<double>, PclInitiator<double>, kPclMaxTracks, kPclMaxCandidates, GlobalNearestNeighbour,
                       SequentialLlr>;

}  // namespace kestrel
