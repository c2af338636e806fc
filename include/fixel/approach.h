#pragma once
/// @file
/// Past the paper: the approach-aware sustained-push set J′ ⊆ J
/// (docs/theory.md §10.7). J judges a push at the seated pose q* only. A part
/// that must turn by θ* on its way to the seat meets other normals and lever
/// arms on the way, and two fixels may hold it there. J′ keeps the wrenches
/// of J that no pair of fixels can hold at any pose of the pair's
/// two-contact family with θ between 0 (the scene pose) and θ*, both ends
/// included, and only while every contact of every family stays on its
/// edge. Decided exactly, in t = tan(θ/2), by real root isolation.

#include <array>
#include <memory>
#include <optional>
#include <string>

#include "fixel/algebraic.h"
#include "fixel/rational.h"
#include "fixel/scene.h"
#include "fixel/sustained.h"

namespace fixel {

namespace internal {
struct ApproachData;
}

/// A pose of a pair's two-contact family at which the pair can hold the
/// part at rest under a wrench: the witness that the wrench is not in J′.
struct ApproachHold {
  std::array<int, 2> fixels{};
  /// t = tan(θ/2) of the pose, exactly: a rational or an algebraic number
  /// (when the pose is t*, θ = θ*: `at_seat` is true and `t` is unset).
  std::optional<AlgebraicReal> t;
  bool at_seat = false;
  /// θ of the pose (rad, counter-clockwise; display only).
  double theta = 0;
  /// For a pair on parallel edges: how far the part has slid along them
  /// (frame B, in units of the edge normal's length times metres; display
  /// only), from q* when `at_seat`.
  std::optional<double> slide;
};

/// J′: the wrenches of J that seat the part along the whole approach.
struct ApproachSet {
  /// J at q*, which J′ refines.
  SustainedSet J;
  /// False when J′ cannot be decided: a contact lies on a curved piece
  /// (q* only enclosed, or exact with every gap 0), or a pair on parallel
  /// edges can touch both at every rotation. `undecided_reason` says which.
  bool decided = false;
  std::string undecided_reason;
  /// tan(θ*/2), exactly, and θ* (rad, display). Zero at an unrotated seat,
  /// where J′ = J.
  QuadraticIrrational t_star{0, 0, 0};
  double theta_star = 0;
  /// Every contact of every pair family lies on its edge (ends included)
  /// for θ between 0 and θ*. When false (and `decided`), J′ is empty: the
  /// part could turn off an edge on its way; `edge_reason` names the fixel
  /// and the pair. Meaningless when !decided.
  bool on_edges = false;
  std::string edge_reason;
  /// J′ has no wrench that J has not: true when J is empty or !on_edges
  /// (J′ may still be empty when this is false). Meaningless when !decided
  /// (then J′ is unknown, not empty): read `decided` first.
  bool empty = true;
  /// Internal data of the exact tests.
  std::shared_ptr<const internal::ApproachData> data;

  /// w ∈ J′ (world frame, f_x, f_y in N and the moment about the centre of
  /// mass in N·m; length 3). Throws UnsupportedError when !decided and
  /// InputError for a wrong length.
  bool contains(const VectorQ& w_W) const;
  /// Empty when w ∈ J′; otherwise the reason in words. When a pair holds
  /// the part on the way, `hold` (if not null) gets the pose.
  std::string why_not(const VectorQ& w_W, ApproachHold* hold = nullptr) const;

  /// The same tests for a wrench w_B given in frame B at the seat (force
  /// along the part's own axes in N, moment about the centre of mass in
  /// N·m; length 3), as a finger's push at a boundary point is (the
  /// pushing region's frame): its world-frame wrench, held along the way,
  /// is R(θ*)·w_B, whose coordinates lie in Q(√d) when θ* is irrational.
  /// Exact as `contains`; the same exceptions.
  bool contains_part_frame(const VectorQ& w_B) const;
  std::string why_not_part_frame(const VectorQ& w_B, ApproachHold* hold = nullptr) const;
};

/// Builds J′ from J (which must come from sustained_set on the same
/// scene). Never throws for a scene J was computed on: what it cannot
/// decide is reported in `decided`.
ApproachSet approach_set(const Scene& scene, const SustainedSet& J);

}  // namespace fixel
