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
// Rational points on the unit circle near the direction of d, on its
// clockwise (cw = true) or counter-clockwise side: cross(u, d) >= 0 or
// cross(d, u) >= 0.
Vec2 unit_direction_outward(const Vec2& d, bool cw);
// A rational q >= sqrt(x), x >= 0.
Rational sqrt_upper(const Rational& x);
// A rational q in [0, sqrt(x)], x >= 0.
Rational sqrt_lower(const Rational& x);

}  // namespace fixel::internal
