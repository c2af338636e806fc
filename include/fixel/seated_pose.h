#pragma once
/// @file
/// The seated pose q* (sustained push, past the paper): the rigid motion of
/// the scene's part at which every fixel point f_i = p_i − ψ_i n_i lies on
/// the boundary, solved without linearising.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fixel/rational.h"
#include "fixel/scene.h"

namespace fixel {

/// a + b·√d with rational a, b and a square-free-ish rational d > 0 (b == 0
/// for a rational value). Plain data: arithmetic on it stays inside fixel.
struct QuadraticIrrational {
  Rational a, b, d;
  /// "a" when b == 0, else "a+b*sqrt(d)" (exact).
  std::string text() const;
  /// Nearest double (display and engine input only).
  double approx() const;
};

/// The seated pose. Coordinates are the motion of the centre of mass (x, y)
/// in frame A and the rotation θ about it (rad, counter-clockwise).
struct SeatedPose {
  /// Exact when every contact lies on a polyline edge: x, y, cos θ, sin θ,
  /// all in one quadratic field Q(√d).
  std::optional<std::array<QuadraticIrrational, 4>> exact;
  /// A certified enclosure [lo, hi] of x, y, θ (always set; a point box when
  /// exact and rational).
  std::array<std::array<double, 2>, 3> enclosure{};
  /// (x, y, θ) rounded to doubles (display and engine input only).
  std::array<double, 3> approx{};
  /// For each fixel: the curve and curve parameter of its contact point on
  /// the boundary (rounded for display when not rational).
  std::vector<int> contact_curve;
  std::vector<double> contact_u;
  /// For each fixel: its contact point g_i on the boundary at q*, in the
  /// part's body frame B (frame A at the scene pose), exact in Q(√d) (empty
  /// when q* is only enclosed).
  std::vector<std::array<QuadraticIrrational, 2>> p_BoG_B;
  /// For each fixel: the boundary's inward normal at g_i, frame B, of any
  /// positive length (rational: an edge normal, or the fixel's own normal
  /// when q* = 0).
  std::vector<Vec2> n_B;
  /// True when every gap is zero (q* = 0 exactly).
  bool at_scene_pose = false;
  /// When q* is not exact (a contact on a curved piece with open gaps): a
  /// certified enclosure, by the Krawczyk test in outward-rounded interval
  /// arithmetic, of cos θ*, sin θ* and, per fixel, of its contact point g_i
  /// and the boundary's tangent there (frame B), as [lo, hi] per coordinate.
  /// A decision these intervals cannot make is reported as undecided.
  std::array<std::array<double, 2>, 2> cos_sin_enclosure{};
  std::vector<std::array<std::array<double, 2>, 2>> p_BoG_B_enclosure;
  std::vector<std::array<std::array<double, 2>, 2>> tangent_B_enclosure;
};

/// Solves for q*: exactly when every fixel lies on a polyline edge, or every
/// gap is zero (then q* = 0 and each contact keeps the fixel's own point and
/// normal); otherwise (contacts on B-spline pieces) as a certified enclosure
/// (interval Newton / Krawczyk, locally unique). Throws SceneError when the
/// scene has no boundary or dof != 3, when a fixel is not on the boundary,
/// when no seated pose exists (a fixel cannot touch its edge) or when it is
/// not unique, and UnsupportedError when the enclosure cannot be certified.
SeatedPose seated_pose(const Scene& scene);

}  // namespace fixel
