// SPDX-License-Identifier: Apache-2.0
// The image's remainderf (remainderf.cpp): the IEEE remainder x - n y (n the
// integer nearest x / y, ties to even), bit for bit as newlib's, for finite
// x, normal y and |x| <= 2^20 |y|; NaN otherwise.
#pragma once

extern "C" {
/// @param x  dividend (for the tracker: an angle, rad).
/// @param y  divisor (for the tracker: 2 pi, rad); |y| >= 2^-125.
/// @return x - n y, |result| <= |y| / 2, with the sign of x when zero;
///         NaN if x is not finite, |y| < 2^-125 or not finite, or |x| > 2^20 |y|.
float kestrel_m4f_remainderf(float x, float y);
}
