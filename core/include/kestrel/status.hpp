// SPDX-License-Identifier: Apache-2.0
// Status codes and a small Result<T>: how every fallible call in core and hal
// reports failure without exceptions (docs/tracking.md, the real-time loop).
// A status is a value the caller must look at ([[nodiscard]]); feed data never
// asserts. to_string() is for host logs and costs only a switch on a board.
#pragma once

#include <cstdint>

namespace kestrel {

enum class Status : std::uint8_t {
  kOk = 0,
  // Frame / feed level (hal wire format and core frame validation).
  kNoData,               ///< Feed: nothing complete yet (not an error).
  kMalformedFrame,       ///< Inconsistent content (count vs length, bad enum value).
  kBadMagic,             ///< Wire: first four bytes are not the frame magic.
  kUnsupportedVersion,   ///< Wire: version field not understood by this decoder.
  kUnknownKind,          ///< Wire: frame kind is not radar, sonar or PCL.
  kTruncated,            ///< Wire: fewer bytes than the header announces.
  kBadCrc,               ///< Wire: CRC-32 over header and payload does not match.
  kBufferTooSmall,       ///< Encode: output span cannot hold the frame.
  kWrongKind,            ///< A frame of another sensor kind than this tracker takes.
  kNonFinite,            ///< NaN or Inf in an input or in a computed quantity.
  kOutOfRange,           ///< A value outside its documented physical range.
  kTooManyCandidates,    ///< More items than the capacity; the excess was dropped.
  kTimeWentBackwards,    ///< Frame time earlier than the last accepted one.
  // Numerical.
  kNotPositiveDefinite,  ///< A covariance (P or S) failed its Cholesky factorisation.
  kNotInitialised,       ///< Filter or track used before it holds a state.
  // Track management.
  kTableFull,            ///< No free slot in a static table.
  // Solvers (multilateration).
  kUnderdetermined,      ///< Fewer usable measurements than the unknowns need.
  kNoConvergence,        ///< Iteration cap reached, or no solution explains the data.
  kAmbiguous,            ///< Two or more distinct solutions fit the data equally well.
  // Frame level, added after the solvers so earlier values keep their numbers.
  kTimeJumpedForward,    ///< Frame time later than the last accepted one by more than the limit.
};

/// Short stable name of a status, for host logs and test messages.
constexpr const char* to_string(Status s) {
  switch (s) {
    case Status::kOk: return "ok";
    case Status::kNoData: return "no_data";
    case Status::kMalformedFrame: return "malformed_frame";
    case Status::kBadMagic: return "bad_magic";
    case Status::kUnsupportedVersion: return "unsupported_version";
    case Status::kUnknownKind: return "unknown_kind";
    case Status::kTruncated: return "truncated";
    case Status::kBadCrc: return "bad_crc";
    case Status::kBufferTooSmall: return "buffer_too_small";
    case Status::kWrongKind: return "wrong_kind";
    case Status::kNonFinite: return "non_finite";
    case Status::kOutOfRange: return "out_of_range";
    case Status::kTooManyCandidates: return "too_many_candidates";
    case Status::kTimeWentBackwards: return "time_went_backwards";
    case Status::kNotPositiveDefinite: return "not_positive_definite";
    case Status::kNotInitialised: return "not_initialised";
    case Status::kTableFull: return "table_full";
    case Status::kUnderdetermined: return "underdetermined";
    case Status::kNoConvergence: return "no_convergence";
    case Status::kAmbiguous: return "ambiguous";
    case Status::kTimeJumpedForward: return "time_jumped_forward";
  }
  return "unknown";
}

/// Number of distinct Status values (for per-status counters).
inline constexpr std::uint8_t kStatusCount = static_cast<std::uint8_t>(Status::kTimeJumpedForward) + 1;

/// Propagate a failure: evaluates the expression (a Status) once and
/// returns it from the enclosing function unless it is kOk. A macro because
/// only a macro can return from its caller; variadic so that template
/// arguments need no extra parentheses.
#define KESTREL_TRY(...)                                                                               \
  do {                                                                                                  \
    if (const ::kestrel::Status kestrel_try_status_ = (__VA_ARGS__); kestrel_try_status_ != ::kestrel::Status::kOk) \
      return kestrel_try_status_;                                                                       \
  } while (false)

/// The same, returning `on_error(status)` instead: a filter's fail(), which
/// records the status in its diagnostics before returning it.
#define KESTREL_TRY_OR(on_error, ...)                                                                  \
  do {                                                                                                  \
    if (const ::kestrel::Status kestrel_try_status_ = (__VA_ARGS__); kestrel_try_status_ != ::kestrel::Status::kOk) \
      return on_error(kestrel_try_status_);                                                             \
  } while (false)

/// A status plus a value that is meaningful only when the status is kOk.
/// T must be default-constructible; no exceptions, no heap.
template <class T>
class [[nodiscard]] Result {
 public:
  constexpr Result(const T& value) : status_(Status::kOk), value_(value) {}  // NOLINT: implicit by design
  constexpr Result(Status status) : status_(status), value_() {}             // NOLINT: implicit by design

  [[nodiscard]] constexpr bool ok() const { return status_ == Status::kOk; }
  [[nodiscard]] constexpr Status status() const { return status_; }
  /// The value; only meaningful when ok().
  [[nodiscard]] constexpr const T& value() const { return value_; }

 private:
  Status status_;
  T value_;
};

}  // namespace kestrel
