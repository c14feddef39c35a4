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
#include <vector>

#include "bench/bench_cases.hpp"

namespace kestrel::bench {
namespace {

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

const char* g_filter = nullptr;  // --filter: only paths containing this text
bool g_list = false;             // --list: print labels, measure nothing

bool wanted(const std::string& path) { return g_filter == nullptr || path.find(g_filter) != std::string::npos; }

void dump(const std::string& path, std::size_t steps) {
  const std::string label = path + " steps=" + std::to_string(steps);
  CALLGRIND_DUMP_STATS_AT(label.c_str());
  std::printf("%s\n", label.c_str());
}

[[noreturn]] void fail(const std::string& path, Status s) {
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

}  // namespace
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
    for_each_filter_case([&]<class F>(const CaseName& n) {
      count_filter<F>(n, s1);
      if constexpr (kTrackerPaths<F>) count_tracker<F>(n);
    });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kestrel-instr-count: %s\n", e.what());
    return 1;
  }
  return 0;
}
