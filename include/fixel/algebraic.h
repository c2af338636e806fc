#pragma once
/// @file
/// Real algebraic numbers with a certified isolating interval: the exact
/// endpoints of the exact pushing region (RegionOptions::exact).

#include <string>
#include <vector>

#include "fixel/rational.h"

namespace fixel {

/// A polynomial with rational coefficients, c[0] + c[1] x + c[2] x² + …
/// (an empty vector is the zero polynomial).
using Polynomial = std::vector<Rational>;

/// A real algebraic number x. Rational: `poly` is empty and lo == hi == x.
/// Irrational: x is the only root of `poly` in [lo, hi], lo < hi, and
/// neither end is a root. `poly` (integer coefficients c0, c1, …) is
/// irreducible over Q, primitive, with a positive leading coefficient, so it
/// is square-free and the minimal polynomial of x up to that scaling.
/// fixel's own ends are so. For one made by a caller, the functions below
/// check only part of it (degree >= 2, lo < hi, a sign change, no rational
/// root met while bisecting): an interval holding three roots, or a
/// reducible polynomial without a rational root, is not detected and gives
/// answers about some root in it. Keeping the invariant is the caller's.
struct AlgebraicReal {
  std::vector<Integer> poly;
  Rational lo, hi;

  /// The rational number q.
  static AlgebraicReal rational(const Rational& q);
  bool is_rational() const { return poly.empty(); }
  /// The value when rational; the isolating interval's midpoint otherwise
  /// (a rational inside the interval, not x).
  Rational midpoint() const { return (lo + hi) / 2; }
  /// Nearest double of the midpoint (display only).
  double approx() const;
};

/// The exact sign of x − q: −1, 0 or +1 (refines a copy of x as needed).
int compare(const AlgebraicReal& x, const Rational& q);

/// x with its isolating interval shrunk by exact bisection until
/// hi − lo <= width (width > 0; InputError otherwise). Rationals are
/// returned unchanged.
AlgebraicReal refined(const AlgebraicReal& x, const Rational& width);

/// x maps to a + b x (b > 0): the image, with its polynomial and interval
/// transformed exactly.
AlgebraicReal affine_image(const AlgebraicReal& x, const Rational& a, const Rational& b);

/// Decimal text of x with only certified digits: the exact value for a
/// rational with a terminating expansion of at most `max_digits` digits
/// after the point, else the digits that every number of the isolating
/// interval shares, followed by "...", e.g. "0.41421..." (truncated, not
/// rounded: x lies in [0.41421, 0.41422)). It does not refine: for D
/// digits of an irrational, pass refined(x, 10⁻ᴰ⁻¹) (√2 isolated in [1, 2]
/// gives only "..."). Throws InputError naming `digits` outside [0, 100000].
std::string certified_decimal(const AlgebraicReal& x, int max_digits = 30);

/// Integer coefficients proportional to p (positive factor), primitive.
std::vector<Integer> primitive_integer(const Polynomial& p);

}  // namespace fixel
