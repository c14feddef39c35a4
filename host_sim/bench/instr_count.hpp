// SPDX-License-Identifier: Apache-2.0
// The measuring side of kestrel-instr-count (instr_count.cpp): callgrind
// collection around the measured calls, one dump per path, and the filter
// and tracker paths of a filter type. Each family of cases is instantiated
// in its own translation unit (instr_count_<family>.cpp), the EKF family's
// once per scalar: GCC's inlining decisions depend on what else a unit
// holds, so one case's count must not move when unrelated cases change
// (docs/performance.md, "Commands"). A board image holds one scalar, as
// each unit here does.
#pragma once

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else  // no valgrind headers: the program still runs its path checks
#define CALLGRIND_TOGGLE_COLLECT
#define CALLGRIND_DUMP_STATS_AT(label) static_cast<void>(label)
#endif

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <type_traits>
#include <vector>

#include "bench/bench_cases.hpp"

namespace kestrel::bench {

// Callgrind collection on for one scope. The toggle is a handful of
// instructions of its own, the same for every step: part of the budget.
class Collect {
 public:
  Collect() { CALLGRIND_TOGGLE_COLLECT; }
  ~Collect() { CALLGRIND_TOGGLE_COLLECT; }
  Collect(const Collect&) = delete;
  Collect& operator=(const Collect&) = delete;
};

/// fn(), with collection on around it when `on`.
template <class Fn>
auto measured(bool on, Fn fn) {
  if (on) {
    Collect c;
    return fn();
  }
  return fn();
}

inline const char* g_filter = nullptr;  // --filter: only paths containing this text
inline bool g_list = false;             // --list: print labels, measure nothing

inline bool wanted(const std::string& path) { return g_filter == nullptr || path.find(g_filter) != std::string::npos; }

inline void dump(const std::string& path, std::size_t steps) {
  const std::string label = path + " steps=" + std::to_string(steps);
  CALLGRIND_DUMP_STATS_AT(label.c_str());
  std::printf("%s\n", label.c_str());
}

[[noreturn]] inline void fail(const std::string& path, Status s) {
  std::fprintf(stderr, "kestrel-instr-count: %s: status %s\n", path.c_str(), to_string(s));
  std::exit(1);
}

/// Filter paths: predict, innovation, update and step over the S1 inputs.
template <class F>
void count_filter(const CaseName& n, const std::vector<FrameSi>& s1) {
  const std::string base = std::string("filter/") + n.filter + "/" + n.scalar + "/" + n.form + "/";
  const FilterRun<F> run = make_filter_run<F>(s1);
  const std::size_t steps = run.inputs.size();

  if (const std::string path = base + "step"; wanted(path)) {
    if (!g_list) {
      F f = run.start;
      for (const auto& in : run.inputs) {
        Status a, b;
        {
          Collect c;
          a = f.predict(in.dt);
          b = f.update(in.z);
        }
        if (a != Status::kOk || b != Status::kOk) fail(path, a != Status::kOk ? a : b);
      }
    }
    dump(path, steps);
  }
  // The parts, each measured on the state the full step sequence reaches.
  const std::string p_predict = base + "predict";
  const std::string p_innov = base + "innovation";
  const std::string p_update = base + "update";
  if (!wanted(p_predict) && !wanted(p_innov) && !wanted(p_update)) return;
  if (g_list) {
    for (const auto& p : {p_predict, p_innov, p_update}) {
      if (wanted(p)) dump(p, steps);
    }
    return;
  }
  // One pass per part, so each dump holds that part only.
  for (const std::string& path : {p_predict, p_innov, p_update}) {
    if (!wanted(path)) continue;
    F f = run.start;
    for (const auto& in : run.inputs) {
      const Status a = measured(path == p_predict, [&] { return f.predict(in.dt); });
      const Status b = measured(path == p_innov, [&] { return f.innovation(in.z).status; });
      const Status u = measured(path == p_update, [&] { return f.update(in.z); });
      if (a != Status::kOk) fail(path, a);
      if (b != Status::kOk) fail(path, b);
      if (u != Status::kOk) fail(path, u);
    }
    dump(path, steps);
  }
}

/// Tracker paths of filter F.
template <class F>
void count_tracker(const CaseName& n) {
  using Tracker = BenchTracker<F>;
  const std::string base = std::string("tracker/") + n.filter + "/" + n.scalar + "/" + n.form + "/";
  bool any = false;
  for (const char* cls : {"normal", "gated_out", "rejected", "initiation", "worst_case"}) any = any || wanted(base + cls);
  if (!any) return;
  const auto paths = make_tracker_paths<F>();
  for (const auto& p : paths) {
    const std::string path = base + p.name;
    if (!wanted(path)) continue;
    if (!g_list) {
      if (p.restart) {
        for (std::size_t r = 0; r < p.reps; ++r) {
          auto t = std::make_unique<Tracker>(*p.start);
          {
            Collect c;
            static_cast<void>(t->step(p.scans[0]));
          }
        }
      } else {
        auto t = std::make_unique<Tracker>(*p.start);
        for (std::size_t i = 0; i < p.scans.size(); ++i) {
          if (p.counted[i]) {
            Collect c;
            static_cast<void>(t->step(p.scans[i]));
          } else {
            static_cast<void>(t->step(p.scans[i]));
          }
        }
      }
    }
    dump(path, p.measured_steps());
  }
}

/// The EKF family's cases (for_each_ekf_case()) whose scalar is S.
template <class S>
void count_ekf_cases_in(const std::vector<FrameSi>& s1) {
  for_each_ekf_case([&]<class F>(const CaseName& n) {
    if constexpr (std::is_same_v<typename F::Scalar, S>) {
      count_filter<F>(n, s1);
      if constexpr (kTrackerPaths<F>) count_tracker<F>(n);
    }
  });
}

}  // namespace kestrel::bench

