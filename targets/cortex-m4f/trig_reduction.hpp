// SPDX-License-Identifier: Apache-2.0
// The image's argument reduction for newlib's sinf and cosf (trig_reduction.cpp):
// x = n pi/2 + y[0] + y[1] for |x| <= 2^7 pi/2, bit for bit as newlib's
// __ieee754_rem_pio2f; NaN in y beyond.
#pragma once

extern "C" {
/// @param x  argument, rad.
/// @param y  out: y[0] + y[1] = x - n pi/2, |y[0] + y[1]| <= pi/4 (head and tail), rad;
///           both NaN if |x| > 2^7 pi/2 or x is not finite.
/// @return n, the quadrant count (only n mod 4 is used by sinf and cosf); 0 when y is NaN.
int kestrel_m4f_rem_pio2f(float x, float* y);
}
