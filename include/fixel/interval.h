#pragma once
/// @file
/// Exact intervals of positive reals (push magnitudes): one type, one
/// emptiness rule, intersection and difference.

#include <optional>
#include <string>
#include <vector>

#include "fixel/rational.h"

namespace fixel {

/// An interval of positive reals with an optional infinite upper end
/// (N·s for impulse magnitudes).
struct Magnitudes {
  bool empty = true;
  Rational lo;  ///< Lower end (>= 0).
  bool lo_closed = false;
  std::optional<Rational> hi;  ///< Upper end; std::nullopt means +∞.
  bool hi_closed = false;

  /// The interval with these ends; `empty` is set when no number is inside.
  /// Throws InputError when lo < 0.
  static Magnitudes make(const Rational& lo, bool lo_closed, const std::optional<Rational>& hi, bool hi_closed);
  /// True when the ends leave no number inside (hi < lo, or hi == lo with an open end).
  static bool ends_cross(const Rational& lo, bool lo_closed, const std::optional<Rational>& hi, bool hi_closed);
  /// Unbounded above (and not empty).
  bool half_line() const { return !empty && !hi.has_value(); }
  /// Exact membership.
  bool contains(const Rational& x) const;
  /// The intersection (empty when either is).
  Magnitudes intersect(const Magnitudes& other) const;
  /// This minus `other`: at most two disjoint pieces, in increasing order.
  std::vector<Magnitudes> subtract(const Magnitudes& other) const;
  /// "[lo, hi)", "(0, inf)", or "no common magnitude" when empty (the CLI's wording).
  std::string describe() const;
  /// The same for people: short fractions with their decimals, long ones
  /// as decimals only (docs/cli.md, "Numbers"); "no common magnitude" when empty.
  std::string describe_readable() const;
};

}  // namespace fixel
