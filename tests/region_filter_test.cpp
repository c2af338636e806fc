// The region's interval pre-test (fixel/internal/region_filter.h): the
// segment and corner tests on enclosures, and the magnitude bounds of IN
// answers; each answer it certifies equals the exact path's, and the
// counters show where it falls back.
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
      const std::vector<internal::LazyPiece> parts = test::halved(piece, 10);
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

// Rational containment of a double interval: no tolerance.
bool holds(const internal::FI& x, const Rational& q) { return Rational(x.inf()) <= q && q <= Rational(x.sup()); }

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
