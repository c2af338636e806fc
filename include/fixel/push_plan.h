#pragma once
/// @file
/// "How hard do I push here?": the magnitude profile of a frictionless push
/// at one boundary point, for the one-step model (S and G) and the
/// sustained push (J).

#include <optional>
#include <string>

#include "fixel/approach.h"
#include "fixel/interval.h"
#include "fixel/outcomes.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/seat_report.h"

namespace fixel {

/// The plan for a push at parameter `u` of curve `curve`, at the scene pose.
struct PushPlan {
  int curve = 0;
  Rational u;
  Vec2 point_A;   ///< The boundary point (m, frame A).
  Vec2 normal_A;  ///< Inward normal there (not unit; the push direction); at a corner, the next edge's.
  /// The point is a corner: its pushes form the fan between the two
  /// one-sided normals, and a status is IN when the whole fan is in.
  bool corner = false;
  VectorQ wrench_direction;  ///< g = (n, r ⊗ n), r from the centre of mass (frame A).
  RegionStatus in_S = RegionStatus::kOut;
  Magnitudes magnitudes_S;           ///< Euclidean |p| (N·s) of impulses along g that land in S (inner bound).
  std::optional<RegionStatus> in_G;  ///< With G (dof 3, frictionless pusher).
  Magnitudes magnitudes_G;           ///< The same for G (one of its pieces).
  /// At a representative impulse of the S window (τ* g with τ* rational in
  /// the middle of the exact window, or twice its lower end when it is
  /// unbounded): the impulse and its one-step outcomes. Only when in_S is
  /// IN (at an OUT corner g's own ray may hit S while the fan does not).
  std::optional<VectorQ> sample_impulse;
  OutcomeCount sample_outcomes;
  std::optional<bool> sample_in_G;
  std::optional<RegionStatus> in_J;  ///< Sustained push (when J can be computed), else unset.
  std::string J_note;                ///< Why J was not judged, when unset.
  /// J′ (docs/theory.md §10.7), built whenever J is.
  std::optional<ApproachSet> approach;
  /// The point against J′: at a smooth point the exact verdict on g, the
  /// push's frame-B wrench at q* (held as the constant world-frame wrench
  /// R(θ*)·g along the way), IN or OUT; at a corner the fan's status as
  /// `fixel region --push sustained --approach` classifies it (PARTIAL
  /// when it cannot tell). Unset when J′ is not decided (`J_approach_note`
  /// says why).
  std::optional<RegionStatus> in_J_approach;
  /// At a smooth point: why g is not in J′, and the pair's pose when a pair
  /// holds the part on its way (`contains` unset when undecided).
  std::optional<ApproachVerdict> J_approach_verdict;
  std::string J_approach_note;
};

/// Plans a push. Throws InputError for a point off the boundary's
/// parameter range; kPartial statuses where the normal is undefined.
/// `control` (may be null) is polled by G's construction and the outcome
/// enumeration; stopping throws StoppedError.
PushPlan plan_push(const Scene& scene, int curve, const Rational& u, bool with_guaranteed,
                   RunControl* control = nullptr);

/// Relative width (hi − lo) / lo of a magnitude window (display); +inf when
/// unbounded, NaN when empty.
double relative_width(const Magnitudes& m);

}  // namespace fixel
