// SPDX-License-Identifier: Apache-2.0
// kestrel-host-replay: what a board's main() does, on the host. Open the
// feed (a stream file instead of a UART), build the tracker, then poll until
// the feed is exhausted, writing every report to a CSV sink. No simulation,
// no scoring: kestrel-sim does that. Usage:
//
//   kestrel-host-replay STREAM_FILE TRACKS_CSV [BUDGET_US]
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>

#include "kestrel/host/board.hpp"

namespace {

using Tracker = kestrel::host::BoardRadarTracker<kestrel::EkfCa<double>>;

int replay(const char* stream_path, const char* csv_path, double budget_us) {
  using kestrel::Status;
  kestrel::host::Feed feed = kestrel::host::StreamFileFeed::open(stream_path);
  kestrel::host::Clock clock;
  kestrel::host::CsvTrackSink sink(csv_path);
  // The tracker is large (the whole track table): keep it off the stack.
  auto tracker = std::make_unique<Tracker>(
      kestrel::make_radar_tracker<double, kestrel::host::kMaxTracks, kestrel::host::kMaxPlots>(
          kestrel::RadarTrackerParams{}));
  const auto budget_cycles = static_cast<std::uint64_t>(budget_us * 1e-6 * double(clock.cycles_per_second()));
  kestrel::host::BoardRunner<Tracker, kestrel::host::CsvTrackSink> runner(
      feed, clock, *tracker, kestrel::hal::RadarAdapter{}, sink, budget_cycles);

  // The board loop. On a board this spins forever; a file ends.
  while (runner.poll_once() != Status::kNoData) {
  }

  const kestrel::hal::RunnerStats& s = runner.stats();
  std::printf("frames %u, steps %u, overruns %u (budget %.1f us), publish failures %u\n", s.frames, s.steps,
              s.overruns, budget_us, s.publish_failures);
  if (s.steps > 0) {
    std::printf("step ns: min %llu, mean %llu, max %llu\n", static_cast<unsigned long long>(s.min_cycles),
                static_cast<unsigned long long>(s.total_cycles / s.steps),
                static_cast<unsigned long long>(s.max_cycles));
  }
  for (std::uint8_t i = 0; i < kestrel::kStatusCount; ++i) {
    if (s.by_status[i] != 0) {
      std::printf("  %-22s %u\n", kestrel::to_string(static_cast<Status>(i)), s.by_status[i]);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: %s STREAM_FILE TRACKS_CSV [BUDGET_US]\n", argv[0]);
    return 2;
  }
  try {
    return replay(argv[1], argv[2], argc == 4 ? std::atof(argv[3]) : 1000.0);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kestrel-host-replay: %s\n", e.what());
    return 1;
  }
}
