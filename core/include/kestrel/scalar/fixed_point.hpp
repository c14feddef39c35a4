// SPDX-License-Identifier: Apache-2.0
// The project's fixed-point scalar for FPU-less cores: a signed Q-format
// number on int64 storage, templated on the fraction bits (Q31.32 by
// default, Q23.40 as the fine-grained option). Every operation is integer
// only and correctly rounded (to nearest, ties to even), with no __int128,
// so the same source gives the same bits on x86-64, i386 and a Cortex-M0+:
// a host replay proves what the board computed. An out-of-range result
// saturates to +-(2^63 - 1) raw, which the type treats as non-finite, as
// float treats Inf/NaN (a filter refuses the step; a counter records it);
// in a constant expression it is a compile error. A double converts only at
// compile time (consteval). Math functions and ScalarTraits are in
// fixed_point_math.hpp, the Eigen glue in fixed_point_eigen.hpp. Operations,
// saturation and construction: docs/fixed-point.md, "Formats".
#pragma once

#include <bit>
#include <concepts>
#include <cstdint>
#include <type_traits>
#include <utility>

// Thumb-1 (Cortex-M0+) builds keep one out-of-line copy of the product and
// of the prepared division: inlined, each is about 150 bytes of 64-bit
// arithmetic, and the filters' kernels hold hundreds of products (the
// board's text budget).
#if defined(__thumb__) && !defined(__thumb2__)
#define KESTREL_FIXED_MUL_OUTLINE [[gnu::noinline]]
#define KESTREL_FIXED_MUL_PART [[gnu::always_inline]]
#else
#define KESTREL_FIXED_MUL_OUTLINE
#define KESTREL_FIXED_MUL_PART
#endif

