#pragma once
/// @file
/// The scene: a planar part (or point mass) near its fixels (docs/formats.md).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fixel/error.h"
#include "fixel/geometry.h"
#include "fixel/rational.h"

namespace fixel {
struct Boundary;
}

namespace fixel {

/// The moving part. Generalised coordinates are (x, y, θ) for dof 3 and
/// (x, y) for a point mass (dof 2).
struct Body {
  int dof = 3;
  Rational mass;     ///< m > 0 (kg).
  Rational inertia;  ///< I > 0 about the centre of mass (kg·m²; dof 3 only; 0 for dof 2).
  /// ν^ℓ, length dof (m/s, rad/s). Must be set in code (an empty vector is
  /// refused); a scene file's default is 0.
  VectorQ velocity;
  Vec2 p_AoCm_A;  ///< Centre of mass in frame A (m).
  /// Which of mass, inertia and centre of mass were derived from the
  /// boundary (uniform density) rather than given in the scene.
  bool mass_from_area = false, inertia_from_area = false, center_of_mass_from_area = false;
  /// The part's outline (one closed counter-clockwise loop), if given.
  std::shared_ptr<const Boundary> boundary;
};

/// One fixture point ("fixel").
struct Fixel {
  /// Contact point on the part at the scene pose, frame A (m). The fixel
  /// itself sits at p − ψ n, a gap ψ outside the part.
  Vec2 p_AoF_A;
  Vec2 n_A;      ///< Inward unit normal (into the part), exactly x²+y² == 1.
  Rational mu;   ///< Coulomb friction μ ≥ 0 (the lower end of an interval).
  Rational gap;  ///< Gap ψ ≥ 0 at the current configuration (m).
  /// Upper end of a friction interval ["lo", "hi"]; unset for one value.
  std::optional<Rational> mu_hi;
  /// The upper end of the friction interval (mu for a single value).
  Rational mu_upper() const { return mu_hi.value_or(mu); }
  /// The scene says this fixel is knowingly not on the part's outline (or
  /// not along its normal): the outline check skips it.
  bool off_boundary = false;
};

/// A whole scene file.
struct Scene {
  std::string name;
  std::string description;  ///< Free text: what the scene is, and any caveat.
  Rational time_step;       ///< h > 0 (s).
  Body body;
  std::vector<Fixel> fixels;
  Rational pusher_mu;  ///< Pusher friction μ_p ≥ 0 (default 0; the lower end of an interval).
  /// b₀ (N·s, and N·m·s for the rotation), length dof. A scene file may
  /// leave it out (then 0); in code it must be set (e.g. VectorQ::Zero(3)):
  /// an empty vector is refused.
  VectorQ background_impulse;
  /// Upper end of the pusher's friction interval; unset for one value.
  std::optional<Rational> pusher_mu_hi;
  /// The upper end of the pusher's friction interval.
  Rational pusher_mu_upper() const { return pusher_mu_hi.value_or(pusher_mu); }

  /// Number of contacts n_c.
  int num_contacts() const { return static_cast<int>(fixels.size()); }
  /// Lever arm r_i = p_i − c of fixel i, in frame A (m). Throws InputError
  /// for an index out of range.
  Vec2 lever_arm(int i) const;
  /// Tangent t_i = n_i rotated by +90° (frame A, unit). Throws InputError
  /// for an index out of range.
  Vec2 tangent(int i) const;
};

/// Checks of a scene's values, shared by the JSON reader and by code that
/// builds a Scene itself. Each throws SceneError naming `path` (the field's
/// JSON path, e.g. `fixels[1].gap`) and the value.
void check_positive(const Rational& v, const std::string& path);
void check_nonnegative(const Rational& v, const std::string& path);
/// n_A must be exactly of unit length (a rational point on the unit circle).
void check_unit_normal(const Vec2& n_A, const std::string& path);

/// With a boundary: every fixel not marked `off_boundary` has its point
/// exactly on the outline and its normal exactly the outline's inward normal
/// there (any normal in the cone between the two one-sided normals at a
/// corner). Throws SceneError naming `fixels[i].point` (with the distance to
/// the outline) or `fixels[i].normal` (with the angle to the inward normal).
void check_fixels_on_boundary(const Scene& scene);

/// Every value check on a scene built in code: h > 0, dof 2 or 3, mass and
/// inertia > 0, vector lengths equal to dof, unit normals, friction and
/// gaps >= 0, fixels on the outline (check_fixels_on_boundary). Throws SceneError as above. (The one-step rules n_c ==
/// dof and W_n nonsingular belong to the analyses that need them.)
void validate_scene(const Scene& scene);

/// validate_scene without the unit normals (a zero normal is still refused)
/// and the outline check: the cheap
/// checks that every analysis built on contact_matrices (seating_set,
/// simulate, enumerate_outcomes, guaranteed_set, ...), sustained_set and
/// physics::push run first, so that a scene built in code with a wrong
/// value is a SceneError, never a crash. (Fixture design builds scenes whose
/// normals are inward but not of unit length; the analyses accept them.)
void check_scene_values(const Scene& scene);

}  // namespace fixel
