#pragma once
/// @file
/// Where an exact point lies on the part's outline, decided exactly: is it
/// on the loop, and is a given direction the loop's inward normal there?
/// (docs/formats.md, "Fixels on the outline").

#include <array>
#include <optional>

#include "fixel/curve.h"
#include "fixel/geometry.h"

namespace fixel {

/// The fit of a point p (and optionally a unit normal n) to a boundary, all
/// in frame A. The booleans are exact decisions; the doubles are for
/// messages and reports only.
struct BoundaryFit {
  bool on_boundary = false;     ///< p lies exactly on the loop (exact).
  bool normal_matches = false;  ///< n is the inward unit normal at p (exact; false when !on_boundary or no n).
  /// p is on a joint of two pieces whose one-sided tangents differ in
  /// direction: a corner, where any n in the closed cone (angle < π) between
  /// the two one-sided inward normals matches (exact).
  bool corner = false;
  int curve = 0;  ///< Curve of the (nearest) boundary point.
  /// Curve parameter of the (nearest) boundary point, when it is exactly
  /// known to be rational (always at a joint; on a piece's interior when the
  /// point determines one rational parameter).
  std::optional<Rational> u;
  /// The inward normal at p, any positive length, exact: set when p is on the
  /// boundary at a known rational parameter and not at a corner.
  std::optional<Vec2> inward_normal;
  double u_approx = 0;                           ///< Display: parameter of the nearest point.
  double distance = 0;                           ///< Display: distance from p to the loop (m); 0 when on it.
  std::array<double, 2> nearest{};               ///< Display: the nearest boundary point (m, frame A).
  std::array<double, 2> inward_normal_approx{};  ///< Display: unit inward normal there (at a corner, the bisector).
  double angle_degrees = 0;                      ///< Display: angle between n and inward_normal_approx (degrees).
};

/// Fits p (and n, when given: it must then be of unit length) to the
/// boundary. The point test is exact: a polyline edge by orientation and
/// betweenness; a curved Bézier piece B(s) by the greatest common divisor g
/// of x(s) − p_x and y(s) − p_y over Q and a Sturm count of g's roots in
/// (0, 1). The normal test at such a root is a Sturm–Tarski query (the root
/// where T(s)·n = 0 and T(s) ⊗ n > 0, T the tangent), so it is exact for
/// irrational parameters too. Loops are bounded by the number of pieces and
/// their degrees.
BoundaryFit fit_to_boundary(const Boundary& boundary, const Vec2& p_A, const Vec2* n_A = nullptr);

/// The exact rational unit vector v/|v| when |v| is rational, else nothing.
std::optional<Vec2> exact_unit(const Vec2& v);

/// A rational unit vector within about 1e-9 rad of the direction of angle
/// `radians` (from the +x axis): a rational point of the unit circle from a
/// continued-fraction approximation of the half-angle tangent. For
/// suggestions in messages; exactly of unit length. Throws InputError when
/// `radians` is not finite.
Vec2 nearby_exact_unit(double radians);

}  // namespace fixel
