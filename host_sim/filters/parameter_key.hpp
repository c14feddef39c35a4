// SPDX-License-Identifier: Apache-2.0
// One key of a tracker's parameter struct: its name, its field, the range of
// its values and its meaning. The radar, PCL and sonar trackers' tables
// (settings.cpp, sensor_settings.cpp) are arrays of these, so one range
// check, one range text and one default text serve every key, and the
// parser, the echo into summary.json and `list --settings` cannot drift
// apart.
#pragma once

#include <limits>
#include <string>
#include <type_traits>

#include "kestrel/association/chi_square.hpp"

namespace kestrel::sim {

/// What a key's values are, from its field's type.
enum class KeyType {
  kReal,   ///< A floating-point field: lo..hi.
  kWhole,  ///< An integer field: a whole number in lo..hi.
  kBool,   ///< A bool: 0 or 1 (false or true).
  kGate,   ///< A GateProbability: 0.9, 0.95, 0.99, 0.995 or 0.999.
};

inline constexpr double kNoUpperBound = std::numeric_limits<double>::infinity();

/// The bounds of a kReal or kWhole key: lo < v (lo_open) or lo <= v, and
/// v <= hi, except that an upper bound of 1 above an open lower bound is
/// open too (a probability in (0, 1)).
struct KeyRange {
  double lo = 0.0;
  bool lo_open = false;
  double hi = kNoUpperBound;
};

template <class P>
struct ParameterKey {
  const char* key;
  KeyType type;
  KeyRange range;
  double (*get)(const P&);     ///< The field as a double (a bool 0 or 1, a gate its probability).
  void (*set)(P&, double);     ///< Only with a value key_accepts() accepted.
  const char* meaning;
  bool from_scenario = false;  ///< The scenario sets its default (the sensor's figure).
};

namespace detail {
template <class>
struct MemberOf;
template <class P, class T>
struct MemberOf<T P::*> {
  using Class = P;
  using Type = T;
};
}  // namespace detail

/// The key `name` of the field `Member` (a pointer to a data member); its
/// KeyType follows from the field's type.
template <auto Member>
constexpr ParameterKey<typename detail::MemberOf<decltype(Member)>::Class> field_key(const char* name,
                                                                                    KeyRange range,
                                                                                    const char* meaning,
                                                                                    bool from_scenario = false) {
  using P = typename detail::MemberOf<decltype(Member)>::Class;
  using T = typename detail::MemberOf<decltype(Member)>::Type;
  constexpr KeyType type = std::is_same_v<T, GateProbability> ? KeyType::kGate
                           : std::is_same_v<T, bool>          ? KeyType::kBool
                           : std::is_integral_v<T>            ? KeyType::kWhole
                                                              : KeyType::kReal;
  const auto get = [](const P& p) -> double {
    if constexpr (type == KeyType::kGate) return gate_probability(p.*Member);
    else if constexpr (type == KeyType::kBool) return p.*Member ? 1.0 : 0.0;
    else return static_cast<double>(p.*Member);
  };
  const auto set = [](P& p, double v) {
    if constexpr (type == KeyType::kGate) (void)gate_probability_from(v, p.*Member);  // checked before
    else if constexpr (type == KeyType::kBool) p.*Member = v == 1.0;
    else p.*Member = static_cast<T>(v);
  };
  return {name, type, range, get, set, meaning, from_scenario};
}

/// `v` in its shortest form that reads back as the same double.
std::string shortest_text(double v);

/// What a key accepts, as `list --settings` and an error show it: "> 0",
/// "whole, 1..8", ">= 0", "false or true", ...
std::string range_text(KeyType type, const KeyRange& range);

/// Whether `v` is finite and within what the key accepts.
bool key_accepts(KeyType type, const KeyRange& range, double v);

/// A key's default as a user would write it (true/false for a bool).
template <class P>
std::string default_text(const ParameterKey<P>& k, const P& defaults) {
  const double v = k.get(defaults);
  if (k.type == KeyType::kBool) return v == 1.0 ? "true" : "false";
  return shortest_text(v);
}

}  // namespace kestrel::sim
