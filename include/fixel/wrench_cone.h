#pragma once
/// @file
/// Conservative cones of the contact wrenches a boundary segment can deliver
/// (paper §4).

#include <optional>
#include <string>
#include <vector>

#include "fixel/curve.h"
#include "fixel/rational.h"

namespace fixel {

/// Which push directions d are bounded, in terms of the inward normal n
/// (the tangent rotated +90°) and t = n rotated +90°, with pusher friction μ.
enum class EdgeFamily {
  kNormal,     ///< d = n (frictionless pusher).
  kMinus,      ///< d = n − μ t (one edge of the pusher's friction cone).
  kPlus,       ///< d = n + μ t (the other edge).
  kWholeCone,  ///< every d = n + λ t, |λ| ≤ μ (the paper's single bound).
};

/// "normal", "n-mu*t", "n+mu*t", "friction cone".
std::string to_string(EdgeFamily family);

/// The push direction of an edge family at a point whose curve tangent
/// (derivative, any positive length) is `tangent`. For kWholeCone, the
/// kMinus edge. Exact and linear in the tangent.
Vec2 push_direction(const Vec2& tangent, EdgeFamily family, const Rational& mu);

/// What a segment's control polygon tells about it.
struct SegmentBounds {
  std::vector<Vec2> hull;  ///< Convex hull of the control points (CGAL, exact), counter-clockwise.
  std::vector<Vec2> legs;  ///< The non-zero hodograph legs P_{k+1} − P_k.
  bool pointed = false;    ///< The legs span a cone of angle < π.
  Vec2 t_start, t_end;     ///< Extreme legs: every leg is in cone(t_start, t_end). Set when pointed.
};

/// Bounds of a Bézier segment. Throws SceneError if every leg is zero.
/// Without `with_hull`, `hull` holds all control points instead (the tight
/// cone's min/max over them equals that over the hull's vertices).
SegmentBounds segment_bounds(const BezierPiece& segment, bool with_hull = true);

/// Which conservative cone to build.
enum class ConeMethod {
  kTight,  ///< Per direction generator d: (d, min_k r_k ⊗ d), (d, max_k r_k ⊗ d).
  kPaper,  ///< The paper's §4.3 cone, made exact and conservative (docs/theory.md §7).
};

/// "tight" or "paper", as on the command line.
const char* to_string(ConeMethod method);

/// A polyhedral cone in wrench space (f_x, f_y, moment about the centre of
/// mass), as generators and as exact facet normals (w in cone iff a·w ≥ 0
/// for every facet a).
struct WrenchCone {
  std::vector<VectorQ> generators;
  std::vector<VectorQ> facets;
  /// Exact membership.
  bool contains(const VectorQ& wrench) const;
};

/// A cone holding every wrench (d, r ⊗ d) of the family at every point of
/// the segment, r = point − p_AoCm_A. Empty (std::nullopt) when the
/// segment's tangent cone is not pointed (the segment must be split).
std::optional<WrenchCone> segment_wrench_cone(const BezierPiece& segment, const Vec2& p_AoCm_A, EdgeFamily family,
                                              const Rational& mu, ConeMethod method);

/// Same from precomputed bounds (both methods share them). Without
/// `with_facets` only the generators are filled (facets stay empty).
std::optional<WrenchCone> segment_wrench_cone(const SegmentBounds& bounds, const Vec2& p_AoCm_A, EdgeFamily family,
                                              const Rational& mu, ConeMethod method, bool with_facets = true);

/// Extreme directions of non-zero planar vectors: every v is in
/// cone(first, last). False when they do not fit in a cone of angle < π.
bool direction_extremes(const std::vector<Vec2>& v, Vec2& first, Vec2& last);

}  // namespace fixel