namespace kestrel {
namespace fixed {

namespace detail {

inline constexpr std::int64_t kPosOverflow = INT64_MAX;   ///< Raw value of +saturation.
inline constexpr std::int64_t kNegOverflow = -INT64_MAX;  ///< Raw value of -saturation.
inline constexpr std::int64_t kMaxFinite = INT64_MAX - 1; ///< Largest finite raw magnitude.

// One counter per thread on a hosted OS (host_sim may run filters in
// parallel); a plain global on bare metal, where there is one thread and
// thread_local would need TLS support.
#if defined(__unix__) || defined(__APPLE__) || defined(_WIN32)
inline thread_local std::uint32_t overflow_events = 0;
#else
inline std::uint32_t overflow_events = 0;
#endif

/// Count a saturation. During constant evaluation the division by zero
/// makes the expression ill-formed instead: an overflowing constant fails
/// to compile ("division by zero is not a constant expression").
constexpr void note_overflow() {
  if (std::is_constant_evaluated()) {
    int fixed_point_overflow_in_constant_expression = 0;
    fixed_point_overflow_in_constant_expression = 1 / fixed_point_overflow_in_constant_expression;
  } else {
    ++overflow_events;
  }
}

/// An unsigned 128-bit integer as two 64-bit words.
struct U128 {
  std::uint64_t hi;
  std::uint64_t lo;
};

constexpr std::uint64_t lo32(std::uint64_t v) { return v & 0xFFFFFFFFu; }

/// Exact 32 x 32 -> 64-bit product from four 16 x 16 -> 32-bit products:
/// what a core without a long multiply (ARMv6-M's MULS gives the low 32
/// bits only) does, inline, where the compiler would call the general
/// 64 x 64-bit __aeabi_lmul for each piece.
KESTREL_FIXED_MUL_PART constexpr std::uint64_t mul_32x32_limbs(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t a0 = a & 0xFFFFu;
  const std::uint32_t a1 = a >> 16;
  const std::uint32_t b0 = b & 0xFFFFu;
  const std::uint32_t b1 = b >> 16;
  const std::uint32_t p00 = a0 * b0;
  const std::uint32_t p01 = a0 * b1;
  const std::uint32_t p10 = a1 * b0;
  const std::uint32_t p11 = a1 * b1;
  const std::uint32_t mid = p01 + p10;
  const std::uint32_t mid_carry = mid < p01 ? 0x10000u : 0u;  // bit 32 of mid, weight 2^48
  const std::uint32_t lo = p00 + (mid << 16);
  const std::uint32_t lo_carry = lo < p00 ? 1u : 0u;
  const std::uint32_t hi = p11 + (mid >> 16) + mid_carry + lo_carry;
  return (std::uint64_t{hi} << 32) | lo;
}

/// Exact 32 x 32 -> 64-bit product: mul_32x32_limbs() on Thumb-1 (no
/// long multiply), the native product elsewhere. The same value either way.
KESTREL_FIXED_MUL_PART constexpr std::uint64_t mul_32x32(std::uint64_t a, std::uint64_t b) {
#if defined(__thumb__) && !defined(__thumb2__)
  return mul_32x32_limbs(static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b));
#else
  return a * b;
#endif
}

/// Exact 64 x 64 -> 128-bit product from four 32 x 32 -> 64-bit products.
KESTREL_FIXED_MUL_PART constexpr U128 mul_wide(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t a0 = lo32(a);
  const std::uint64_t a1 = a >> 32;
  const std::uint64_t b0 = lo32(b);
  const std::uint64_t b1 = b >> 32;
  // An operand below 2^32 (a value below 1) needs two pieces, not four:
  // without a long multiply (Thumb-1) each piece is four MULS and carries.
  if (a1 == 0 || b1 == 0) {
    const std::uint64_t s = a1 == 0 ? a0 : b0;  // the short operand
    const std::uint64_t l = a1 == 0 ? b : a;
    const std::uint64_t q0 = mul_32x32(s, lo32(l));
    const std::uint64_t q1 = mul_32x32(s, l >> 32) + (q0 >> 32);  // < 2^64: no carry out
    return U128{q1 >> 32, (q1 << 32) | lo32(q0)};
  }
  const std::uint64_t p00 = mul_32x32(a0, b0);
  const std::uint64_t p01 = mul_32x32(a0, b1);
  const std::uint64_t p10 = mul_32x32(a1, b0);
  const std::uint64_t p11 = mul_32x32(a1, b1);
  const std::uint64_t mid = (p00 >> 32) + lo32(p01) + lo32(p10);  // < 3 * 2^32: no carry out
  return U128{p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32), (mid << 32) | lo32(p00)};
}

KESTREL_FIXED_MUL_PART constexpr U128 add(U128 a, U128 b) {
  const std::uint64_t lo = a.lo + b.lo;
  return U128{a.hi + b.hi + (lo < a.lo ? 1u : 0u), lo};
}

constexpr U128 sub(U128 a, U128 b) {
  return U128{a.hi - b.hi - (a.lo < b.lo ? 1u : 0u), a.lo - b.lo};
}

constexpr bool less(U128 a, U128 b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }

/// a << s for 0 <= s < 128.
KESTREL_FIXED_MUL_PART constexpr U128 shl(U128 a, int s) {
  if (s == 0) return a;
  if (s >= 64) return U128{a.lo << (s - 64), 0};
  return U128{(a.hi << s) | (a.lo >> (64 - s)), a.lo << s};
}

/// a >> s for 0 <= s < 128.
KESTREL_FIXED_MUL_PART constexpr U128 shr(U128 a, int s) {
  if (s == 0) return a;
  if (s >= 64) return U128{0, a.hi >> (s - 64)};
  return U128{a.hi >> s, (a.lo >> s) | (a.hi << (64 - s))};
}

/// round(v / 2^s), ties to even, for 0 <= s < 64.
constexpr U128 round_shift(U128 v, int s) {
  if (s == 0) return v;
  U128 q = shr(v, s);
  const std::uint64_t mask = (std::uint64_t{1} << s) - 1u;
  const std::uint64_t rem = v.lo & mask;
  const std::uint64_t half = std::uint64_t{1} << (s - 1);
  if (rem > half || (rem == half && (q.lo & 1u) != 0)) q = add(q, U128{0, 1});
  return q;
}

/// round_shift() by a shift known at compile time (the product's): on a
/// 32-bit core the 128-bit shifts become word moves instead of calls.
template <int s>
KESTREL_FIXED_MUL_PART constexpr U128 round_shift_by(U128 v) {
  static_assert(s > 0 && s < 64);
  const std::uint64_t q_hi = v.hi >> s;
  const std::uint64_t q_lo = (v.lo >> s) | (v.hi << (64 - s));
  const std::uint64_t rem = v.lo & ((std::uint64_t{1} << s) - 1u);
  constexpr std::uint64_t kHalf = std::uint64_t{1} << (s - 1);
  const bool up = rem > kHalf || (rem == kHalf && (q_lo & 1u) != 0);
  if (!up) return U128{q_hi, q_lo};
  return U128{q_hi + (q_lo + 1u == 0 ? 1u : 0u), q_lo + 1u};
}

/// |v| as uint64 (exact for INT64_MIN too).
constexpr std::uint64_t magnitude(std::int64_t v) {
  return v < 0 ? 0u - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
}

/// sign * mag as a finite raw value, or saturation (counted) when it does not fit.
constexpr std::int64_t to_raw_saturating(U128 mag, bool negative) {
  if (mag.hi != 0 || mag.lo > static_cast<std::uint64_t>(kMaxFinite)) {
    note_overflow();
    return negative ? kNegOverflow : kPosOverflow;
  }
  const auto m = static_cast<std::int64_t>(mag.lo);
  return negative ? -m : m;
}

/// Quotient and remainder of a 128 / 64-bit unsigned division.
struct DivResult {
  std::uint64_t q;
  std::uint64_t r;
};

/// Bit length of v > 0 (1..64).
constexpr int bit_length(std::uint64_t v) { return 64 - std::countl_zero(v); }

/// Bit length of v (0 for v == 0).
constexpr int bit_length(U128 v) {
  if (v.hi != 0) return 64 + bit_length(v.hi);
  return v.lo != 0 ? bit_length(v.lo) : 0;
}

#if defined(__thumb__) && !defined(__thumb2__)
/// The loop of udiv() below in Thumb-1 (ARMv6-M), steps > 0 iterations on
/// remainder r and dividend/quotient word lo: the same steps and result as
/// the C loop, about 12 instructions per quotient bit where the compiler's
/// 64-bit code takes 22 (the golden hashes run it under qemu-arm).
inline DivResult udiv_thumb1(std::uint64_t r, std::uint64_t lo, std::uint64_t d, int steps) {
  auto l0 = static_cast<std::uint32_t>(lo);
  auto l1 = static_cast<std::uint32_t>(lo >> 32);
  auto r0 = static_cast<std::uint32_t>(r);
  auto r1 = static_cast<std::uint32_t>(r >> 32);
  const auto d0 = static_cast<std::uint32_t>(d);
  const auto d1 = static_cast<std::uint32_t>(d >> 32);
  auto left = static_cast<std::uint32_t>(steps);
  asm(".syntax unified\n"  // GCC hands inline Thumb asm over in divided syntax
      "1:\n\t"
      "adds  %[l0], %[l0], %[l0]\n\t"  // (r:lo) <<= 1; the carry is the remainder's 65th bit
      "adcs  %[l1], %[l1]\n\t"
      "adcs  %[r0], %[r0]\n\t"
      "adcs  %[r1], %[r1]\n\t"
      "bcs   2f\n\t"                   // r >= 2^64 > d
      "cmp   %[r1], %[d1]\n\t"
      "bhi   2f\n\t"
      "bne   3f\n\t"
      "cmp   %[r0], %[d0]\n\t"
      "bcc   3f\n"                     // r < d: quotient bit 0
      "2:\n\t"
      "subs  %[r0], %[r0], %[d0]\n\t"  // r -= d (modulo 2^64: exact)
      "sbcs  %[r1], %[d1]\n\t"
      "adds  %[l0], %[l0], #1\n"        // quotient bit 1 (bit 0 is free after the shift)
      "3:\n\t"
      "subs  %[left], %[left], #1\n\t"
      "bne   1b\n\t"
      ".syntax divided"
      : [l0] "+l"(l0), [l1] "+l"(l1), [r0] "+l"(r0), [r1] "+l"(r1), [left] "+l"(left)
      : [d0] "l"(d0), [d1] "l"(d1)
      : "cc");
  return DivResult{(std::uint64_t{l1} << 32) | l0, (std::uint64_t{r1} << 32) | r0};
}
#endif

/// floor(n / d) and n mod d for d != 0 and n.hi < d (so the quotient fits in
/// 64 bits): restoring shift-subtract, one quotient bit per iteration (no
/// hardware divider needed). Leading quotient bits that must be zero (n
/// has too few bits for them) are skipped: at most 64 iterations, fewer
/// the smaller the quotient.
constexpr DivResult udiv(U128 n, std::uint64_t d) {
  int skip = bit_length(d) + 63 - bit_length(n);  // floor(n / 2^(64 - skip)) < d
  skip = skip < 0 ? 0 : (skip > 64 ? 64 : skip);
  const U128 start = shl(n, skip);
  std::uint64_t r = start.hi;
  std::uint64_t lo = start.lo;  // dividend bits shift out at the top, quotient bits in at the bottom
#if defined(__thumb__) && !defined(__thumb2__)
  if (!std::is_constant_evaluated() && skip < 64) {
    return udiv_thumb1(r, lo, d, 64 - skip);
  }
#endif
  for (int i = skip; i < 64; ++i) {
    const bool carry = (r >> 63) != 0;  // the shifted remainder has 65 bits
    r = (r << 1) | (lo >> 63);
    lo <<= 1;
    if (carry || r >= d) {
      r -= d;  // modulo 2^64: exact, since the true remainder is < d
      lo |= 1u;
    }
  }
  return DivResult{lo, r};
}

/// round(n / d), ties to even, for d != 0; {1, 0} (>= 2^64) when the
/// quotient does not fit in 64 bits.
constexpr U128 udiv_round(U128 n, std::uint64_t d) {
  if (n.hi >= d) return U128{1, 0};
  DivResult qr = udiv(n, d);
  const bool r_top = (qr.r >> 63) != 0;
  const std::uint64_t r2 = qr.r << 1;
  const bool up = r_top || r2 > d || (r2 == d && (qr.q & 1u) != 0);
  if (up) {
    ++qr.q;
    if (qr.q == 0) return U128{1, 0};
  }
  return U128{0, qr.q};
}

/// round(v / 2^s), ties away from zero in magnitude, for 0 < s < 128.
KESTREL_FIXED_MUL_PART constexpr U128 round_shift_wide(U128 v, int s) { return shr(add(v, shl(U128{0, 1}, s - 1)), s); }

/// round(sqrt(n)) of an unsigned 128-bit integer, digit by digit: each
/// step brings down two bits of n (n.hi's, then n.lo's) and gives one root
/// bit. Leading zero pairs of n give zero root bits and are skipped: at
/// most 64 steps. The remainder is at most 2 root (< 2^65) between steps
/// and 4 times that plus 3 within one: 64 bits and a small high word.
/// Never a tie: n is an integer.
constexpr std::uint64_t isqrt_round(U128 n) {
  const int skip = (128 - bit_length(n)) / 2;
  if (skip == 64) return 0;
  std::uint64_t rem_lo = 0;
  std::uint32_t rem_hi = 0;
  std::uint64_t root = 0;
  for (int half = skip / 32; half < 2; ++half) {
    const int first = half == skip / 32 ? skip % 32 : 0;
    std::uint64_t digits = (half == 0 ? n.hi : n.lo) << (2 * first);  // the pairs still to bring down, at the top
    for (int i = first; i < 32; ++i) {
      rem_hi = (rem_hi << 2) | static_cast<std::uint32_t>(rem_lo >> 62);
      rem_lo = (rem_lo << 2) | (digits >> 62);
      digits <<= 2;
      const std::uint64_t trial_lo = (root << 2) | 1u;  // 4 root + 1
      const auto trial_hi = static_cast<std::uint32_t>(root >> 62);
      root <<= 1;
      if (rem_hi > trial_hi || (rem_hi == trial_hi && rem_lo >= trial_lo)) {
        rem_hi = rem_hi - trial_hi - (rem_lo < trial_lo ? 1u : 0u);
        rem_lo -= trial_lo;
        root |= 1u;
      }
    }
  }
  // n = root^2 + rem; round(sqrt(n)) = root + 1 iff n > root^2 + root.
  if (rem_hi != 0 || rem_lo > root) ++root;
  return root;
}

/// round(sign(v) * |m| * 2^e) for a double's integer mantissa m and exponent e,
/// with saturation; exact integer work so it is bit-identical everywhere.
constexpr std::int64_t scale_mantissa(std::uint64_t mant, int e, bool negative) {
  if (mant == 0) return 0;
  if (e >= 0) {
    if (e >= 64) return to_raw_saturating(U128{1, 0}, negative);
    return to_raw_saturating(shl(U128{0, mant}, e), negative);
  }
  if (-e >= 64) return 0;  // |value| < 2^53 * 2^-64 < 0.5
  return to_raw_saturating(round_shift(U128{0, mant}, -e), negative);
}

}  // namespace detail

