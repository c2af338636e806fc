// The paper cone on enclosures (fixel/internal/paper_cone_filter.h): its
// generators hold the exact ones, and the segment tests made with it give
// the exact test's answers.
#include "fixel/internal/paper_cone_filter.h"

#include <gtest/gtest.h>

#include <random>

#include "filter_test_util.h"
#include "fixel/curve.h"
#include "fixel/filter.h"
#include "fixel/internal/region_filter.h"
#include "fixel/internal/wrench_cone_detail.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/seating.h"
#include "fixel/wrench_cone.h"
#include "test_util.h"

namespace fixel {
namespace {

// The exact segment test of classify (region.cpp) for one family, forced
// exact: partial when there is no cone, IN, OUT, else partial.
internal::Quick exact_segment_test(RegionTarget& target, const BezierPiece& segment, const Vec2& c, ConeMethod method) {
  ForceExactScope exact;
  const auto cone = segment_wrench_cone(segment, c, EdgeFamily::kNormal, 0, method);
  if (!cone) return internal::Quick::kPartial;
  std::vector<Vec2> dirs;
  for (const auto& g : cone->generators)
    if (dirs.empty() || dirs.back().x != g[0] || dirs.back().y != g[1]) dirs.push_back({g[0], g[1]});
  Vec2 first, last;
  const bool pointed = direction_extremes(dirs, first, last);
  RegionInterval detail;
  if (target.contains_cone(cone->generators, pointed ? &first : nullptr, pointed ? &last : nullptr, &detail))
    return internal::Quick::kIn;
  return target.misses(cone->generators) ? internal::Quick::kOut : internal::Quick::kPartial;
}

GTEST_TEST(PaperConeFilter, PaperConesOfEdgesThroughTheCentreOfMassAgreeWithTheExactTest) {
  // The notched square's four notch edges lie on lines through the centre
  // of mass, so their paper cones' moment bounds are ⊥-angle terms ±R at
  // hull vertices with ⊥ inside the arc. Their pieces, halved ten times:
  // every answer the pre-test gives is the exact test's, with either cone.
  // (Its undecided ones are OUT tests of S that need the exact LP, as many
  // with the tight cone as with the paper cone.)
  const Scene scene = test::notched_square();
  const SeatingSet S = seating_set(scene);
  const auto target = seating_target(S, scene.background_impulse);
  internal::IntervalTarget* it = target->interval_target();
  ASSERT_NE(it, nullptr);
  const std::vector<EdgeFamily> normal{EdgeFamily::kNormal};
  int decided[2] = {0, 0}, pieces = 0;
  for (const int k : {2, 4, 8, 10}) {
    const BezierPiece& piece = scene.body.boundary->pieces[k];
    const std::vector<internal::LazyPiece> parts = test::halved(piece, 8);
    for (const auto& p : parts) {
      ++pieces;
      for (const ConeMethod method : {ConeMethod::kPaper, ConeMethod::kTight}) {
        const internal::Quick q =
            internal::quick_segment(p.enclosures(), p.leg_enclosures(), scene.body.p_AoCm_A, 0, normal, method, *it);
        if (q == internal::Quick::kUnknown) continue;
        ++decided[method == ConeMethod::kPaper ? 0 : 1];
        EXPECT_EQ(q, exact_segment_test(*target, p.exact(), scene.body.p_AoCm_A, method))
            << to_string(method) << " piece " << k << " u in [" << to_string(p.u0()) << ", " << to_string(p.u1())
            << "]";
      }
    }
  }
  EXPECT_GT(decided[0], pieces / 10);
  EXPECT_EQ(decided[0], decided[1]);
}

// Whether every exact entry lies in its enclosure (compared as rationals).
bool holds(const internal::FGen& enclosure, const VectorQ& exact) {
  for (int j = 0; j < 3; ++j)
    if (Rational(enclosure[j].inf()) > exact[j] || exact[j] > Rational(enclosure[j].sup())) return false;
  return true;
}

GTEST_TEST(PaperConeFilter, PaperConeEnclosuresHoldTheExactGeneratorsOfRandomSegments) {
  // Random Bézier segments of degree 1 to 3, pushed with and without
  // friction: the pre-test's paper cone exists iff the exact one does, and
  // each of its generators holds the exact one. Many of these cones take a
  // moment bound from a ⊥-angle term (X = ±sqrt_upper(|r|²) at a hull
  // vertex), which the enclosure must hold too.
  std::mt19937_64 rng(64);
  const Rational mu(1, 5);
  int built = 0, none = 0, undecided = 0, perpendicular = 0;
  for (int trial = 0; trial < 300; ++trial) {
    BezierPiece seg;
    seg.u0 = 0;
    seg.u1 = 1;
    const int degree = 1 + trial % 3;
    for (int k = 0; k <= degree; ++k)
      seg.control.push_back({test::random_rational(rng, -3, 3, 11), test::random_rational(rng, -3, 3, 11)});
    const Vec2 c{test::random_rational(rng, -1, 1, 7), test::random_rational(rng, -1, 1, 7)};
    internal::LazyPiece::Enclosures control, legs;
    for (const Vec2& p : seg.control) control.push_back(internal::to_interval(p));
    for (const Vec2& leg : seg.legs()) legs.push_back(internal::to_interval(leg));
    const SegmentBounds bounds = segment_bounds(seg);
    if (!bounds.pointed) continue;
    for (const EdgeFamily f : {EdgeFamily::kNormal, EdgeFamily::kMinus, EdgeFamily::kPlus}) {
      const Rational m = f == EdgeFamily::kNormal ? Rational(0) : mu;
      const Vec2 ds = push_direction(bounds.t_start, f, m), de = push_direction(bounds.t_end, f, m);
      if (cross(ds, de) < 0) continue;  // the exact path splits before the paper cone
      const auto exact = segment_wrench_cone(bounds, c, f, m, ConeMethod::kPaper);
      std::vector<internal::FGen> gens;
      const int answer =
          internal::paper_cone_enclosure(internal::to_interval(ds), internal::to_interval(de), control, legs, c, gens);
      if (answer == internal::kUndecided) {
        ++undecided;
        continue;
      }
      ASSERT_EQ(answer == 1, exact.has_value()) << "trial " << trial;
      if (!exact) {
        ++none;
        continue;
      }
      ++built;
      ASSERT_EQ(exact->generators.size(), 4u);
      ASSERT_TRUE(gens.size() == 4 || gens.size() == 2);
      for (std::size_t i = 0; i < 4; ++i)
        EXPECT_TRUE(holds(gens[i % gens.size()], exact->generators[i])) << "trial " << trial << " generator " << i;
      for (const Vec2& p : bounds.hull) {
        const Rational R = internal::sqrt_upper(dot(sub(p, c), sub(p, c)));
        perpendicular += exact->generators[0][2] == -R || exact->generators[1][2] == R;
      }
    }
  }
  EXPECT_GT(built, 200);
  EXPECT_GT(perpendicular, 20);
  EXPECT_LT(undecided * 20, built) << undecided << " undecided, " << none << " without a cone";
}

}  // namespace
}  // namespace fixel
