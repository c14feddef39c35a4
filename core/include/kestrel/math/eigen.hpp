// The one way core includes Eigen. It routes eigen_assert to KESTREL_ASSERT
// (so a board links no printf/stdio through Eigen), keeps Eigen's static
// alignment identical in every translation unit, and names the fixed-size
// vector/matrix aliases every model and filter uses.
#pragma once

#include "kestrel/assert.hpp"

#ifndef eigen_assert
#define eigen_assert(x) KESTREL_ASSERT(x)
#endif

#include <Eigen/Core>
#include <Eigen/Cholesky>

namespace kestrel {

template <class Scalar, int kRows>
using Vec = Eigen::Matrix<Scalar, kRows, 1>;

template <class Scalar, int kRows, int kCols>
using Mat = Eigen::Matrix<Scalar, kRows, kCols>;

}  // namespace kestrel
