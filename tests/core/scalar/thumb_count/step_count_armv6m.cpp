// SPDX-License-Identifier: Apache-2.0
// Thumb instructions of one tracker step on the Cortex-M0+ code generation
// (docs/fixed-point.md, "Cost on the Cortex-M0+"): the board's tracker
// (EKF-CA radar tracker on Q31.32, 8 tracks x 32 plots, default parameters)
// built with the board's flags and run under qemu-arm's Linux user mode.
// Every measured step is bracketed by calls of kestrel_count_begin() and
// kestrel_count_end(); count_thumb_steps.py reads qemu's execution log (one
// line per instruction with -singlestep -d nochain,exec) and counts the
// lines between the two. Measured steps:
//   - normal: S1 seed 1 (s1_integer_scenario.hpp), those of steps 10..29
//     where one confirmed track takes its one plot (at least 10 of them, or
//     the program exits 1);
//   - full frame: 8 targets on straight radial tracks confirmed over 6
//     frames, then one frame of 32 plots (8 targets, 24 clutter plots
//     outside every gate, which find no free slot): 256 gate tests, 8
//     updates, 8 reports.
// Build and run: count_thumb_steps.py (it prints the command it runs).
#include <cstddef>
#include <cstdint>

#include "core/scalar/s1_integer_scenario.hpp"
#include "support/arm_linux_user.hpp"

namespace {

using kestrel::test::arm_linux_user::exit_with;
using kestrel::test::arm_linux_user::write_text;
using Q = kestrel::Q31_32;
using BoardTracker = kestrel::RadarTracker<kestrel::EkfCa<Q>, 8, 32>;

constexpr kestrel::RadarTrackerParams kParams{};
constexpr kestrel::RadarTrackerConfig<Q> kConfig = kestrel::radar_tracker_config<Q>(kParams);

}  // namespace

// The markers the log counter looks for: never inlined, never merged.
extern "C" __attribute__((noinline, used)) void kestrel_count_begin() { asm volatile("" ::: "memory"); }
extern "C" __attribute__((noinline, used)) void kestrel_count_end() { asm volatile("" ::: "memory"); }

extern "C" [[noreturn]] void kestrel_assert_failed(const char*, int, const char*) {
  write_text("assertion failed\n");
  exit_with(2);
}

namespace {

void write_digit_line(const char* text, int v) {
  char line[64];
  std::size_t i = 0;
  for (const char* p = text; *p != '\0' && i < 40; ++p) line[i++] = *p;
  char digits[12];
  std::size_t n = 0;
  do {
    digits[n++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v > 0 && n < sizeof digits);
  while (n > 0) line[i++] = digits[--n];
  line[i++] = '\n';
  line[i] = '\0';
  write_text(line);
}

/// S1 seed 1, steps 0..29; steps 10..29 measured. Writes one flag per
/// measured step, 1 where it took the normal path (one confirmed track
/// took its one plot): the counter keeps those.
bool run_normal(BoardTracker& tracker) {
  kestrel::test::S1Options o;
  o.seed = 1;
  kestrel::test::SplitMix64 rng(o.seed);
  BoardTracker::Scan scan;
  char flags[48] = "normal flags: ";
  std::size_t n = 14;
  int normal = 0;
  for (int k = 0; k < 30; ++k) {
    const kestrel::test::S1Sample sample = kestrel::test::s1_sample(k, o, rng);
    if (kestrel::hal::to_scan(kestrel::test::s1_frame(sample), scan) != kestrel::Status::kOk) return false;
    const bool measured = k >= 10;
    if (measured) kestrel_count_begin();
    const kestrel::Status s = tracker.step(scan);
    if (measured) kestrel_count_end();
    if (s != kestrel::Status::kOk) return false;
    if (measured) {
      const kestrel::StepStats& st = tracker.last_step();
      const bool is_normal = st.associated == 1 && st.seeded == 0 && st.initiated == 0 && st.deleted == 0 &&
                             tracker.tracks().size() == 1 && tracker.reports().size() == 1;
      flags[n++] = is_normal ? '1' : '0';
      normal += is_normal ? 1 : 0;
    }
  }
  flags[n++] = '\n';
  flags[n] = '\0';
  write_text(flags);
  return normal >= 10;
}

/// 8 targets, target i at bearing (i - 4) * 2^26 bam (about 2.8 deg apart),
/// range 5 km + i * 1.5 km, closing at 100 m/s; clutter plots at 60 km and
/// bearings far from every target. Frames every 0.5 s.
kestrel::hal::Frame crowd_frame(int k, bool with_clutter) {
  kestrel::hal::Frame f{};
  f.kind = kestrel::hal::FrameKind::kRadar;
  f.t_us = 500000 * static_cast<std::int64_t>(k);
  std::size_t n = 0;
  for (int i = 0; i < 8; ++i) {
    kestrel::hal::RadarPlot p{};
    p.range_mm = static_cast<std::uint32_t>(5000000 + 1500000 * i - 50000 * k);
    p.bearing_bam = (i - 4) * (std::int32_t{1} << 26);
    f.radar[n++] = p;
  }
  if (with_clutter) {
    for (int c = 0; c < 24; ++c) {
      kestrel::hal::RadarPlot p{};
      p.range_mm = 60000000u + 10000u * static_cast<std::uint32_t>(c);
      p.bearing_bam = (std::int32_t{1} << 30) + c * (std::int32_t{1} << 24);
      f.radar[n++] = p;
    }
  }
  f.count = static_cast<std::uint16_t>(n);
  return f;
}

bool run_full_frame(BoardTracker& tracker) {
  BoardTracker::Scan scan;
  for (int k = 0; k < 7; ++k) {
    const bool measured = k == 6;
    if (kestrel::hal::to_scan(crowd_frame(k, measured), scan) != kestrel::Status::kOk) return false;
    if (measured) kestrel_count_begin();
    const kestrel::Status s = tracker.step(scan);
    if (measured) kestrel_count_end();
    if (s != kestrel::Status::kOk) return false;
    if (measured && (tracker.last_step().associated != 8 || tracker.last_step().dropped != 24 ||
                     tracker.reports().size() != 8)) {
      write_digit_line("full frame: associated ", tracker.last_step().associated);
      write_digit_line("full frame: dropped ", tracker.last_step().dropped);
      write_digit_line("full frame: reports ", static_cast<int>(tracker.reports().size()));
      return false;
    }
  }
  return true;
}

}  // namespace

extern "C" [[noreturn]] void _start() {
  BoardTracker normal = kestrel::make_radar_tracker<Q, 8, 32>(kParams, kConfig);
  const bool ok_normal = run_normal(normal);
  write_text(ok_normal ? "normal: steps 10..29 measured\n" : "normal: fewer than 10 normal steps\n");
  BoardTracker crowd = kestrel::make_radar_tracker<Q, 8, 32>(kParams, kConfig);
  const bool ok_full = run_full_frame(crowd);
  write_text(ok_full ? "full frame: 1 step measured\n" : "full frame: a step did not take the full-frame path\n");
  const bool clean = kestrel::fixed_point_overflow_count() == 0;
  if (!clean) write_text("overflow events counted\n");
  exit_with(ok_normal && ok_full && clean ? 0 : 1);
}
