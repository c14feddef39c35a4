// SPDX-License-Identifier: Apache-2.0
// `kestrel-sim timing --worst-case <board>`: the frame the board's
// instruction budget counts (tests/targets/frame_budget.py), timed on the
// host: the board's scalar, capacities (its board_config.hpp) and tracker
// parameters, the worst-case scene as wire frames
// (kestrel/board/worst_case_frame.hpp), adapter + Tracker::step of each
// counted frame, repeated from a copy of the tracker as it was before it.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cortex-m0plus/board_config.hpp"
#include "cortex-m4f/board_config.hpp"
#include "cortex-m7/board_config.hpp"
#include "kestrel/board/worst_case_frame.hpp"
#include "kestrel/hal/radar_adapter.hpp"
#include "kestrel/scalar/fixed_point_eigen.hpp"
#include "kestrel/tracking/radar_tracker.hpp"
#include "riscv64-linux/board_config.hpp"
#include "timing/step_timing.hpp"

namespace kestrel::sim::cli {

namespace {

constexpr std::size_t kCounted = board::kWorstCaseCountedFrames;

template <class Scalar, std::size_t kTracks, std::size_t kPlots>
int time_worst_case(const std::string& board, const char* scalar, std::size_t reps) {
  using Tracker = RadarTracker<EkfCa<Scalar>, kTracks, kPlots>;
  using Clock = std::chrono::steady_clock;
  auto tracker = std::make_unique<Tracker>(make_radar_tracker<Scalar, kTracks, kPlots>(RadarTrackerParams{}));
  auto frame = std::make_unique<hal::Frame>();
  auto before = std::make_unique<Tracker>(*tracker);
  typename Tracker::Scan scan{};
  const hal::RadarAdapter adapter{};
  const std::size_t frames = board::kWorstCaseWarmFrames + kCounted;
  std::printf("worst-case frame of %s on the host: %zu tracks x %zu plots, %s, frames_hash %llu\n", board.c_str(),
              kTracks, kPlots, scalar,
              static_cast<unsigned long long>(board::frames_hash(kTracks, kPlots, frames)));
  bool worst = true;
  for (std::size_t k = 0; k < frames; ++k) {
    board::worst_case_frame(kTracks, kPlots, k, *frame);
    if (k < board::kWorstCaseWarmFrames) {
      if (adapter(*frame, scan) != Status::kOk || tracker->step(scan) != Status::kOk) {
        throw std::runtime_error("warm-up frame " + std::to_string(k) + " was refused");
      }
      continue;
    }
    *before = *tracker;
    std::vector<std::uint64_t> ns;
    ns.reserve(reps);
    for (std::size_t r = 0; r < reps; ++r) {
      *tracker = *before;
      const auto t0 = Clock::now();
      const Status c = adapter(*frame, scan);
      const Status s = tracker->step(scan);
      const auto t1 = Clock::now();
      ns.push_back(static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count()));
      if (c != Status::kOk || s != Status::kOk) throw std::runtime_error("a counted frame was refused");
    }
    const StepStats& st = tracker->last_step();
    const bool ok = st.associated == kTracks && st.dropped == kPlots - kTracks && tracker->reports().size() == kTracks;
    worst = worst && ok;
    std::printf("  frame %zu (%s): associated %u, dropped %u, reports %zu\n", k, ok ? "worst case" : "NOT the worst case",
                static_cast<unsigned>(st.associated), static_cast<unsigned>(st.dropped), tracker->reports().size());
    const StepTiming t = summarise_step_times(ns, 0);
    std::printf("    adapter + step, %zu repetitions (SteadyClock, ns): min %llu  median %llu  p99 %llu  max %llu\n",
                t.steps, static_cast<unsigned long long>(t.min_ns), static_cast<unsigned long long>(t.median_ns),
                static_cast<unsigned long long>(t.p99_ns), static_cast<unsigned long long>(t.max_ns));
  }
  std::printf("  the board's instructions for these frames: targets/frame_budgets.json (frame_budget.py --table)\n");
  return worst ? 0 : 1;
}

}  // namespace

int cmd_timing_worst_case(const std::string& board, std::size_t reps) {
  if (reps == 0) throw std::invalid_argument("--runs must be at least 1");
  if (board == "cortex-m4f") return time_worst_case<float, m4f::kMaxTracks, m4f::kMaxPlots>(board, "float", reps);
  if (board == "cortex-m7") return time_worst_case<double, m7::kMaxTracks, m7::kMaxPlots>(board, "double", reps);
  if (board == "cortex-m0plus") {
    return time_worst_case<Q31_32, m0plus::kMaxTracks, m0plus::kMaxPlots>(board, "Q31.32", reps);
  }
  if (board == "riscv64-linux" || board == "host") {
    return time_worst_case<double, rv64::kMaxTracks, rv64::kMaxPlots>(board, "double", reps);
  }
  throw std::invalid_argument("--worst-case: unknown board '" + board +
                              "' (cortex-m4f, cortex-m7, cortex-m0plus, riscv64-linux, host)");
}

}  // namespace kestrel::sim::cli
