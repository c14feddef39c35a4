// SPDX-License-Identifier: Apache-2.0
// kestrel-instr-count: the EKF (EKF-CA, R2-AEKF) family's double cases, in a
// translation unit of their own (instr_count.hpp says why).
#include <vector>

#include "bench/instr_count.hpp"

namespace kestrel::bench {

void count_ekf_family_double(const std::vector<FrameSi>& s1) { count_ekf_cases_in<double>(s1); }

}  // namespace kestrel::bench
