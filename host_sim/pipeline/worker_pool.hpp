// SPDX-License-Identifier: Apache-2.0
// The one worker pool of kestrel-sim: every Monte Carlo loop (radar runs,
// PCL, sonar, the MC-001 campaign) hands out its run indices through it.
// Results are stored by index, so they never depend on the thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace kestrel::sim {

/// How for_each_index reports progress.
struct Progress {
  const char* label = nullptr;  ///< nullptr: silent. Otherwise "<label>: n/N <unit> ..." on stderr.
  const char* unit = "runs";
};

/// Run work(i) for every i in [0, items) on `jobs` threads (at most one per
/// item; 1 runs on the calling thread), indices handed out in order. The
/// first exception stops the hand-out and is rethrown once every thread
/// has joined. With progress.label set and a loop that lasts over 2 s, a
/// progress line on stderr twice a second and a closing line with the wall
/// time. @return that wall time, s.
template <class Work>
double for_each_index(std::size_t items, unsigned jobs, Work&& work, Progress progress = {}) {
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::atomic<bool> finished{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto worker = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= items) return;
      try {
        work(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = items;  // stop handing out work
      }
      done.fetch_add(1);
    }
  };
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::thread reporter;
  std::atomic<bool> reported{false};
  if (progress.label != nullptr) {
    reporter = std::thread([&] {
      // Silent for the first 2 s: only a command that takes a while talks.
      for (int k = 0; k < 40 && !finished.load(); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(50));
      while (!finished.load()) {
        reported = true;
        const std::size_t n = done.load();
        const double t = elapsed();
        const double left = n > 0 ? t * static_cast<double>(items - n) / static_cast<double>(n) : 0.0;
        std::fprintf(stderr, "\r%s: %zu/%zu %s (%.0f %%), %.0f s elapsed, about %.0f s left   ", progress.label, n,
                     items, progress.unit, items > 0 ? 100.0 * static_cast<double>(n) / static_cast<double>(items) : 100.0,
                     t, left);
        for (int k = 0; k < 10 && !finished.load(); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    });
  }
  const unsigned threads = std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(std::max<std::size_t>(items, 1))));
  std::vector<std::thread> pool;
  for (unsigned j = 1; j < threads; ++j) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  finished = true;
  const double wall = elapsed();
  if (reporter.joinable()) reporter.join();
  if (reported.load()) {
    std::fprintf(stderr, "\r%s: %zu/%zu %s, %.1f s with %u thread%s                              \n", progress.label,
                 done.load(), items, progress.unit, wall, threads, threads == 1 ? "" : "s");
  }
  if (failure) std::rethrow_exception(failure);
  return wall;
}

}  // namespace kestrel::sim
