#pragma once
// J′'s data (approach.cpp builds it, approach_target.cpp reads it): each
// pair's two-contact family as polynomials in t = tan(θ/2), every one
// multiplied by 1 + t² (> 0), so signs and cones are unchanged
// (docs/theory.md §10.7). No CGAL here.

#include <array>
#include <vector>

#include "fixel/algebraic.h"
#include "fixel/seated_pose.h"

namespace fixel::internal {

using PolyVec3 = std::array<Polynomial, 3>;

struct PairFamily {
  std::array<int, 2> fixels{};
  // World-frame generators of FC_i + FC_j at the pose t: W_n ± μ W_t of
  // both fixels (f_x, f_y, moment about the centre of mass).
  std::vector<PolyVec3> gens;
  // Body-frame contact points g_i, g_j on their edges (x, y).
  std::array<std::array<Polynomial, 2>, 2> contact_B;
  // ≥ 0 exactly while both contacts lie on their edges (two per fixel).
  std::vector<Polynomial> on_edge;
  // Both fixels frictionless: the generators span a plane.
  bool planar = false;
};

struct ApproachData {
  std::vector<PairFamily> pairs;
  QuadraticIrrational t_star{0, 0, 0};
  // Rational bounds with t_lo < t* < t_hi when t* ≠ 0, tight to about 2⁻⁴⁰.
  Rational t_lo, t_hi;
};

// Evaluates the polynomials of a vector at a rational t.
inline std::array<Rational, 3> eval3(const PolyVec3& p, const Rational& t) {
  std::array<Rational, 3> out;
  for (int k = 0; k < 3; ++k) {
    Rational v = 0;
    for (std::size_t i = p[k].size(); i-- > 0;) v = v * t + p[k][i];
    out[k] = v;
  }
  return out;
}

}  // namespace fixel::internal