/// A signed fixed-point number with kFracBits fraction bits on int64
/// storage: value = raw / 2^kFracBits, range +-2^(63 - kFracBits).
template <int kFracBits>
class FixedPoint {
  static_assert(kFracBits >= 1 && kFracBits <= 60,
                "1..60 fraction bits (the math functions work at 2^-60 internally)");

 public:
  using Raw = std::int64_t;
  static constexpr int kFractionBits = kFracBits;
  static constexpr int kIntegerBits = 63 - kFracBits;  ///< Excluding the sign bit.
  static constexpr Raw kOne = Raw{1} << kFracBits;     ///< Raw value of 1.

  constexpr FixedPoint() = default;

  /// Exact from an integer (saturating and counted if out of range). Implicit,
  /// as Eigen and generic code write Scalar(0), Scalar(1), x / Scalar(2).
  template <std::integral I>
    requires(!std::same_as<I, bool>)
  constexpr FixedPoint(I v) : raw_(from_integer(v)) {}  // NOLINT(google-explicit-constructor)

  /// From a double literal, at compile time only: a fixed-point image never
  /// converts a double at run time. Round to nearest, ties to even.
  explicit consteval FixedPoint(double v) : raw_(from_double(v).raw_) {}

  static constexpr FixedPoint from_raw(Raw raw) {
    FixedPoint q;
    q.raw_ = raw;
    return q;
  }

