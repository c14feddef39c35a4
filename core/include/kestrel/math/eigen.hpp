// SPDX-License-Identifier: Apache-2.0
// The one way core includes Eigen. It routes eigen_assert to KESTREL_ASSERT
// (so a board links no printf/stdio through Eigen), keeps Eigen's static
// alignment identical in every translation unit, and names the fixed-size
// vector/matrix aliases every model and filter uses.
#pragma once

#include "kestrel/assert.hpp"

// Eigen's internal checks (index bounds, sizes, EIGEN_RUNTIME_NO_MALLOC) go
// through KESTREL_ASSERT in debug builds and vanish with NDEBUG or
// EIGEN_NO_DEBUG, as Eigen's own do. The no-heap proof does not rest on them:
// boards make malloc a link error and tests count every allocation.
#ifndef eigen_assert
#if defined(EIGEN_NO_DEBUG) || defined(NDEBUG)
#define eigen_assert(x) static_cast<void>(0)
#else
#define eigen_assert(x) KESTREL_ASSERT(x)
#endif
#endif

// Products of fixed-size matrices up to 4096 rows+cols+depth are evaluated
// coefficient by coefficient instead of through Eigen's blocked GEMM kernel,
// whose workspace helper references malloc even for fixed sizes (a board's
// link-time heap guard rejects it; the channel-gated TOA update with 16
// channels crosses Eigen's default threshold of 20). kestrel_core also sets
// it as a compile definition so every translation unit agrees.
#ifndef EIGEN_GEMM_TO_COEFFBASED_THRESHOLD
#define EIGEN_GEMM_TO_COEFFBASED_THRESHOLD 4096
#endif

#include <Eigen/Core>
#include <Eigen/Cholesky>

namespace kestrel {

template <class Scalar, int kRows>
using Vec = Eigen::Matrix<Scalar, kRows, 1>;

template <class Scalar, int kRows, int kCols>
using Mat = Eigen::Matrix<Scalar, kRows, kCols>;

}  // namespace kestrel
