// SPDX-License-Identifier: Apache-2.0
#include "filters/parameter_key.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace kestrel::sim {

std::string shortest_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  if (std::strtod(text, nullptr) == v) return text;
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

namespace {
// A probability's upper bound 1 is open; other upper bounds are inclusive.
bool hi_open(const KeyRange& r) { return r.lo_open && r.hi == 1.0; }
}  // namespace

std::string range_text(KeyType type, const KeyRange& r) {
  switch (type) {
    case KeyType::kBool: return "false or true";
    case KeyType::kGate: return "0.9, 0.95, 0.99, 0.995, 0.999";
    case KeyType::kWhole:
    case KeyType::kReal: break;
  }
  std::string text = type == KeyType::kWhole ? "whole, " : "";
  if (r.lo_open) {
    text += "> " + shortest_text(r.lo);
    if (r.hi != kNoUpperBound) text += (hi_open(r) ? ", < " : ", <= ") + shortest_text(r.hi);
  } else {
    text += r.hi != kNoUpperBound ? shortest_text(r.lo) + ".." + shortest_text(r.hi) : ">= " + shortest_text(r.lo);
  }
  return text;
}

bool key_accepts(KeyType type, const KeyRange& r, double v) {
  if (!std::isfinite(v)) return false;
  GateProbability gate{};
  switch (type) {
    case KeyType::kBool: return v == 0.0 || v == 1.0;
    case KeyType::kGate: return gate_probability_from(v, gate);
    case KeyType::kWhole:
      if (v != std::floor(v)) return false;
      break;
    case KeyType::kReal: break;
  }
  return (r.lo_open ? v > r.lo : v >= r.lo) && (hi_open(r) ? v < r.hi : v <= r.hi);
}

}  // namespace kestrel::sim