  /// Round to nearest (ties to even) from a double, by integer work on its
  /// bits, so the result is the same on every host. NaN and out-of-range
  /// values saturate (counted). Host code and constant expressions only: on
  /// a board, use integer units and from_ratio().
  static constexpr FixedPoint from_double(double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    const bool negative = (bits >> 63) != 0;
    const int biased = static_cast<int>((bits >> 52) & 0x7FFu);
    std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1u);
    if (biased == 0x7FF) {  // Inf or NaN
      detail::note_overflow();
      return from_raw(negative && mant == 0 ? detail::kNegOverflow : detail::kPosOverflow);
    }
    int e = -1074;  // subnormal
    if (biased != 0) {
      mant |= std::uint64_t{1} << 52;
      e = biased - 1075;
    }
    return from_raw(detail::scale_mantissa(mant, e + kFracBits, negative));
  }

  /// round(num / den), ties to even, for integer sensor units (e.g. range in
  /// mm: den = 1000). Exact integer division; den == 0 saturates (counted).
  static constexpr FixedPoint from_ratio(std::int64_t num, std::int64_t den) {
    if (den == 0) {
      detail::note_overflow();
      return from_raw(num < 0 ? detail::kNegOverflow : detail::kPosOverflow);
    }
    const bool negative = (num < 0) != (den < 0);
    const detail::U128 n = detail::shl(detail::U128{0, detail::magnitude(num)}, kFracBits);
    return from_raw(detail::to_raw_saturating(detail::udiv_round(n, detail::magnitude(den)), negative));
  }

  constexpr Raw raw() const { return raw_; }

  /// false for a saturated value (and for INT64_MIN, which no operation makes).
  constexpr bool is_finite() const { return raw_ > detail::kNegOverflow && raw_ < detail::kPosOverflow; }

  /// Host-side conversion (tests, logs, host_sim); a board never needs it.
  explicit constexpr operator double() const {
    return static_cast<double>(raw_) / static_cast<double>(kOne);
  }
  explicit constexpr operator float() const { return static_cast<float>(static_cast<double>(*this)); }

  // ---- arithmetic: one correctly rounded result per operation --------------

  friend constexpr FixedPoint operator+(FixedPoint a, FixedPoint b) {
    // The common case first: both in [-2^61, 2^61), whose sum is in
    // [-2^62, 2^62) and so finite: no check after the add.
    if (below_2_61(a.raw_, b.raw_)) {
      return from_raw(static_cast<Raw>(static_cast<std::uint64_t>(a.raw_) + static_cast<std::uint64_t>(b.raw_)));
    }
    if (!a.is_finite() || !b.is_finite()) return propagate_add(a, b);
    const auto s = static_cast<Raw>(static_cast<std::uint64_t>(a.raw_) + static_cast<std::uint64_t>(b.raw_));
    const bool wrapped = ((a.raw_ >= 0) == (b.raw_ >= 0)) && ((s >= 0) != (a.raw_ >= 0));
    if (wrapped || s > detail::kMaxFinite || s < -detail::kMaxFinite) {
      detail::note_overflow();
      return from_raw(a.raw_ >= 0 ? detail::kPosOverflow : detail::kNegOverflow);
    }
    return from_raw(s);
  }

  friend constexpr FixedPoint operator-(FixedPoint a) {
    return from_raw(a.raw_ == INT64_MIN ? detail::kPosOverflow : -a.raw_);
  }

  friend constexpr FixedPoint operator-(FixedPoint a, FixedPoint b) { return a + (-b); }

  KESTREL_FIXED_MUL_PART friend constexpr FixedPoint operator*(FixedPoint a, FixedPoint b) {
    return from_raw(product(a.raw_, b.raw_));
  }

  friend constexpr FixedPoint operator/(FixedPoint a, FixedPoint b) {
    const bool negative = (a.raw_ < 0) != (b.raw_ < 0);
    if (!a.is_finite()) return from_raw(negative ? detail::kNegOverflow : detail::kPosOverflow);
    if (!b.is_finite()) return FixedPoint{};  // finite / "infinite" -> 0
    if (b.raw_ == 0) {
      detail::note_overflow();
      return from_raw(a.raw_ < 0 ? detail::kNegOverflow : detail::kPosOverflow);
    }
    const detail::U128 n = detail::shl(detail::U128{0, detail::magnitude(a.raw_)}, kFracBits);
    return from_raw(detail::to_raw_saturating(detail::udiv_round(n, detail::magnitude(b.raw_)), negative));
  }

  /// A positive divisor prepared for repeated division by it: one 64-step
  /// division here, then each quotient is a 64 x 64-bit product and a
  /// shift. The normalised reciprocal m = round(2^(n + 62) / d) (d of n
  /// bits) has 63 significant bits, so a quotient is within 1.5 LSB of the
  /// correctly rounded a / d: for work whose result is a decision, not
  /// stored bits (is_positive_definite's LDL^T pivots).
  class Divisor {
   public:
    /// a / d within 1.5 LSB; saturated a stays saturated.
    KESTREL_FIXED_MUL_OUTLINE constexpr FixedPoint divide(FixedPoint a) const {
      const bool negative = a.raw_ < 0;
      if (!a.is_finite() || !valid_) return from_raw(negative ? detail::kNegOverflow : detail::kPosOverflow);
      const detail::U128 p = detail::mul_wide(detail::magnitude(a.raw_), m_);
      return from_raw(detail::to_raw_saturating(detail::round_shift_wide(p, shift_), negative));
    }

   private:
    friend class FixedPoint;
    std::uint64_t m_ = 0;
    int shift_ = 1;
    bool valid_ = false;
  };

  /// d prepared for Divisor::divide(); d must be positive and finite (else
  /// every quotient saturates).
  static constexpr Divisor divisor(FixedPoint d) {
    Divisor out;
    if (!(d.raw_ > 0) || !d.is_finite()) return out;
    const auto dm = static_cast<std::uint64_t>(d.raw_);
    const int n = detail::bit_length(dm);
    out.m_ = detail::udiv_round(detail::shl(detail::U128{0, 1}, n + 62), dm).lo;
    out.shift_ = n + 62 - kFracBits;
    out.valid_ = true;
    return out;
  }

  constexpr FixedPoint& operator+=(FixedPoint b) { return *this = *this + b; }
  constexpr FixedPoint& operator-=(FixedPoint b) { return *this = *this - b; }
  constexpr FixedPoint& operator*=(FixedPoint b) { return *this = *this * b; }
  constexpr FixedPoint& operator/=(FixedPoint b) { return *this = *this / b; }
  constexpr FixedPoint operator+() const { return *this; }

  friend constexpr bool operator==(FixedPoint a, FixedPoint b) { return a.raw_ == b.raw_; }
  friend constexpr auto operator<=>(FixedPoint a, FixedPoint b) { return a.raw_ <=> b.raw_; }

 private:
  template <std::integral I>
  static constexpr Raw from_integer(I v) {
    constexpr Raw kMaxInt = detail::kMaxFinite >> kFracBits;
    if (std::cmp_greater(v, kMaxInt) || std::cmp_less(v, -kMaxInt)) {
      detail::note_overflow();
      return std::cmp_less(v, 0) ? detail::kNegOverflow : detail::kPosOverflow;
    }
    return static_cast<Raw>(v) * kOne;
  }

  /// The raw product of raw a and b. Out of line on Thumb-1, where raw
  /// int64 operands and result travel in r0..r3 (FixedPoint ones would
  /// travel through memory).
  KESTREL_FIXED_MUL_OUTLINE static constexpr Raw product(Raw a, Raw b) {
    const bool negative = (a < 0) != (b < 0);
    if (!below_2_62(a, b) && (!from_raw(a).is_finite() || !from_raw(b).is_finite())) {
      return negative ? detail::kNegOverflow : detail::kPosOverflow;
    }
    const detail::U128 p = detail::mul_wide(detail::magnitude(a), detail::magnitude(b));
    return detail::to_raw_saturating(detail::round_shift_by<kFracBits>(p), negative);
  }

  /// Whether both raw values are in [-2^62, 2^62) (bits 63 and 62 equal in
  /// each), which makes both finite: one test on the high words instead of
  /// four 64-bit comparisons (a 32-bit core's * checks it first).
  static constexpr bool below_2_62(Raw a, Raw b) {
    const auto ha = static_cast<std::uint32_t>(static_cast<std::uint64_t>(a) >> 32);
    const auto hb = static_cast<std::uint32_t>(static_cast<std::uint64_t>(b) >> 32);
    return (((ha ^ (ha << 1)) | (hb ^ (hb << 1))) >> 31) == 0;
  }

  /// Whether both raw values are in [-2^61, 2^61) (bits 63, 62 and 61 equal
  /// in each), which keeps their sum finite: + checks it first. (Within
  /// 2^62, -2^62 + -2^62 would be INT64_MIN.)
  static constexpr bool below_2_61(Raw a, Raw b) {
    const auto ha = static_cast<std::uint32_t>(static_cast<std::uint64_t>(a) >> 32);
    const auto hb = static_cast<std::uint32_t>(static_cast<std::uint64_t>(b) >> 32);
    // Flipped by its own sign, a high word is below 2^29 iff bits 31..29 were equal.
    const std::uint32_t ma = ha ^ static_cast<std::uint32_t>(static_cast<std::int32_t>(ha) >> 31);
    const std::uint32_t mb = hb ^ static_cast<std::uint32_t>(static_cast<std::int32_t>(hb) >> 31);
    return ((ma | mb) >> 29) == 0;
  }

  /// Sum where an operand is saturated: saturation sticks (opposite signs,
  /// the fixed-point "NaN", give +saturation). Not counted again.
  static constexpr FixedPoint propagate_add(FixedPoint a, FixedPoint b) {
    if (!a.is_finite() && !b.is_finite() && (a.raw_ < 0) != (b.raw_ < 0)) {
      return from_raw(detail::kPosOverflow);
    }
    const Raw r = a.is_finite() ? b.raw_ : a.raw_;
    return from_raw(r < 0 ? detail::kNegOverflow : detail::kPosOverflow);
  }

  Raw raw_ = 0;
};

}  // namespace fixed

using fixed::FixedPoint;
/// 31 integer bits, 32 fraction bits: +-2.1e9, resolution 2.3e-10. The default.
using Q31_32 = FixedPoint<32>;
/// 23 integer bits, 40 fraction bits: +-8.4e6, resolution 9.1e-13.
using Q23_40 = FixedPoint<40>;

/// Saturation events (overflow, division by zero, sqrt of a negative, a
/// non-finite double) of fixed-point arithmetic on this thread since the last
/// reset_fixed_point_overflow_count(). Tests assert it stays 0.
inline std::uint32_t fixed_point_overflow_count() { return fixed::detail::overflow_events; }
inline void reset_fixed_point_overflow_count() { fixed::detail::overflow_events = 0; }

}  // namespace kestrel
