// SPDX-License-Identifier: Apache-2.0
// A double -> fixed-point conversion at run time must not compile: the
// constructor from double is consteval (a board never converts a double).
#include "kestrel/scalar/fixed_point.hpp"

int main(int argc, char**) {
  const double seconds = 0.5 * argc;
#ifdef KESTREL_SHOULD_FAIL
  const kestrel::Q31_32 dt(seconds);
#else
  const kestrel::Q31_32 dt = kestrel::Q31_32::from_ratio(500 * argc, 1000);
  static_cast<void>(seconds);
#endif
  return static_cast<int>(dt.raw() & 1);
}
