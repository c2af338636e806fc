// The subdivision's lazy pieces (fixel/internal/lazy_piece.h): their
// enclosures and leg enclosures hold the exact control points and legs,
// and the exact points they make equal repeated exact halving.
#include "fixel/internal/lazy_piece.h"

#include <gtest/gtest.h>

#include <random>

#include "filter_test_util.h"
#include "fixel/curve.h"
#include "fixel/filter.h"
#include "fixel/region.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::run;

GTEST_TEST(LazyPiece, AxisParallelLegsOfWholePiecesAreExactZeros) {
  // Eight end legs of nonunique_part's twelve cubic pieces are parallel to
  // an axis; each zero coordinate is a difference of two equal non-dyadic
  // rationals. As a difference of enclosures it straddled zero, and the
  // paper cone's grid direction along that axis could not be certified (8
  // of the 12 pieces fell back). Taken exactly, it is a point.
  const Scene scene = test::scene_file("nonunique_part");
  int axis_parallel = 0;
  for (const BezierPiece& piece : scene.body.boundary->pieces) {
    const internal::LazyPiece lazy(piece, true);
    const std::vector<Vec2> legs = piece.legs();
    ASSERT_EQ(lazy.leg_enclosures().size(), legs.size());
    for (std::size_t k = 0; k < legs.size(); ++k)
      for (const auto& [exact, enclosed] :
           {std::pair{legs[k].x, lazy.leg_enclosures()[k].x}, std::pair{legs[k].y, lazy.leg_enclosures()[k].y}}) {
        if (exact != 0) continue;
        ++axis_parallel;
        EXPECT_EQ(enclosed.inf(), 0);
        EXPECT_EQ(enclosed.sup(), 0);
      }
  }
  EXPECT_EQ(axis_parallel, 8);
  const SeatingSet S = seating_set(scene);
  for (const ConeMethod method : {ConeMethod::kPaper, ConeMethod::kTight}) {
    RegionOptions opt;
    opt.resolution = Rational(1, 4096);
    opt.cone = method;
    reset_filter_stats();
    const Region r = run(false, [&] { return compute_region(scene, S, opt); });
    EXPECT_EQ(filter_stats().at(FilterSite::kRegionTest).fallbacks, 0) << to_string(method);
    EXPECT_EQ(filter_stats().at(FilterSite::kRegionTest).certified, r.stats.cone_tests) << to_string(method);
  }
}

// The subdivision's lazy pieces: halving enclosures keeps them around the
// exact control points, and the exact points made from the boundary piece
// at depth 12 equal those of twelve exact halvings.
// Rational containment of a double interval: no tolerance.
bool holds(const internal::FI& x, const Rational& q) { return Rational(x.inf()) <= q && q <= Rational(x.sup()); }

GTEST_TEST(LazyPiece, LazyPiecesEncloseAndEqualRepeatedExactHalving) {
  const BezierPiece root{0, Rational(1, 3), Rational(2), {{0, 0}, {Rational(1, 3), 2}, {3, Rational(5, 7)}, {4, 0}}};
  ForceExactScope filtered(false);
  internal::LazyPiece lazy(root, true);
  BezierPiece exact = root;
  for (int depth = 0; depth < 12; ++depth) {
    const bool left = depth % 3 == 1;
    const auto h = lazy.halves();
    lazy = left ? h.first : h.second;
    const auto e = exact.split(Rational(1, 2));
    exact = left ? e.first : e.second;
  }
  ASSERT_EQ(lazy.enclosures().size(), exact.control.size());
  for (std::size_t k = 0; k < exact.control.size(); ++k) {
    EXPECT_TRUE(holds(lazy.enclosures()[k].x, exact.control[k].x)) << k;
    EXPECT_TRUE(holds(lazy.enclosures()[k].y, exact.control[k].y)) << k;
  }
  EXPECT_EQ(lazy.u0(), exact.u0);
  EXPECT_EQ(lazy.u1(), exact.u1);
  const BezierPiece& made = lazy.exact();
  for (std::size_t k = 0; k < exact.control.size(); ++k) {
    EXPECT_EQ(made.control[k].x, exact.control[k].x) << k;
    EXPECT_EQ(made.control[k].y, exact.control[k].y) << k;
  }
}

// The legs of a lazy piece are halved on their own (de Casteljau on the
// hodograph). At depth 20 of a cubic with non-dyadic control points each
// leg enclosure holds the exact leg of the sub-curve (made in one exact
// restriction, not by halving) and is tight relative to the leg: a
// difference of the point enclosures is about 10^-7 wide relative to a leg
// that short, which left blob32's rays grazing S undecided.
GTEST_TEST(LazyPiece, LegEnclosuresHoldTheExactLegsAndStayTightAtDepthTwenty) {
  const BezierPiece root{
      0,
      Rational(0),
      Rational(1),
      {{0, 0}, {Rational(1, 3), Rational(7, 5)}, {Rational(19, 7), Rational(2, 3)}, {4, Rational(1, 9)}}};
  ForceExactScope filtered(false);
  std::mt19937_64 rng(20);
  for (int path = 0; path < 8; ++path) {
    internal::LazyPiece lazy(root, true);
    for (int depth = 0; depth < 20; ++depth) {
      const auto h = lazy.halves();
      lazy = rng() % 2 ? h.first : h.second;
    }
    const BezierPiece exact = root.restrict_to(lazy.u0(), lazy.u1());
    ASSERT_EQ(lazy.leg_enclosures().size() + 1, exact.control.size());
    for (std::size_t k = 0; k + 1 < exact.control.size(); ++k) {
      const Vec2 leg = sub(exact.control[k + 1], exact.control[k]);
      const internal::FVec2& f = lazy.leg_enclosures()[k];
      EXPECT_TRUE(holds(f.x, leg.x) && holds(f.y, leg.y)) << "path " << path << " leg " << k;
      // Relative width below 2^-40 (the old difference of points: about 2^-23).
      const Rational rel = 1099511627776;
      EXPECT_LT(Rational(f.x.sup()) - Rational(f.x.inf()), abs(leg.x) / rel) << "path " << path << " leg " << k;
      EXPECT_LT(Rational(f.y.sup()) - Rational(f.y.inf()), abs(leg.y) / rel) << "path " << path << " leg " << k;
    }
  }
}

// After the exact path halved a piece, its children's legs come from exact
// differences: they hold the exact legs as well.
GTEST_TEST(LazyPiece, LegsOfExactlyHalvedPiecesHoldTheExactLegs) {
  const BezierPiece root{0, Rational(0), Rational(1), {{0, 0}, {Rational(1, 3), 2}, {3, Rational(5, 7)}, {4, 0}}};
  ForceExactScope filtered(false);
  internal::LazyPiece lazy(root, true);
  (void)lazy.exact();  // as the exact path does: later halvings are exact
  const auto h = lazy.halves();
  const BezierPiece exact = root.restrict_to(h.second.u0(), h.second.u1());
  for (std::size_t k = 0; k + 1 < exact.control.size(); ++k) {
    const Vec2 leg = sub(exact.control[k + 1], exact.control[k]);
    EXPECT_TRUE(holds(h.second.leg_enclosures()[k].x, leg.x) && holds(h.second.leg_enclosures()[k].y, leg.y)) << k;
  }
}

}  // namespace
}  // namespace fixel
