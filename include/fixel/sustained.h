#pragma once
/// @file
/// Past the paper: the sustained-push wrench set J at the seated pose q*.
/// A constant world-frame wrench w (force through the centre of mass, N,
/// and moment about it, N·m) seats the part and keeps it seated when
///   (a) −w ∈ int cone(W_n*)  (the part cannot escape), and
///   (b) −w ∉ FC_i + FC_j for every pair and −w ∉ FC_i for every fixel
///       (no proper subset of fixels can hold the part),
/// with W_n*, FC_i evaluated at q* (docs/theory.md §10).

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "fixel/rational.h"
#include "fixel/scene.h"
#include "fixel/seated_pose.h"

namespace fixel {

namespace internal {
struct SustainedData;
}

/// A convex polyhedral cone in wrench space (f_x, f_y, moment), world frame
/// at q*, with coefficients in Q(√d): V-form `rays` (of its closure) and
/// H-form rows a·w ≥ 0 (`closed`) and a·w > 0 (`strict`).
struct AlgebraicCone {
  std::vector<std::array<QuadraticIrrational, 3>> rays;
  std::vector<std::array<QuadraticIrrational, 3>> closed;
  std::vector<std::array<QuadraticIrrational, 3>> strict;
  /// False when q* is only enclosed (curved contacts): the vectors above are
  /// then empty and these certified enclosures ([lo, hi] per entry) hold.
  bool exact = true;
  std::vector<std::array<std::array<double, 2>, 3>> rays_enclosure, closed_enclosure, strict_enclosure;
};

/// The wrenches a pair of fixels can hold: −(FC_i + FC_j) in w-space.
struct JamCone {
  std::array<int, 2> fixels{};
  AlgebraicCone cone;
};

/// J = (open cone) minus the union of the jam cones, exact.
struct SustainedSet {
  SeatedPose pose;
  /// {w : −w ∈ int cone(W_n*)}: rays −W_n,i*, strict rows only.
  AlgebraicCone cone;
  /// −(FC_i + FC_j) for every pair i < j (each −FC_i lies in a pair's cone).
  std::vector<JamCone> jam_cones;
  /// J as disjoint convex cones (their union is J exactly).
  std::vector<AlgebraicCone> pieces;
  /// False when the enclosure of q* could not decide which pieces are
  /// empty (then `pieces` is empty and `empty` is false: unknown).
  bool pieces_decided = true;
  /// J has no wrench: no single sustained push can be trusted.
  bool empty = true;
  /// When empty: which fixels can hold the part, in words.
  std::string empty_reason;
  /// Every solution of the acceleration-level contact LCP at the seat keeps
  /// the part at rest with every contact loaded, for every w in J
  /// (docs/theory.md §10.3: true by the theorem there whenever the seat is
  /// non-degenerate; vacuous when J is empty), and checked by enumerating
  /// every contact mode of the step LCP at the seat for one wrench inside
  /// each piece when q* is rational (`stability_checks` counts them).
  bool strongly_stable = false;
  int stability_checks = 0;
  /// Friction used per fixel (the upper end of an interval: J shrinks as μ
  /// grows, so J at the upper ends is the robust set).
  std::vector<Rational> mu;
  /// Body-frame data for the exact tests (internal).
  std::shared_ptr<const internal::SustainedData> data;

  /// Exact membership of a world-frame wrench (length 3). With an enclosed
  /// q*, throws UnsupportedError when the enclosure cannot decide.
  bool contains(const VectorQ& w_W) const;
  /// Empty when w_W is in J; otherwise which condition fails, in words
  /// ("can escape: ..." or "fixels[0] and fixels[1] can hold the part ...").
  std::string why_not(const VectorQ& w_W) const;
};

/// Checks strong stability by contact-mode enumeration at the seat, for one
/// wrench inside each piece of J, when q* is rational; clears
/// J.strongly_stable if an outcome moves. Returns the number of wrenches
/// checked (0 when q* is irrational or J is empty).
int check_strong_stability(const Scene& scene, SustainedSet& J);

/// The sustained-push analyses need a rigid body (dof 3) with exactly 3
/// fixels: throws SceneError naming the field otherwise (as sustained_set
/// does first). They also need the seated pose q* (seated_pose's errors).
void require_sustained_fixture(const Scene& scene);

/// Computes q* and J. Throws what seated_pose throws, SceneError when W_n*
/// is singular (a degenerate seat), and InputError for dof != 3. With
/// `check_stability` false the independent contact-mode check of strong
/// stability is skipped (`strongly_stable` then rests on the theorem alone
/// and `stability_checks` is 0): fixture design evaluates J for thousands of
/// layouts, and the check costs most of J's time.
SustainedSet sustained_set(const Scene& scene, bool check_stability = true);

}  // namespace fixel
