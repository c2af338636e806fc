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
  /// True when every gap is zero (q* = 0 exactly).
  bool at_scene_pose = false;
};

/// Solves for q*. Throws SceneError when no seated pose exists (a fixel
/// cannot touch the boundary) or when it is not unique, and SceneError if
/// the scene has no boundary.
SeatedPose seated_pose(const Scene& scene);

}  // namespace fixel
