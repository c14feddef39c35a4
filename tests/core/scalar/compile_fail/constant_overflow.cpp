// SPDX-License-Identifier: Apache-2.0
// A constant outside the format's range is a compile error, not a silent
// saturation: Q23.40 holds +-8.4e6.
#include "kestrel/scalar/fixed_point_math.hpp"

#ifdef KESTREL_SHOULD_FAIL
constexpr kestrel::Q23_40 kRangeM(1.0e7);
#else
constexpr kestrel::Q23_40 kRangeM(1.0e6);
#endif
constexpr kestrel::Q23_40 kSquared = kRangeM * kestrel::Q23_40(2);

int main() { return static_cast<int>(kSquared.raw() & 1); }
