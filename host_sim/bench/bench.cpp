// SPDX-License-Identifier: Apache-2.0
// kestrel-bench: ns per step (Google Benchmark) of every case in
// bench_cases.hpp, dense and structured side by side in the same run:
//   filter/<filter>/<scalar>/<form>/step      predict + update over S1
//   tracker/<filter>/<scalar>/<form>/<class>  one Tracker::step of a path class
// On a loaded machine read the CPU column (Google Benchmark's "Time" is wall
// clock); the restart paths report thread CPU time as their manual time.
// The repeatable figures are the instruction counts of kestrel-instr-count
// (docs/performance.md).
//   kestrel-bench --benchmark_filter=filter/ --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <time.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_cases.hpp"

namespace kestrel::bench {
namespace {

// Keeps every case's inputs alive for the benchmarks that reference them.
std::vector<std::shared_ptr<const void>> g_keep;

/// predict + update on consecutive S1 frames; back to the initiated state
/// after the last frame (one filter copy per ~300 steps).
template <class F>
void bm_filter_step(benchmark::State& state, const FilterRun<F>* run) {
  F f = run->start;
  std::size_t k = 0;
  const std::size_t n = run->inputs.size();
  for (auto _ : state) {
    const auto& in = run->inputs[k];
    Status a = f.predict(in.dt);
    Status b = f.update(in.z);
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(b);
    if (++k == n) {
      k = 0;
      f = run->start;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

/// A consecutive path: each iteration steps the next scan; after the last,
/// back to the start state (one tracker copy per pass). Every scan of the
/// sequence is timed, including the few the instruction count leaves out.
template <class Tracker>
void bm_tracker_sequence(benchmark::State& state, const TrackerPath<Tracker>* p) {
  auto t = std::make_unique<Tracker>(*p->start);
  std::size_t k = 0;
  for (auto _ : state) {
    Status s = t->step(p->scans[k]);
    benchmark::DoNotOptimize(s);
    if (++k == p->scans.size()) {
      k = 0;
      *t = *p->start;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

/// Thread CPU time, s (the machine is shared: wall-clock time includes
/// other processes' slices, thread CPU time does not).
double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// A restart path: each iteration restores kBatch copies of the start state
/// (not timed), then times stepping each once by thread CPU time; reports
/// the mean per step.
template <class Tracker>
void bm_tracker_restart(benchmark::State& state, const TrackerPath<Tracker>* p) {
  constexpr std::size_t kBatch = 16;
  std::vector<std::unique_ptr<Tracker>> ts;
  for (std::size_t i = 0; i < kBatch; ++i) ts.push_back(std::make_unique<Tracker>(*p->start));
  for (auto _ : state) {
    for (auto& t : ts) *t = *p->start;
    benchmark::ClobberMemory();
    const double t0 = thread_cpu_s();
    for (auto& t : ts) {
      Status s = t->step(p->scans[0]);
      benchmark::DoNotOptimize(s);
    }
    const double t1 = thread_cpu_s();
    state.SetIterationTime((t1 - t0) / static_cast<double>(kBatch));
  }
  state.SetItemsProcessed(state.iterations());
}

constexpr benchmark::IterationCount kRestartIterations = 5000;

template <class F>
void register_tracker_paths(const std::string& tail) {
  using Tracker = BenchTracker<F>;
  auto paths = std::make_shared<std::vector<TrackerPath<Tracker>>>(make_tracker_paths<F>());
  for (const auto& p : *paths) {
    const std::string name = "tracker/" + tail + p.name;
    if (p.restart) {
      // A fixed iteration count: the timed part (one step) is a few percent
      // of an iteration (16 tracker copies), so reaching --benchmark_min_time
      // of manual time took ~40x that in CPU time, and the unfiltered run
      // over 15 minutes. 5000 iterations are 80,000 timed steps.
      benchmark::RegisterBenchmark(name.c_str(), bm_tracker_restart<Tracker>, &p)
          ->UseManualTime()
          ->Iterations(kRestartIterations);
    } else {
      benchmark::RegisterBenchmark(name.c_str(), bm_tracker_sequence<Tracker>, &p);
    }
  }
  g_keep.push_back(paths);
}

/// The filter path of case n, and its tracker paths if kTrackerPaths<F>.
template <class F>
void register_case(const CaseName& n, const std::vector<FrameSi>& s1) {
  const std::string tail = std::string(n.filter) + "/" + n.scalar + "/" + n.form + "/";
  auto run = std::make_shared<const FilterRun<F>>(make_filter_run<F>(s1));
  benchmark::RegisterBenchmark(("filter/" + tail + "step").c_str(), bm_filter_step<F>, run.get());
  g_keep.push_back(run);
  if constexpr (kTrackerPaths<F>) register_tracker_paths<F>(tail);
}

}  // namespace
}  // namespace kestrel::bench

int main(int argc, char** argv) {
  using namespace kestrel::bench;
  try {
    const std::vector<FrameSi> s1 = s1_frames();
    for_each_filter_case([&]<class F>(const CaseName& n) { register_case<F>(n, s1); });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kestrel-bench: %s\n", e.what());
    return 1;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
