#pragma once
// Pieces of the wrench-cone construction that the region targets and the
// tests use, but a library user does not: the corner cone and the rational
// bounds on half angles and square roots.

#include "fixel/wrench_cone.h"

namespace fixel::internal {

// push_direction's formula for any number type (Rational, or intervals in
// the region's pre-test): from the inward normal n = rot90(tangent) and
// t = rot90(n), the direction n, n + μt or n − μt of `family`.
template <class V, class S>
V push_direction_from(const V& n, const V& t, EdgeFamily family, const S& mu) {
  switch (family) {
    case EdgeFamily::kNormal:
      return n;
    case EdgeFamily::kPlus:
      return {n.x + mu * t.x, n.y + mu * t.y};
    case EdgeFamily::kMinus:
    case EdgeFamily::kWholeCone:
      return {n.x - mu * t.x, n.y - mu * t.y};
  }
  return n;
}

// The exact wrench cone of a corner point r (lever arm) whose push
// directions fan from d_in to d_out (the angle between them < π):
// generators (d_in, r ⊗ d_in) and (d_out, r ⊗ d_out).
WrenchCone corner_cone(const Vec2& r, const Vec2& d_in, const Vec2& d_out);

// A rational c in [0, cos(Δ/2)], Δ the angle between non-zero a and b (< π).
Rational cos_half_angle_lower(const Vec2& a, const Vec2& b);
// The rational point of the unit circle nearest the direction of d (not
// zero) on its clockwise (cw = true) or counter-clockwise side, among
// u(τ) = ((1 − τ²), 2τ)/(1 + τ²), τ = k/2^20 (−u(τ) when d.x < 0): the one
// with cross(u, d) >= 0 (or cross(d, u) >= 0) whose next grid point inward
// fails that test. d itself when it is on the grid (docs/theory.md §7).
Vec2 unit_direction_outward(const Vec2& d, bool cw);
// The grid search's start, k with τ = k/2^20 near tan(θ/2) (θ − π when
// flip), from doubles; clamped to ±kUnitGridLimit. Only a guess: the
// answer does not depend on it while it is within kUnitGridSteps of it.
constexpr long kUnitGridLimit = 1L << 21;
constexpr int kUnitGridSteps = 4096;
long unit_grid_guess(double x, double y, bool flip);
// A rational q >= sqrt(x), x >= 0.
Rational sqrt_upper(const Rational& x);
// A rational q in [0, sqrt(x)], x >= 0.
Rational sqrt_lower(const Rational& x);

}  // namespace fixel::internal
