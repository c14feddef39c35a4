// SPDX-License-Identifier: Apache-2.0
// kestrel-instr-count: the radar IMM's cases (CV, CA and CT EKFs mixed), in a
// translation unit of their own (instr_count.hpp says why): the filter
// paths and the tracker's normal and worst_case paths.
#include <vector>

#include "bench/instr_count.hpp"

namespace kestrel::bench {

void count_imm_family(const std::vector<FrameSi>& s1) {
  for_each_imm_case([&]<class F>(const CaseName& n) {
    count_filter<F>(n, s1);
    count_tracker<F>(n);  // normal and worst_case (kAllTrackerPaths)
  });
}

}  // namespace kestrel::bench
