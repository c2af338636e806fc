// The region's interval pre-test (fixel/internal/region_filter.h): lazy
// pieces halved in intervals, their leg enclosures, and the segment test on
// them; each answer it certifies equals the exact path's, and the counters
// show where it falls back.
#include "fixel/internal/region_filter.h"

#include <gtest/gtest.h>

#include <random>

#include "filter_test_util.h"
#include "fixel/curve.h"
#include "fixel/filter.h"
#include "fixel/guaranteed.h"
#include "fixel/internal/wrench_cone_detail.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "fixel/wrench_cone.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::region_json_of;
using test::run;

// A whole piece halved `levels` times in intervals: its 2^levels parts in
// order.
std::vector<internal::LazyPiece> halved(const BezierPiece& piece, int levels) {
  std::vector<internal::LazyPiece> parts{internal::LazyPiece(piece, true)};
  for (int level = 0; level < levels; ++level) {
    std::vector<internal::LazyPiece> next;
    for (const auto& p : parts) {
      auto h = p.halves();
      next.push_back(h.first);
      next.push_back(h.second);
    }
    parts = next;
  }
  return parts;
}

GTEST_TEST(RegionFilter, StraightEdgesWithNonDyadicEndsPassTheRegionPreTestWithoutTheExactPath) {
  // example2_rounded's four straight edges end at tenths: one leg per piece,
  // whose push directions at both ends are the same vector. Before that was
  // recognised, 36 of its 82 region tests fell back; now only the few whose
  // target tests need the exact LP do.
  const Scene scene = test::scene_file("example2_rounded");
  const SeatingSet S = seating_set(scene);
  RegionOptions opt;
  opt.resolution = Rational(1, 1024);
  reset_filter_stats();
  const Region r = run(false, [&] { return compute_region(scene, S, opt); });
  const FilterCounts c = filter_stats().at(FilterSite::kRegionTest);
  EXPECT_EQ(c.certified + c.fallbacks, r.stats.cone_tests);
  // The last four were OUT tests of cones meeting S between generators,
  // certified since by a combination's ray.
  EXPECT_EQ(c.fallbacks, 0) << c.certified << " certified";
}

