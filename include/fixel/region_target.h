#pragma once
/// @file
/// The target set a push must reach (S, G, J, or any set that can answer
/// the questions below): one interface, so that the region algorithm does
/// not branch on which set it classifies against. The model is CGAL's traits
/// parameter: the algorithm asks the target three exact questions.

#include <array>
#include <memory>
#include <vector>

#include "fixel/algebraic.h"
#include "fixel/rational.h"
#include "fixel/region.h"
#include "fixel/scene.h"

namespace fixel {

struct GuaranteedSet;
struct SeatingSet;
struct SustainedSet;
struct ApproachSet;

namespace internal {
class IntervalTarget;  // internal/region_filter.h
}

/// A target of the pushing region. Wrenches and generators are in frame A
/// (f_x, f_y, moment about the centre of mass); every answer is exact.
class RegionTarget {
 public:
  virtual ~RegionTarget() = default;

  /// Which push model the target answers for ("step", "sustained").
  virtual const char* push_model() const = 0;

  /// The target's name in reports: "S", "G" or "J".
  virtual const char* name() const = 0;

  /// Every ray of cone(gens) (generators with force parts in
  /// cone(d_first, d_last)) reaches the target. On success `detail` may get
  /// the certified magnitudes and the half_line flag.
  /// `d_first`, `d_last` are null when the force parts span π or more.
  virtual bool contains_cone(const std::vector<VectorQ>& gens, const Vec2* d_first, const Vec2* d_last,
                             RegionInterval* detail) = 0;

  /// No ray of cone(gens) reaches the target.
  virtual bool misses(const std::vector<VectorQ>& gens) = 0;

  /// Point test at one boundary point: the push wrenches form cone(gens) of
  /// one or two generators (parallel d_first, d_last: a single ray). The
  /// default is contains_cone; targets with richer answers override it.
  virtual RegionStatus test_point(const std::vector<VectorQ>& gens, const Vec2& d_first, const Vec2& d_last,
                                  Magnitudes* out, std::vector<Magnitudes>* set) {
    RegionInterval detail;
    const bool in = contains_cone(gens, &d_first, &d_last, &detail);
    if (out) *out = in ? detail.magnitudes : Magnitudes{};
    (void)set;
    return in ? RegionStatus::kIn : RegionStatus::kOut;
  }

  /// The exact region (RegionOptions::exact): polynomials in the local
  /// parameter s of a Bézier piece whose signs decide test_point along it.
  /// `gens[j][k]` is component k of push-wrench generator j (the same order
  /// as test_point's `gens`), a polynomial in s. The answer of test_point
  /// may change only at a real root of a returned polynomial. The default
  /// throws UnsupportedError: a target without this cannot give an exact region.
  virtual std::vector<Polynomial> sign_polynomials(const std::vector<std::array<Polynomial, 3>>& gens) const;

  /// Throws if the target cannot answer for a pusher with friction `mu`.
  virtual void check_pusher(const Rational& mu) const { (void)mu; }

  /// Throws InputError (naming the set: "S", "J" or "J'") when the target's
  /// set was built from another scene than `scene`, whose region or points
  /// it would otherwise answer for silently. The region, point and sample
  /// functions call it first. fixel's targets check S exactly against the
  /// scene (check_seating_set_of), and J and J′ against the scene they were
  /// built from where J looks (outline, centre of mass, mass, inertia,
  /// fixels); the default accepts every scene.
  virtual void check_scene(const Scene& scene) const { (void)scene; }

  /// The target's answers on interval enclosures (fixel's own targets; internal),
  /// or null: the region code then asks only the exact questions above.
  virtual internal::IntervalTarget* interval_target() { return nullptr; }

  /// Counters of the run (set by the region code before use; may be null).
  RegionStats* stats = nullptr;
};

/// The one-step seating set S of the paper, with background impulse b0:
/// a ray τ g reaches S when b0 + τ g ∈ S for some τ > 0. Keeps its own
/// copy of S (a temporary is fine). Throws InputError for a set
/// seating_set does not make (dof other than 3, or no apex).
std::unique_ptr<RegionTarget> seating_target(const SeatingSet& S, const VectorQ& b0);

/// The guaranteed set G (frictionless pusher only), with background b0.
/// Keeps its own copies of G and S.
std::unique_ptr<RegionTarget> guaranteed_target(const GuaranteedSet& G, const SeatingSet& S, const VectorQ& b0);

/// The sustained-push set J (docs/theory.md §10): a wrench direction reaches
/// J when it lies in J (any magnitude). Keeps a reference to J's data.
std::unique_ptr<RegionTarget> sustained_target(const SustainedSet& J);

/// The approach-aware set J′ (approach.h, docs/theory.md §10.7). J′ is not
/// kept as polyhedral cones, so a segment is IN when it is IN for J and
/// misses outer cones of the jam cones swept along the approach, OUT when
/// it misses J or lies in a jam cone at a pose of the approach, and PARTIAL
/// otherwise: exact answers, a wider PARTIAL band than J's. Throws
/// UnsupportedError when J′ is not decided. Keeps its own copy of the data.
std::unique_ptr<RegionTarget> approach_target(const ApproachSet& A);

}  // namespace fixel
