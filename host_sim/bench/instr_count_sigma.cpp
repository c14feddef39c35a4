// SPDX-License-Identifier: Apache-2.0
// kestrel-instr-count: the sigma-point (UKF, CDKF, SR-UKF, SR-CDKF) family's cases, in a translation unit of
// their own (instr_count.hpp says why).
#include <vector>

#include "bench/instr_count.hpp"

namespace kestrel::bench {

void count_sigma_family(const std::vector<FrameSi>& s1) {
  for_each_sigma_case([&]<class F>(const CaseName& n) {
    count_filter<F>(n, s1);
    if constexpr (kTrackerPaths<F>) count_tracker<F>(n);
  });
}

}  // namespace kestrel::bench