GTEST_TEST(RegionFilter, AxisParallelLegsOfWholePiecesAreExactZeros) {
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

GTEST_TEST(RegionFilter, InSegmentsOfStraightPiecesCarryMagnitudeBoundsFromThePreTest) {
  // A straight piece gives each edge family one push direction, so its
  // first and last directions are one vector; as two enclosures their cross
  // product is not a point, and no IN answer had bounds (the exact path
  // then ran for every such segment). Now every one has: a segment whose
  // magnitude window is certainly empty is bounded as empty.
  const Scene scene = test::scene_file("example2_rounded");
  const SeatingSet S = seating_set(scene);
  const auto target = seating_target(S, scene.background_impulse);
  internal::IntervalTarget* it = target->interval_target();
  ASSERT_NE(it, nullptr);
  int in = 0, bounded = 0;
  for (const std::vector<EdgeFamily>& families :
       {std::vector<EdgeFamily>{EdgeFamily::kNormal}, std::vector<EdgeFamily>{EdgeFamily::kMinus, EdgeFamily::kPlus}})
    for (const BezierPiece& piece : scene.body.boundary->pieces) {
      if (piece.control.size() != 2) continue;
      const std::vector<internal::LazyPiece> parts = halved(piece, 10);
      const Rational mu = families.size() == 1 ? Rational(0) : Rational(1, 10);
      for (const auto& p : parts) {
        std::optional<internal::MagnitudeBounds> bounds;
        const internal::Quick q = internal::quick_segment(p.enclosures(), p.leg_enclosures(), scene.body.p_AoCm_A, mu,
                                                          families, ConeMethod::kTight, *it, &bounds);
        if (q != internal::Quick::kIn) continue;
        ++in;
        if (bounds) ++bounded;
      }
    }
  EXPECT_GE(in, 8);
  EXPECT_EQ(bounded, in) << bounded << " of " << in << " IN segments bounded";
}

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

GTEST_TEST(RegionFilter, PaperConesOfEdgesThroughTheCentreOfMassAgreeWithTheExactTest) {
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
    const std::vector<internal::LazyPiece> parts = halved(piece, 8);
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

GTEST_TEST(RegionFilter, PaperConeEnclosuresHoldTheExactGeneratorsOfRandomSegments) {
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

GTEST_TEST(RegionFilter, InMagnitudesWhoseLowerEndIsAPointAndNoUpperEndNeedNoExactPath) {
  // The polygon with every gap 0: S is the cone −Σ FC_i and b0 = 0 its
  // apex, so every IN answer's magnitudes are a half-line from exactly 0,
  // which the enclosures show (a point lower end, no upper end). They are
  // settled without the exact path, merged or not, and the JSON is the
  // exact path's.
  Scene scene = test::scene_file("polygon");
  for (auto& f : scene.fixels) f.gap = 0;
  const SeatingSet S = seating_set(scene);
  for (const bool merge : {false, true}) {
    RegionOptions opt;
    opt.resolution = Rational(1, 1024);
    opt.merge = merge;
    reset_filter_stats();
    const std::string filtered = run(false, [&] { return region_json_of(scene, S, opt); });
    const FilterCounts c = filter_stats().at(FilterSite::kInMagnitudes);
    EXPECT_GT(c.certified, 0) << "merge " << merge;
    EXPECT_EQ(c.fallbacks, 0) << "merge " << merge;
    EXPECT_NE(filtered.find("\"status\": \"in\""), std::string::npos);
    EXPECT_EQ(filtered, run(true, [&] { return region_json_of(scene, S, opt); })) << "merge " << merge;
  }
}

GTEST_TEST(RegionFilter, InAnswersWithCertainlyNoCommonMagnitudeNeedNoExactMagnitudes) {
  // On example2_rounded's right edge the IN segments have magnitude windows
  // whose ends cross: no common magnitude. Their enclosures show it, so the
  // exact path does not run for them. Counted against the forced-exact run
  // without merging: each IN answer with empty exact magnitudes is certified
  // (kInMagnitudes), every other one is computed exactly there.
  const Scene scene = test::scene_file("example2_rounded");
  const SeatingSet S = seating_set(scene);
  RegionOptions opt;
  opt.resolution = Rational(1, 1024);
  opt.merge = false;
  const Region exact = run(true, [&] { return compute_region(scene, S, opt); });
  long in = 0, empty = 0;
  for (const RegionInterval& r : exact.intervals) {
    if (r.status != RegionStatus::kIn) continue;
    ++in;
    if (r.magnitudes.empty) ++empty;
  }
  ASSERT_GT(empty, 0);
  reset_filter_stats();
  const std::string filtered = run(false, [&] { return region_json_of(scene, S, opt); });
  const FilterCounts c = filter_stats().at(FilterSite::kInMagnitudes);
  EXPECT_EQ(c.certified, empty);
  EXPECT_EQ(c.fallbacks, in - empty);
  EXPECT_EQ(filtered, run(true, [&] { return region_json_of(scene, S, opt); }));
  // Merged, the empty run needs no exact magnitudes at all, and the JSON
  // is still the exact path's.
  opt.merge = true;
  reset_filter_stats();
  const std::string merged = run(false, [&] { return region_json_of(scene, S, opt); });
  EXPECT_GE(filter_stats().at(FilterSite::kInMagnitudes).certified, empty);
  EXPECT_EQ(merged, run(true, [&] { return region_json_of(scene, S, opt); }));
}

GTEST_TEST(RegionFilter, AnUndecidedRayBesideACertainMissAndACertainHitStillLeavesTheSegmentPartial) {
  // At 2^-20 the pieces beside a region end have generators whose rays
  // graze S. Where another generator certainly misses and each cone has a
  // certain hit, the segment is partial whatever those rays do (67 → 59
  // fallbacks); the legs' own enclosures (below) then decided nearly all
  // of the rest (59 → 3). The JSON, and its LP count, stay the same.
  const Scene scene = test::scene_file("blob32");
  const SeatingSet S = seating_set(scene);
  RegionOptions opt;
  opt.resolution = Rational(1, 1048576);
  reset_filter_stats();
  const std::string filtered = run(false, [&] { return region_json_of(scene, S, opt); });
  const FilterCounts c = filter_stats().at(FilterSite::kRegionTest);
  EXPECT_LE(c.fallbacks, 3) << c.certified << " certified";
  EXPECT_EQ(filtered, run(true, [&] { return region_json_of(scene, S, opt); }));
}

// The region's interval pre-test (FilterSite::kRegionTest) decides OUT and
// partial segments and corners from enclosures; a piece that is exactly
// straight with coordinates in fifths and thirds (not doubles) has legs
// whose orientations the enclosures cannot certify, so its pre-test falls
// back to the exact path, and the answers stay identical.
GTEST_TEST(RegionFilter, AStraightPieceInThirdsFallsBackFromTheRegionPreTest) {
  const std::string scene_json = R"({"name": "flat bottom", "time_step": "1",
    "body": {"dof": 3, "mass": "1", "velocity": ["0", "0", "0"], "boundary": [{"type": "bspline", "degree": 3,
      "knots": ["0", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13", "14", "15", "16", "17", "18"],
      "control_points": [["-2", "1"], ["-11/5", "0"], ["-2", "-1"], ["-1", "-9/5"], ["-1/3", "-9/5"], ["1/3", "-9/5"],
        ["1", "-9/5"], ["2", "-1"], ["11/5", "0"], ["2", "1"], ["1", "9/5"], ["-1", "9/5"], ["-2", "1"], ["-11/5", "0"],
        ["-2", "-1"]]}]},
    "fixels": [{"point": ["-32/15", "0"], "normal": ["1", "0"], "mu": "1/10", "gap": "1/10", "off_boundary": true},
      {"point": ["0", "-2"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/20", "off_boundary": true},
      {"point": ["5/6", "-5/3"], "normal": ["-7/25", "24/25"], "mu": "1/10", "gap": "3/20", "off_boundary": true}],
    "pusher": {"mu": "0"}})";
  const Scene scene = parse_scene(scene_json, "flat bottom");
  const SeatingSet S = seating_set(scene);
  for (const Rational& mu : {Rational(0), Rational(1, 10)}) {
    RegionOptions opt;
    opt.resolution = Rational(1, 64);
    opt.pusher_mu = mu;
    reset_filter_stats();
    const std::string filtered = run(false, [&] { return region_json_of(scene, S, opt); });
    const FilterCounts pre = filter_stats().at(FilterSite::kRegionTest);
    EXPECT_GT(pre.certified, 10) << "mu " << to_string(mu);
    EXPECT_GE(pre.fallbacks, 1) << "mu " << to_string(mu);
    EXPECT_EQ(filtered, run(true, [&] { return region_json_of(scene, S, opt); })) << "mu " << to_string(mu);
  }
}

// The subdivision's lazy pieces: halving enclosures keeps them around the
// exact control points, and the exact points made from the boundary piece
// at depth 12 equal those of twelve exact halvings.
GTEST_TEST(RegionFilter, LazyPiecesEncloseAndEqualRepeatedExactHalving) {
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
    const double x = to_double(exact.control[k].x), y = to_double(exact.control[k].y);
    EXPECT_TRUE(lazy.enclosures()[k].x.inf() <= x && x <= lazy.enclosures()[k].x.sup()) << k;
    EXPECT_TRUE(lazy.enclosures()[k].y.inf() <= y && y <= lazy.enclosures()[k].y.sup()) << k;
  }
  EXPECT_EQ(lazy.u0(), exact.u0);
  EXPECT_EQ(lazy.u1(), exact.u1);
  const BezierPiece& made = lazy.exact();
  for (std::size_t k = 0; k < exact.control.size(); ++k) {
    EXPECT_EQ(made.control[k].x, exact.control[k].x) << k;
    EXPECT_EQ(made.control[k].y, exact.control[k].y) << k;
  }
}

// Rational containment of a double interval: no tolerance.
bool holds(const internal::FI& x, const Rational& q) { return Rational(x.inf()) <= q && q <= Rational(x.sup()); }

// The legs of a lazy piece are halved on their own (de Casteljau on the
// hodograph). At depth 20 of a cubic with non-dyadic control points each
// leg enclosure holds the exact leg of the sub-curve (made in one exact
// restriction, not by halving) and is tight relative to the leg: a
// difference of the point enclosures is about 10^-7 wide relative to a leg
// that short, which left blob32's rays grazing S undecided.
GTEST_TEST(RegionFilter, LegEnclosuresHoldTheExactLegsAndStayTightAtDepthTwenty) {
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
GTEST_TEST(RegionFilter, LegsOfExactlyHalvedPiecesHoldTheExactLegs) {
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

// The enclosure of cos_half_angle_lower rests on a static error bound
// (beside cos_half_bounds). Each certified enclosure, from the directions'
// enclosures, holds the exact answer for the exact directions: random
// pairs at every angle, nearly equal and nearly opposite pairs, and lengths
// from 2^-30 to 2^30. Compared as rationals.
GTEST_TEST(RegionFilter, CosHalfBoundsHoldTheExactLowerCosineOfTheHalfAngle) {
  std::mt19937_64 rng(31);
  std::uniform_int_distribution<int> coord(-1000, 1000), den(1, 997), scale(-30, 30), kind(0, 3);
  auto pow2 = [](int e) { return e >= 0 ? Rational(Integer(1) << e) : Rational(1, Integer(1) << -e); };
  int certified = 0, near_opposite = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Vec2 a{Rational(coord(rng), den(rng)) * pow2(scale(rng)), Rational(coord(rng), den(rng)) * pow2(scale(rng))};
    if (is_zero(a)) continue;
    const Rational s = pow2(scale(rng));
    const Rational eps = Rational(coord(rng), den(rng)) / pow(Integer(10), 1 + trial % 9);
    Vec2 b;
    switch (kind(rng)) {
      case 0:
        b = {Rational(coord(rng), den(rng)), Rational(coord(rng), den(rng))};
        break;
      case 1:  // nearly the same direction
        b = {s * (a.x + eps * a.y), s * (a.y - eps * a.x)};
        break;
      default:  // nearly opposite
        b = {-s * (a.x + eps * a.y), -s * (a.y - eps * a.x)};
        break;
    }
    if (is_zero(b)) continue;
    const Rational c = internal::cos_half_angle_lower(a, b);
    internal::Protect guard;
    internal::FI out;
    if (!internal::cos_half_bounds(internal::to_interval(a), internal::to_interval(b), out)) continue;
    ++certified;
    if (dot(a, b) < 0) ++near_opposite;
    EXPECT_TRUE(holds(out, c)) << "trial " << trial << ": c = " << to_string(c) << " not in [" << out.inf() << ", "
                               << out.sup() << "]";
  }
  EXPECT_GT(certified, 1200) << near_opposite;
  EXPECT_GT(near_opposite, 300) << certified;
}

// G is a union of convex pieces with strict rows: its pre-test needs one
// piece that every ray hits for IN (then the exact path computes the
// magnitudes), and replays misses() piece by piece, LP count included, for
// OUT and partial. Regions of bundled scenes and of random blobs are the
// same JSON as the exact path's, and the pre-test decided segments (it
// decided none before G had one).
GTEST_TEST(RegionFilter, GuaranteedRegionsArePreTestedAndIdenticalJson) {
  std::vector<Scene> scenes;
  for (const char* name : {"example2_rounded", "blob", "polygon", "nonunique_part"})
    scenes.push_back(test::scene_file(name));
  std::mt19937_64 rng(44);
  for (int trial = 0; trial < 4; ++trial) scenes.push_back(test::random_blob_scene(rng));
  int tested = 0;
  for (const Scene& scene : scenes) {
    SeatingSet S;
    try {
      S = seating_set(scene);
    } catch (const Error&) {
      continue;
    }
    const GuaranteedSet G = guaranteed_set(scene, S);
    RegionOptions opt;
    opt.resolution = Rational(1, 1024);
    opt.guaranteed = &G;
    reset_filter_stats();
    const std::string filtered = run(false, [&] { return region_json_of(scene, S, opt); });
    const FilterCounts c = filter_stats().at(FilterSite::kRegionTest);
    EXPECT_GT(c.certified, 0) << scene.name;
    EXPECT_EQ(filtered, run(true, [&] { return region_json_of(scene, S, opt); })) << scene.name;
    ++tested;
  }
  EXPECT_GE(tested, 6);
}

}  // namespace
}  // namespace fixel
