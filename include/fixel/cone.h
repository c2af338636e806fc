#pragma once
/// @file
/// Exact H-form of a finitely generated cone in R² or R³.

#include <vector>

#include "fixel/rational.h"

namespace fixel {

/// The closed half-space {p : a·p ≥ c}.
struct Halfspace {
  VectorQ a;
  Rational c;
  /// Exact test a·p ≥ c (interval-filtered); points on the boundary plane
  /// are inside. Throws InputError when p and a differ in length.
  bool contains(const VectorQ& p) const;
};

/// Facet normals of cone(rays) = {Σ λ_k r_k : λ ≥ 0} ⊂ R^dim, dim ∈ {2, 3}:
/// the cone is exactly {x : a·x ≥ 0 for every returned a}. Works for any
/// number of rays and any rank: a lower-dimensional cone gets each of its
/// equalities as a pair of opposite normals, and a cone that is the whole
/// space gets no normals. Each normal is scaled to a primitive integer
/// vector, and the list has no duplicates. Throws InputError if dim is not 2
/// or 3 or a ray has the wrong length.
std::vector<VectorQ> cone_facet_normals(const std::vector<VectorQ>& rays, int dim);

/// `v` scaled by a positive rational to a primitive integer vector (entries
/// with gcd 1); the zero vector is returned unchanged.
VectorQ primitive_direction(const VectorQ& v);

}  // namespace fixel
