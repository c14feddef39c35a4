// SPDX-License-Identifier: Apache-2.0
// The worst-case frame at a board's capacity, for its instruction budget
// (tests/targets/frame_budget.py): the board's own Tracker type (board.hpp)
// built with the board's parameters, stepped through the worst-case scene
// (kestrel/board/worst_case_frame.hpp): kWorstCaseWarmFrames frames to
// confirm a full table, then kWorstCaseCountedFrames full frames, each
// converted by the board's adapter and stepped between calls of
// kestrel_count_mark(); the QEMU plugin (insn_count/qemu_insn_count.cpp)
// counts the instructions between those calls. Built in the board's
// tree with its code generation (targets/common/worst_frame.cmake) and run
// under qemu-arm or qemu-riscv64 Linux user mode. Prints, per counted frame,
// what the step did, and exits 1 if it was not the worst-case path (every
// track associated, every other plot dropped, a report per track).
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "board.hpp"
#include "kestrel/board/worst_case_frame.hpp"

#if defined(__arm__) && !defined(__linux__)
#include "support/arm_linux_user.hpp"
#else
#include <unistd.h>
#endif

namespace {

using namespace KESTREL_WF_NS;
using Scan = Tracker::Scan;
constexpr std::size_t kTracks = Tracker::Table::kMaxTracks;
constexpr std::size_t kPlots = Scan::kMaxMeasurements;
constexpr std::size_t kCounted = kestrel::board::kWorstCaseCountedFrames;

// As the board's main.cpp builds it (targets/<board>/main.cpp), with the
// board's filter type. Called from run(): without start files no static
// constructor runs.
using TrackFilter = std::remove_cvref_t<decltype(std::declval<const Tracker&>().prototype_filter())>;
#if defined(KESTREL_WF_CONSTEXPR_SCALARS)
constexpr kestrel::RadarTrackerParams kParams{};
constexpr kestrel::RadarTrackerConfig<Tracker::Scalar> kConfig =
    kestrel::radar_tracker_config<Tracker::Scalar>(kParams);
Tracker make_board_tracker() {
  return kestrel::make_radar_tracker<Tracker::Scalar, kMaxTracks, kMaxPlots, TrackFilter>(kParams, kConfig);
}
#else
Tracker make_board_tracker() {
  return kestrel::make_radar_tracker<Tracker::Scalar, kMaxTracks, kMaxPlots, TrackFilter>(kestrel::RadarTrackerParams{});
}
#endif
kestrel::hal::Frame g_frame{};
Scan g_scan{};

void write_out(const char* s, std::size_t n) {
#if defined(__arm__) && !defined(__linux__)
  kestrel::test::arm_linux_user::write_stdout(s, n);
#else
  static_cast<void>(::write(1, s, n));
#endif
}

struct Line {
  char text[160];
  std::size_t size = 0;
  Line& put(const char* s) {
    while (*s != '\0' && size < sizeof text) text[size++] = *s++;
    return *this;
  }
  Line& num(std::uint64_t v) {
    char d[20];
    std::size_t n = 0;
    do {
      d[n++] = static_cast<char>('0' + v % 10u);
      v /= 10u;
    } while (v != 0u && n < sizeof d);
    while (n > 0 && size < sizeof text) text[size++] = d[--n];
    return *this;
  }
  void flush() {
    put("\n");
    write_out(text, size);
  }
};

}  // namespace

// Its first instruction is what the plugin counts between; noinline and an
// empty asm keep it a real call the compiler cannot move across the step.
extern "C" __attribute__((noinline)) void kestrel_count_mark() { asm volatile("" ::: "memory"); }

namespace {

bool run() {
  using kestrel::Status;
  Line().put("board ").put(KESTREL_WF_BOARD).put(" tracks ").num(kTracks).put(" plots ").num(kPlots).flush();
  const std::size_t frames = kestrel::board::kWorstCaseWarmFrames + kCounted;
  Line().put("frames_hash ").num(kestrel::board::frames_hash(kTracks, kPlots, frames)).flush();
  static Tracker g_tracker = make_board_tracker();
  const kestrel::hal::RadarAdapter adapter{};
  bool ok = true;
  for (std::size_t k = 0; k < frames; ++k) {
    kestrel::board::worst_case_frame(kTracks, kPlots, k, g_frame);
    const bool counted = k >= kestrel::board::kWorstCaseWarmFrames;
    if (counted) kestrel_count_mark();
    const Status c = adapter(g_frame, g_scan);
    if (counted) kestrel_count_mark();
    const Status s = g_tracker.step(g_scan);
    if (!counted) continue;
    kestrel_count_mark();
    const kestrel::StepStats& st = g_tracker.last_step();
    const bool worst = c == Status::kOk && s == Status::kOk && st.associated == kTracks &&
                       st.dropped == kPlots - kTracks && g_tracker.reports().size() == kTracks;
    ok = ok && worst;
    Line()
        .put("frame ")
        .num(k)
        .put(worst ? " worst_case" : " NOT_worst_case")
        .put(" convert_status ")
        .num(static_cast<std::uint64_t>(c))
        .put(" step_status ")
        .num(static_cast<std::uint64_t>(s))
        .put(" associated ")
        .num(st.associated)
        .put(" dropped ")
        .num(st.dropped)
        .put(" reports ")
        .num(g_tracker.reports().size())
        .flush();
  }
  return ok;
}

}  // namespace

#if defined(__arm__) && !defined(__linux__)
extern "C" [[noreturn]] void kestrel_assert_failed(const char*, int, const char*) {
  kestrel::test::arm_linux_user::exit_with(2);
}
extern "C" [[noreturn]] void _start() { kestrel::test::arm_linux_user::exit_with(run() ? 0 : 1); }
#else
int main() { return run() ? 0 : 1; }
#endif
