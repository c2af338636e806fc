#pragma once
// Interval pre-tests of the pushing region (docs/performance.md, issue 12):
// a segment's wrench cone (tight or paper) and a point's push wrenches are built as
// interval enclosures straight from the control points, with every decision
// of the exact construction (zero legs, direction extremes, spans) taken on a
// certified sign. A target that answers ray and OUT tests on enclosures then
// decides OUT and partial without one exact rational; IN (whose magnitudes
// are part of the answer) and anything undecided go to the exact path, which
// recomputes from scratch, so no answer depends on which path ran.

#include <array>
#include <boost/container/small_vector.hpp>
#include <optional>
#include <vector>

#include "fixel/internal/filtered.h"
#include "fixel/region.h"
#include "fixel/wrench_cone.h"

namespace fixel::internal {

// A wrench generator (f_x, f_y, moment about the centre of mass) enclosed.
using FGen = std::array<FI, 3>;

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

// A piece of the subdivision: a parameter range [u0, u1] of a boundary
// piece, enclosures of its control points and of its control polygon's
// legs (both halved in intervals), and its exact control points only when
// asked for (the exact path), then made from the boundary piece (the
// control points of a sub-curve are unique, so they equal those of
// repeated halving). Children of a piece whose exact points were asked for
// are halved exactly.
class LazyPiece {
 public:
  using Enclosures = boost::container::small_vector<FVec2, 4>;
  // The whole boundary piece; with `enclose`, its control points' enclosures.
  LazyPiece(const BezierPiece& root, bool enclose);
  int curve() const { return root_->curve; }
  const Rational& u0() const { return u0_; }
  const Rational& u1() const { return u1_; }
  // Empty when made without enclosures.
  const Enclosures& enclosures() const { return ctrl_; }
  // Legs P_{k+1} − P_k, enclosed on their own: a difference of two point
  // enclosures loses all relative precision once the piece is short.
  const Enclosures& leg_enclosures() const { return legs_; }
  const BezierPiece& exact() const;
  // The halves at local parameter 1/2.
  std::pair<LazyPiece, LazyPiece> halves() const;

 private:
  LazyPiece(const BezierPiece* root, Rational u0, Rational u1) : root_(root), u0_(std::move(u0)), u1_(std::move(u1)) {}
  const BezierPiece* root_;
  Rational u0_, u1_;
  Enclosures ctrl_, legs_;
  mutable std::optional<BezierPiece> exact_;
  mutable bool asked_ = false;
};

// The segment test of classify (region.cpp) with the tight or the paper
// cone (`method`) for `families` of push directions with pusher friction
// mu, centre of mass c, from the enclosures of the segment's control
// points and legs. On kIn, `bounds` (if given) gets the enclosure of the
// answer's magnitudes when it can be certified.
Quick quick_segment(const LazyPiece::Enclosures& control, const LazyPiece::Enclosures& legs, const Vec2& c,
                    const Rational& mu, const std::vector<EdgeFamily>& families, ConeMethod method,
                    IntervalTarget& target, std::optional<MagnitudeBounds>* bounds = nullptr);

// The paper cone (segment_wrench_cone with ConeMethod::kPaper) of one edge
// family's push directions enclosed by ds and de, for a segment with
// control points and legs enclosed and centre of mass c, as the pre-test
// builds it: 1 with `gens` enclosing the exact generators in their order
// (the two of û_s only, when û_e = û_s exactly), 0 when the exact
// construction finds no cone (its unit directions span π), kUndecided when
// a sign it needs is not certified.
int paper_cone_enclosure(const FVec2& ds, const FVec2& de, const LazyPiece::Enclosures& control,
                         const LazyPiece::Enclosures& legs, const Vec2& c, std::vector<FGen>& gens);

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
