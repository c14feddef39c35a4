// SPDX-License-Identifier: Apache-2.0
// The image's hypotf (hypotf.cpp): libstdc++'s float stub, bit for bit,
// with the square root as one VSQRT.F32 instead of a call to newlib's
// errno-setting sqrtf.
#pragma once

extern "C" {
/// @param x, y  legs (for the tracker: Cartesian offsets, m).
/// @return sqrt(x^2 + y^2) as s sqrt((x/s)^2 + (y/s)^2), s = |x| + |y|; s when s is 0.
float kestrel_m4f_hypotf(float x, float y);
}
