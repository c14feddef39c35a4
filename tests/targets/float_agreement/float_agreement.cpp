// SPDX-License-Identifier: Apache-2.0
// The float radar tracker on S1 and S1n seed 1 (integer-generated frames,
// the same bytes on every platform: tests/core/scalar/s1_integer_scenario.hpp),
// one line per report with the exact bits of its state and of the diagonal
// of its covariance:
//   <scenario> <step> <track id> <status> <x0..x5 bits> <P00..P55 bits>
// Built twice: for the host (kestrel-float-agreement-host) and, with a
// Cortex-M board's own code generation, as a program that qemu-arm's Linux
// user mode runs (kestrel-float-agreement; no start files, output through
// the write system call). tests/targets/float_agreement/compare.py compares
// the two outputs (docs/decisions.md, "Floating-point contraction").
#include <bit>
#include <cstddef>
#include <cstdint>

#include "core/scalar/s1_integer_scenario.hpp"

#if defined(__arm__) && !defined(__linux__)
#define KESTREL_ARM_LINUX_USER 1
#include "support/arm_linux_user.hpp"
#else
#include <cstdio>
#include <cstdlib>
#endif

namespace {

constexpr std::size_t kLineCapacity = 160;

struct Line {
  char text[kLineCapacity];
  std::size_t size = 0;

  void put(char c) {
    if (size < kLineCapacity) text[size++] = c;
  }
  void put_decimal(std::uint32_t v) {
    char digits[10];
    std::size_t n = 0;
    do {
      digits[n++] = static_cast<char>('0' + v % 10u);
      v /= 10u;
    } while (v != 0u && n < sizeof(digits));
    while (n > 0) put(digits[--n]);
  }
  void put_hex(std::uint32_t v) {
    for (int d = 7; d >= 0; --d) put("0123456789abcdef"[(v >> (4 * d)) & 0xFu]);
  }
};

void write_line(const Line& line);

bool dump(const char* name, bool time_varying_noise) {
  kestrel::test::S1Options o;
  o.seed = 1;
  o.time_varying_noise = time_varying_noise;
  return kestrel::test::run_s1<float>(o, [name](int k, const kestrel::test::S1Sample&,
                                                const kestrel::test::S1Tracker<float>& tracker) {
    for (const auto& r : tracker.reports()) {
      Line line;
      for (const char* p = name; *p != '\0'; ++p) line.put(*p);
      line.put(' ');
      line.put_decimal(static_cast<std::uint32_t>(k));
      line.put(' ');
      line.put_decimal(r.track_id);
      line.put(' ');
      line.put_decimal(static_cast<std::uint32_t>(r.status));
      for (int i = 0; i < 6; ++i) {
        line.put(' ');
        line.put_hex(std::bit_cast<std::uint32_t>(r.x(i)));
      }
      for (int i = 0; i < 6; ++i) {
        line.put(' ');
        line.put_hex(std::bit_cast<std::uint32_t>(r.P(i, i)));
      }
      line.put('\n');
      write_line(line);
    }
  });
}

bool dump_all() { return dump("S1", false) && dump("S1n", true); }

}  // namespace

#ifdef KESTREL_ARM_LINUX_USER
// Bare-metal code generation run under qemu-arm's Linux user mode.
namespace {

using kestrel::test::arm_linux_user::exit_with;

void write_line(const Line& line) { kestrel::test::arm_linux_user::write_stdout(line.text, line.size); }

}  // namespace

extern "C" [[noreturn]] void kestrel_assert_failed(const char*, int, const char*) { exit_with(2); }

extern "C" [[noreturn]] void _start() { exit_with(dump_all() ? 0 : 1); }

#else
namespace {

void write_line(const Line& line) { std::fwrite(line.text, 1, line.size, stdout); }

}  // namespace

extern "C" [[noreturn]] void kestrel_assert_failed(const char* file, int line, const char* expr) {
  std::fprintf(stderr, "%s:%d: assertion failed: %s\n", file, line, expr);
  std::abort();
}

int main() { return dump_all() ? 0 : 1; }
#endif
