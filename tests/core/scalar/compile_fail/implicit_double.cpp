// SPDX-License-Identifier: Apache-2.0
// A double never converts to fixed point implicitly (explicit constructor).
#include "kestrel/scalar/fixed_point.hpp"

kestrel::Q31_32 half() {
#ifdef KESTREL_SHOULD_FAIL
  return 0.5;
#else
  return kestrel::Q31_32(0.5);
#endif
}

int main() { return static_cast<int>(half().raw() & 1); }
