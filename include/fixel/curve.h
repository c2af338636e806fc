#pragma once
/// @file
/// The part's boundary: polylines and B-splines with exact rational control
/// points, their exact Bézier pieces, and exact mass properties.

#include <string>
#include <utility>
#include <vector>

#include "fixel/geometry.h"
#include "fixel/progress.h"
#include "fixel/rational.h"

namespace fixel {

/// A polynomial piece of the boundary in Bézier form. Local parameter
/// s ∈ [0, 1] maps to the curve parameter u = u0 + s (u1 − u0).
struct BezierPiece {
  int curve = 0;              ///< Index of the curve in the boundary list.
  Rational u0, u1;            ///< Curve-parameter range covered, u0 < u1.
  std::vector<Vec2> control;  ///< degree + 1 control points, frame A.

  int degree() const { return static_cast<int>(control.size()) - 1; }
  /// Point at local parameter s (de Casteljau, exact).
  Vec2 point(const Rational& s) const;
  /// k-th derivative with respect to s at local parameter s (exact).
  Vec2 derivative(const Rational& s, int k = 1) const;
  /// De Casteljau split at local parameter s ∈ (0, 1): the pieces on [0, s]
  /// and [s, 1], with their curve-parameter ranges.
  std::pair<BezierPiece, BezierPiece> split(const Rational& s) const;
  /// The sub-piece on curve parameters [a, b] ⊂ [u0, u1].
  BezierPiece restrict_to(const Rational& a, const Rational& b) const;
  /// Local parameter of curve parameter u. Throws InputError unless u0 < u1.
  Rational local(const Rational& u) const;
  /// Hodograph legs P_{k+1} − P_k (some may be zero).
  std::vector<Vec2> legs() const;
};

/// One curve of the boundary.
struct Curve {
  enum class Type { kPolyline, kBSpline };
  Type type = Type::kPolyline;
  int degree = 1;               ///< 1 for a polyline.
  std::vector<Vec2> points;     ///< Polyline vertices or B-spline control points.
  std::vector<Rational> knots;  ///< B-spline knots (n + degree + 1), empty for a polyline.

  /// Parameter range: [0, k] for a polyline of k + 1 points, [knots[p], knots[n]] for a B-spline.
  Rational u_begin() const;
  Rational u_end() const;
  /// The curve's Bézier pieces in parameter order (knot insertion for
  /// B-splines); pieces of zero parameter length are skipped.
  std::vector<BezierPiece> bezier_pieces(int curve_index) const;
  /// Point at parameter u ∈ [u_begin, u_end] (exact).
  Vec2 point(const Rational& u) const;
  /// k-th derivative with respect to u (exact; at a knot or polyline vertex
  /// the right-hand derivative, except at u_end).
  Vec2 derivative(const Rational& u, int k = 1) const;
};

/// Area, centroid and second moment of the enclosed region (Green's theorem).
struct MassProperties {
  Rational area;          ///< Enclosed area (> 0 for a valid loop).
  Vec2 centroid;          ///< Area centroid, frame A.
  Rational polar_moment;  ///< ∬ |p|² dA about the origin of frame A.
  /// ∬ |p − c|² dA about the point c.
  Rational polar_moment_about(const Vec2& c) const;
};

/// The validated boundary: one closed counter-clockwise loop.
struct Boundary {
  std::vector<Curve> curves;
  std::vector<BezierPiece> pieces;  ///< All curves' pieces, in loop order.
  MassProperties mass;
};

/// Validates and assembles a boundary: every curve valid, consecutive
/// curves joined exactly, the loop closed and simple (check_simple_loop),
/// counter-clockwise with non-zero area. Throws SceneError naming `path`
/// (e.g. "body.boundary[1]").
/// `control` (may be null) is polled through the checks and the mass
/// properties (task "load"): progress, time limit and Ctrl-C on huge parts.
Boundary make_boundary(std::vector<Curve> curves, const std::string& path = "body.boundary",
                       RunControl* control = nullptr);

/// Checks that a closed loop of Bézier pieces (in loop order, each ending
/// where the next begins) is simple: no two points of the loop coincide
/// except the shared endpoints of consecutive pieces. Segments are decided
/// exactly (a CGAL sweep, O(n log n), when every piece is a segment); curved
/// pieces by their control-polygon hulls, refined by exact de Casteljau
/// splits until they are separated or a crossing is proven. Throws
/// SceneError naming `path`, the two curves, their parameters and the point:
/// "crosses itself", "touches itself", or, when the bounded refinement
/// cannot decide, a message saying so.
/// `control` (may be null) is polled along the sweep.
void check_simple_loop(const std::vector<BezierPiece>& pieces, const std::string& path = "body.boundary",
                       RunControl* control = nullptr);

/// Exact mass properties of a closed loop of Bézier pieces; `control` (may
/// be null) is polled every 256 pieces.
MassProperties mass_properties(const std::vector<BezierPiece>& pieces, RunControl* control = nullptr);

}  // namespace fixel
