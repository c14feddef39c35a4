// SPDX-License-Identifier: Apache-2.0
// kestrel-instr-count: runs every measured path a fixed number of times with
// callgrind collection switched on only around the measured calls, and
// dumps callgrind's counters after each path (CALLGRIND_DUMP_STATS_AT with
// the path's label), so each dump holds that path's instructions and
// nothing else. Run it under
//   valgrind --tool=callgrind --collect-atstart=no kestrel-instr-count
// (host_sim/bench/check_instruction_budgets.py does, and divides by the
// step count in the label). Outside valgrind the client requests are no-ops
// and the program only checks that every path takes its path.
//
// Labels: "<path> steps=<n>", path = filter/<filter>/<scalar>/<form>/<op>
// (op: predict, innovation, update, step = predict + update) or
// tracker/<filter>/<scalar>/<form>/<class>.
#include <cstdio>
#include <cstring>
#include <exception>
#include <vector>

#include "bench/bench_inputs.hpp"
#include "bench/instr_count.hpp"

namespace kestrel::bench {
// One translation unit per family, and per scalar for the EKF family
// (instr_count.hpp says why).
void count_ekf_family_double(const std::vector<FrameSi>& s1);
void count_ekf_family_float(const std::vector<FrameSi>& s1);
void count_ekf_family_q31_32(const std::vector<FrameSi>& s1);
void count_sigma_family(const std::vector<FrameSi>& s1);
void count_imm_family(const std::vector<FrameSi>& s1);
}  // namespace kestrel::bench

int main(int argc, char** argv) {
  using namespace kestrel::bench;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--list") == 0) {
      g_list = true;
    } else if (std::strcmp(argv[i], "--filter") == 0 && i + 1 < argc) {
      g_filter = argv[++i];
    } else {
      std::fprintf(stderr,
                   "usage: kestrel-instr-count [--list] [--filter TEXT]\n"
                   "  run under: valgrind --tool=callgrind --collect-atstart=no kestrel-instr-count\n");
      return 2;
    }
  }
  try {
    const std::vector<FrameSi> s1 = s1_frames();
    count_ekf_family_double(s1);
    count_ekf_family_float(s1);
    count_ekf_family_q31_32(s1);
    count_sigma_family(s1);
    count_imm_family(s1);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kestrel-instr-count: %s\n", e.what());
    return 1;
  }
  return 0;
}
