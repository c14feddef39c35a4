// SPDX-License-Identifier: Apache-2.0
// kestrel-rv64: the riscv64-linux board's main, a static Linux process.
// The Linux shell around the board loop (loop.cpp): open the input (a
// stream file, '-' for stdin, or a serial device, put in raw mode at the
// given baud rate), open the output for KTRK track records, find the cycle
// clock's rate, then run loop_poll_once() until the input ends (a file) or
// SIGINT/SIGTERM (a device), waiting in poll(2) when no frame is ready. On
// exit it prints the runner's statistics to stderr, in the format of
// kestrel-host-replay. This file may use stdio and the rest of libc; the
// tracker's code path (loop.cpp) may not, and is held to that by the
// heap-guard image.
//
//   kestrel-rv64 [--baud N] [--clock-hz N] [--budget-report] INPUT [TRACKS_OUT]
//     INPUT       stream file, '-' (stdin) or a tty such as /dev/ttyS1
//     TRACKS_OUT  file for KTRK v2 records, '-' for stdout (default), or the
//                 same tty as INPUT (records go back over the link)
//     --baud N    line rate when INPUT is a tty (default 115200)
//     --clock-hz  rate of the rdtime/rdcycle clock when the system does not
//                 tell (timebase-frequency / cpufreq)
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <type_traits>

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include "cycle_clock.hpp"
#include "loop.hpp"

namespace {

volatile std::sig_atomic_t g_stop = 0;

void on_signal(int) { g_stop = 1; }

speed_t baud_constant(long baud) {
  switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    case 1000000: return B1000000;
    case 2000000: return B2000000;
    default: return B0;
  }
}

/// Raw 8N1 at `baud`, no flow control: the link the microcontroller boards use.
bool configure_tty(int fd, long baud) {
  termios t{};
  if (::tcgetattr(fd, &t) != 0) return false;
  ::cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS);
  const speed_t speed = baud_constant(baud);
  if (speed == B0 || ::cfsetispeed(&t, speed) != 0 || ::cfsetospeed(&t, speed) != 0) return false;
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  return ::tcsetattr(fd, TCSANOW, &t) == 0;
}

/// A big-endian u32 file such as /proc/device-tree/cpus/timebase-frequency.
std::uint64_t read_be32_file(const char* path) {
  std::FILE* f = std::fopen(path, "rb");
  if (f == nullptr) return 0;
  unsigned char b[4] = {};
  const std::size_t n = std::fread(b, 1, 4, f);
  std::fclose(f);
  if (n != 4) return 0;
  return (std::uint64_t{b[0]} << 24) | (std::uint64_t{b[1]} << 16) | (std::uint64_t{b[2]} << 8) | b[3];
}

/// A decimal file such as cpuinfo_max_freq (kHz).
std::uint64_t read_decimal_file(const char* path) {
  std::FILE* f = std::fopen(path, "r");
  if (f == nullptr) return 0;
  unsigned long long v = 0;
  const int n = std::fscanf(f, "%llu", &v);
  std::fclose(f);
  return n == 1 ? v : 0;
}

std::uint64_t system_clock_hz() {
  if constexpr (std::is_same_v<kestrel::rv64::CycleClock, kestrel::rv64::RdtimeClock>) {
    return read_be32_file("/proc/device-tree/cpus/timebase-frequency");
  } else if constexpr (std::is_same_v<kestrel::rv64::CycleClock, kestrel::rv64::RdcycleClock>) {
    return read_decimal_file("/sys/devices/system/cpu/cpu0/cpufreq/cpuinfo_max_freq") * 1000u;
  } else {
    return 1'000'000'000u;
  }
}

