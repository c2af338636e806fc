#pragma once
/// @file
/// Ground-floor planar geometry: the exact 2-vector and its named
/// predicates and constructions, defined once (after CGAL's kernel_ftC2.h).

#include "fixel/rational.h"

namespace fixel {

/// A 2-vector of exact numbers. Points and directions are in the frame
/// named by the variable (frame A: the part's body frame at the scene pose,
/// axes aligned with the world).
struct Vec2 {
  Rational x, y;
};

/// a ⊗ b = a_x b_y − a_y b_x (the planar cross product).
inline Rational cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
/// a · b.
inline Rational dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
/// a − b.
inline Vec2 sub(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
/// Both coordinates exactly zero.
inline bool is_zero(const Vec2& v) { return v.x == 0 && v.y == 0; }
/// Sign of a ⊗ b: +1 when b is counter-clockwise of a, −1 clockwise, 0 parallel.
inline int orientation(const Vec2& a, const Vec2& b) { return sign(cross(a, b)); }
/// d lies in the closed planar cone spanned by a then b counter-clockwise
/// (angle < π; a single ray when a and b are parallel and alike). The cone
/// is closed: d = 0 is in it.
inline bool in_cone(const Vec2& d, const Vec2& a, const Vec2& b) {
  if (cross(a, b) == 0) return cross(a, d) == 0 && dot(a, d) >= 0;
  return cross(a, d) >= 0 && cross(d, b) >= 0;
}

/// Wrench (force, moment) of a unit push along direction d_A applied at lever
/// arm r_A: (d_x, d_y, r ⊗ d) for dof 3 and (d_x, d_y) for dof 2.
VectorQ contact_wrench(const Vec2& r_A, const Vec2& d_A, int dof);

}  // namespace fixel
