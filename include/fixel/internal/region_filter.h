#pragma once
// Interval pre-tests of the pushing region (docs/performance.md, issue 12):
// a segment's wrench cone (tight or paper) and a point's push wrenches are built as
// interval enclosures straight from the control points, with every decision
// of the exact construction (zero legs, direction extremes, spans) taken on a
// certified sign. A target that answers ray and OUT tests on enclosures then
// decides OUT and partial without one exact rational; IN (whose magnitudes
// are part of the answer) and anything undecided go to the exact path, which
// recomputes from scratch, so no answer depends on which path ran.

#include <optional>
#include <vector>

#include "fixel/internal/enclosed_plane.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/lazy_piece.h"
#include "fixel/region.h"
#include "fixel/wrench_cone.h"

namespace fixel::internal {

// Enclosure of a target's exact ray magnitudes T(g) = {τ > 0 : b0 + τ g in
// the target}, certified non-empty: lo (closed or open), hi when bounded
// (then closed).
struct FMagnitudes {
  FI lo;
  bool lo_closed = false;
  bool has_hi = false;
  FI hi;
};

// What a target answers on enclosures. Its owner promises: contains_cone is
// interval_contains, test_point is contains_cone (IN or OUT) when
// answers_points(), and misses is true iff no generator's ray hits and the
// LP proves the cone misses (the Farkas certificate below is one such
// proof).
class IntervalTarget {
 public:
  virtual ~IntervalTarget() = default;
  // Does the ray of g meet the target: 1 hit, 0 miss, kUndecided.
  virtual int interval_ray_hits(const FGen& g) const = 0;
  // The OUT test of cone(gens[0..n)) (the target's misses()) when certified:
  // 1 the cone misses the target, 0 it meets it, kUndecided. A certified
  // answer counts the LP test it stands for (RegionStats::lp_tests). Asked
  // only of cones with no ray hit, unless out_test_sees_hits().
  virtual int certify_out_test(const FGen* gens, std::size_t n) = 0;
  // Whether certify_out_test is asked of every cone that is not IN: a
  // target whose misses() counts LP tests before it notices a hit.
  virtual bool out_test_sees_hits() const { return false; }
  // T(g) enclosed; false when a sign is undecided or T(g) may be empty. The
  // owner's contains_cone reports common_magnitudes (region_targets.h) of
  // these T and half_line = no T has an upper end.
  virtual bool interval_magnitudes(const FGen& g, FMagnitudes& out) const = 0;
  // contains_cone on enclosures: 1 IN, 0 not IN, kUndecided, given each
  // generator's interval_ray_hits. A convex target holds the cone iff every
  // generator's ray hits it (the default); a union of convex pieces (G)
  // needs one piece that all of them hit.
  virtual int interval_contains(const FGen* gens, const int* hits, std::size_t n) const;
  // Whether test_point is contains_cone (IN or OUT), so that the point
  // pre-test applies; false for a target whose points can be partial.
  virtual bool answers_points() const { return true; }
  // Set by the pre-test before it asks interval_contains and
  // certify_out_test: whether the generators come in pairs (2k, 2k + 1)
  // with the same exact force part and two moments (a segment's tight
  // cone), so that a target may use that structure (a cross product of a
  // pair has an exactly zero moment part, which no enclosure shows).
  bool paired_generators = false;
  // Set by the pre-test for the duration of interval_contains and
  // certify_out_test: per generator, the index k of the control point whose
  // moment it certainly is ((d, (P_k − c) ⊗ d), P_k certainly the only
  // extreme for d), else −1; null when none is known. Generators with one
  // k lie in one plane through 0 (the wrenches of forces at P_k), which no
  // enclosure shows (docs/theory.md §10.5).
  const int* generator_points = nullptr;
  // False for a cone target (J): its IN answers carry no magnitudes
  // (half_line, Magnitudes{}), so a certified IN is the whole answer.
  virtual bool in_answers_have_magnitudes() const { return true; }
};

// Enclosure of the magnitudes an IN answer reports: certified non-empty,
// or (`empty`) certified empty, the upper end certainly below the lower.
struct MagnitudeBounds {
  FI lo;
  bool lo_closed = true;
  bool has_hi = false;
  FI hi;
  bool hi_closed = true;
  bool all_half = true;  // no generator's T(g) has an upper end
  bool empty = false;    // no common magnitude: the exact answer is Magnitudes{}
};

// The pre-test's answer.
enum class Quick {
  kIn,       // certified IN: the exact path runs for the magnitudes
  kOut,      // certified OUT (a segment: the LP test is counted)
  kPartial,  // certified partial (a segment that must split, a point with no defined fan)
  kUnknown,  // some sign undecided: the exact path decides
};

// The segment test of classify (region.cpp) with the tight or the paper
// cone (`method`) for `families` of push directions with pusher friction
// mu, centre of mass c, from the enclosures of the segment's control
// points and legs. On kIn, `bounds` (if given) gets the enclosure of the
// answer's magnitudes when it can be certified.
Quick quick_segment(const LazyPiece::Enclosures& control, const LazyPiece::Enclosures& legs, const Vec2& c,
                    const Rational& mu, const std::vector<EdgeFamily>& families, ConeMethod method,
                    IntervalTarget& target, std::optional<MagnitudeBounds>* bounds = nullptr);

// cos_half_angle_lower(a, b) (internal/wrench_cone_detail.h) of the exact
// directions enclosed by a and b, enclosed; false when not certified (then
// nothing is claimed). Needs a Protect scope.
bool cos_half_bounds(const FVec2& a, const FVec2& b, FI& out);

// The point test of status_at: tangents t_in, t_out (enclosures of the exact
// ones) at `point`.
Quick quick_point(const FVec2& t_in, const FVec2& t_out, const Vec2& point, const Vec2& c, const Rational& mu,
                  const std::vector<EdgeFamily>& families, IntervalTarget& target,
                  std::optional<MagnitudeBounds>* bounds = nullptr);

}  // namespace fixel::internal