void print_stats() {
  using kestrel::Status;
  const kestrel::hal::RunnerStats& s = kestrel::rv64::loop_stats();
  const double hz = static_cast<double>(kestrel::rv64::loop_clock_hz());
  const double budget_us = static_cast<double>(kestrel::rv64::loop_budget_cycles()) / hz * 1e6;
  std::fprintf(stderr, "frames %u, steps %u, overruns %u (budget %.1f us), publish failures %u\n", s.frames,
               s.steps, s.overruns, budget_us, s.publish_failures);
  if (s.steps > 0) {
    std::fprintf(stderr, "step cycles (%s, %.0f Hz): min %llu, mean %llu, max %llu\n",
                 kestrel::rv64::loop_clock_name(), hz, static_cast<unsigned long long>(s.min_cycles),
                 static_cast<unsigned long long>(s.total_cycles / s.steps),
                 static_cast<unsigned long long>(s.max_cycles));
    std::fprintf(stderr, "step ns: min %.0f, mean %.0f, max %.0f\n", static_cast<double>(s.min_cycles) / hz * 1e9,
                 static_cast<double>(s.total_cycles / s.steps) / hz * 1e9,
                 static_cast<double>(s.max_cycles) / hz * 1e9);
  }
  for (std::uint8_t i = 0; i < kestrel::kStatusCount; ++i) {
    if (s.by_status[i] != 0) {
      std::fprintf(stderr, "  %-22s %u\n", kestrel::to_string(static_cast<Status>(i)), s.by_status[i]);
    }
  }
  if (kestrel::rv64::loop_read_errors() + kestrel::rv64::loop_write_errors() + kestrel::rv64::loop_dropped_reports() !=
      0) {
    std::fprintf(stderr, "read errors %u, write errors %u, reports dropped %u\n", kestrel::rv64::loop_read_errors(),
                 kestrel::rv64::loop_write_errors(), kestrel::rv64::loop_dropped_reports());
  }
}

int usage(const char* argv0) {
  std::fprintf(stderr, "usage: %s [--baud N] [--clock-hz N] INPUT [TRACKS_OUT]\n", argv0);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  long baud = 115200;
  std::uint64_t clock_hz = 0;
  int arg = 1;
  for (; arg < argc && std::strncmp(argv[arg], "--", 2) == 0 && argv[arg][2] != '\0'; arg += 2) {
    if (arg + 1 >= argc) return usage(argv[0]);
    if (std::strcmp(argv[arg], "--baud") == 0) {
      baud = std::strtol(argv[arg + 1], nullptr, 10);
    } else if (std::strcmp(argv[arg], "--clock-hz") == 0) {
      clock_hz = std::strtoull(argv[arg + 1], nullptr, 10);
    } else {
      return usage(argv[0]);
    }
  }
  if (argc - arg < 1 || argc - arg > 2) return usage(argv[0]);
  const char* input = argv[arg];
  const char* output = argc - arg == 2 ? argv[arg + 1] : "-";

  int in_fd = STDIN_FILENO;
  if (std::strcmp(input, "-") != 0) {
    in_fd = ::open(input, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (in_fd < 0) in_fd = ::open(input, O_RDONLY | O_NONBLOCK | O_CLOEXEC);  // a read-only file
    if (in_fd < 0) {
      std::fprintf(stderr, "kestrel-rv64: cannot open %s: %s\n", input, std::strerror(errno));
      return 1;
    }
  } else {
    (void)::fcntl(in_fd, F_SETFL, ::fcntl(in_fd, F_GETFL) | O_NONBLOCK);
  }
  const bool tty = ::isatty(in_fd) != 0;
  if (tty && !configure_tty(in_fd, baud)) {
    std::fprintf(stderr, "kestrel-rv64: cannot set %s to raw 8N1 at %ld baud\n", input, baud);
    return 1;
  }

  int out_fd = STDOUT_FILENO;
  if (std::strcmp(output, "-") != 0) {
    out_fd = std::strcmp(output, input) == 0 ? in_fd : ::open(output, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (out_fd < 0) {
      std::fprintf(stderr, "kestrel-rv64: cannot open %s: %s\n", output, std::strerror(errno));
      return 1;
    }
  }

  if (clock_hz == 0) clock_hz = system_clock_hz();
  if (kestrel::rv64::CycleClock::kNeedsRate && clock_hz == 0) {
    std::fprintf(stderr, "kestrel-rv64: the rate of %s is unknown: pass --clock-hz\n",
                 kestrel::rv64::CycleClock::kName);
    return 1;
  }
  kestrel::rv64::loop_init(in_fd, out_fd, clock_hz);

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  while (g_stop == 0) {
    if (kestrel::rv64::loop_poll_once() != kestrel::Status::kNoData) continue;
    if (kestrel::rv64::loop_input_ended()) break;
    // Nothing ready: wait for input outside the loop (the feed never blocks).
    pollfd p{in_fd, POLLIN, 0};
    (void)::poll(&p, 1, 100);
  }
  print_stats();
  return 0;
}
