// Compiles the GNN assignment solver (kestrel/association/gnn.hpp) for the
// floating scalars under the firmware rules (-fno-exceptions -fno-rtti,
// EIGEN_NO_MALLOC, the warning wall with -Werror). Nothing links against it.
#include "kestrel/association/gnn.hpp"

namespace kestrel {

template class Gnn<double, 16, 64>;
template class Gnn<float, 8, 32>;

}  // namespace kestrel
