#include "fixel/design.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>

#include "filter_test_util.h"
#include "fixel/design_search.h"
#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/design_detail.h"
#include "fixel/internal/region_context.h"
#include "fixel/io.h"
#include "fixel/progress.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/scene_json.h"
#include "fixel/sustained.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::scene_file;

// The "house": the rectangle [−1, 1] × [−1, 0] under the roof (1, 0),
// (0, 1), (−1, 0), mirror-symmetric about x = 0. Curve parameters: bottom
// [0, 1], right side [1, 2], right roof [2, 3], left roof [3, 4], left side
// [4, 5]. Area 3, centre of mass (0, −2/9).
Scene house(const std::string& mu = "0") {
  return parse_scene(R"({"name": "house", "time_step": "1",
    "body": {"dof": 3, "mass": "1",
             "boundary": [{"type": "polyline", "points": [["-1","-1"], ["1","-1"], ["1","0"], ["0","1"], ["-1","0"], ["-1","-1"]]}]},
    "fixels": [], "pusher": {"mu": ")" +
                     mu + R"("}})");
}

// B1 = (−1/2, −1), B2 = (1/2, −1) on the bottom, L = (−1, −1/2) on the left
// side, R = (1, −1/2) on the right side.
std::vector<DesignCandidate> house_candidates(const Scene& part) {
  return parse_candidates(part, R"({"candidates": [{"curve": 0, "u": "1/4"}, {"curve": 0, "u": "3/4"},
                                                   {"curve": 0, "u": "9/2"}, {"curve": 0, "u": "3/2"}]})");
}

DesignOptions frictionless(int jobs = 1) {
  DesignOptions o;
  o.mu = 0;
  o.pusher_mu = 0;
  o.resolution = Rational(1, 64);
  o.jobs = jobs;
  o.top = 10;
  return o;
}

GTEST_TEST(Design, CandidatesAreExactBoundaryPointsWithInwardNormals) {
  const Scene part = house();
  const auto c = house_candidates(part);
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0].point.x, Rational(-1, 2));
  EXPECT_EQ(c[0].point.y, Rational(-1));
  EXPECT_EQ(c[2].point.x, Rational(-1));
  EXPECT_EQ(c[2].point.y, Rational(-1, 2));
  // Inward: up from the bottom, +x from the left side, −x from the right side.
  EXPECT_EQ(c[0].normal.x, 0);
  EXPECT_GT(c[0].normal.y, 0);
  EXPECT_GT(c[2].normal.x, 0);
  EXPECT_EQ(c[2].normal.y, 0);
  EXPECT_LT(c[3].normal.x, 0);
}

GTEST_TEST(Design, TriplesAreIndexedLexicographically) {
  EXPECT_EQ(triple_count(2), 0);
  EXPECT_EQ(triple_count(4), 4);
  EXPECT_EQ(triple_count(200), 1313400);
  EXPECT_EQ(triple_count(3000000), 4499995500001000000);  // n(n−1)(n−2)/6, by hand
  EXPECT_THROW(triple_count(5000000), InputError);        // 2.08·10¹⁹ is beyond a long (it wrapped)
  const long n = 7;
  long index = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const auto t = triple_at(n, index++);
        EXPECT_EQ(t, (std::array<int, 3>{i, j, k}));
      }
  EXPECT_EQ(index, triple_count(n));
  EXPECT_THROW(triple_at(n, index), InputError);
}

// By hand: L and R push along one line through the centre of mass in
// opposite directions, so {B, L, R} has a singular W_n; {B1, B2, L} and
// {B1, B2, R} are mirror images, so their scores are equal and the tie
// keeps the lexicographic order. For {B1, B2, L} (W_n columns (0, 1, −1/2),
// (0, 1, 1/2), (1, 0, 5/18)), a frictionless push −w = λ·W_n needs d_x < 0
// and d_y < 0: only the right roof (d = (−1, −1)) at u = 2 + t, where
// λ = (2t, 1 − 2t, 1): IN exactly for t in (0, 1/2). With μ = 0 the jam
// cones are faces of cone(W_n), so J is the whole open cone. At resolution
// 1/64 the cells touching t = 0 (the corner, where λ₁ = 0) and t = 1/2
// (where λ₂ = 0) hold a point outside the open cone, so they are partial
// and IN is t in [1/64, 31/64], 15/32 of a unit of parameter out of the
// outline's 5: the score is 3/32.
GTEST_TEST(Design, TheHousesBestLayoutsAreTheMirrorPairInCandidateOrder) {
  const Scene part = house();
  const DesignOptions o = frictionless();
  const DesignResult r = design(part, house_candidates(part), o);
  EXPECT_EQ(r.stats.triples, 4);
  EXPECT_EQ(r.stats.singular, 2);
  EXPECT_EQ(r.stats.no_form_closure, 0);
  EXPECT_EQ(r.stats.j_empty, 0);
  EXPECT_EQ(r.stats.regions, 2);
  ASSERT_EQ(r.layouts.size(), 2u);
  EXPECT_EQ(r.layouts[0].fixels, (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(r.layouts[1].fixels, (std::array<int, 3>{0, 1, 3}));
  EXPECT_EQ(r.layouts[0].score, r.layouts[1].score);
  EXPECT_EQ(o.resolution, Rational(1, 64));
  EXPECT_EQ(r.layouts[0].score, Rational(3, 32));
  EXPECT_EQ(r.layouts[0].sustained_empty, std::optional<bool>(false));
  ASSERT_TRUE(r.layouts[0].step_score.has_value());  // completed for the reported layouts
}

// By hand, on the square [−1, 1]² with B1 = (−1/2, −1), B2 = (1/2, −1),
// L = (−1, 0), R = (1, 0): {B, L, R} is singular (L and R push along one line
// through the centre), and {B1, B2, L} needs a push with d_x < 0 and d_y < 0,
// which no flat edge gives a frictionless finger (its push is along ±x or
// ±y) and no corner gives for its whole fan (the fan holds an edge normal);
// {B1, B2, R} is its mirror image. So every triple is dropped.
GTEST_TEST(Design, TheSquaresAxisAlignedLayoutsHaveNoFormClosureWithAFinger) {
  const Scene part = parse_scene(R"({"name": "square", "time_step": "1",
    "body": {"dof": 3, "mass": "1",
             "boundary": [{"type": "polyline", "points": [["-1","-1"], ["1","-1"], ["1","1"], ["-1","1"], ["-1","-1"]]}]},
    "fixels": []})");
  const auto c = parse_candidates(part, R"({"candidates": [{"curve": 0, "u": "1/4"}, {"curve": 0, "u": "3/4"},
                                                          {"curve": 0, "u": "7/2"}, {"curve": 0, "u": "3/2"}]})");
  const DesignResult r = design(part, c, frictionless());
  EXPECT_EQ(r.stats.singular, 2);
  EXPECT_EQ(r.stats.no_form_closure, 2);
  EXPECT_TRUE(r.layouts.empty());
  EXPECT_EQ(r.no_layout, "every one of the 4 triples was dropped (2 with W_n singular, 2 without form closure)");
}

// A pentagon with three candidates whose triple has no form closure with a
// finger (tests below), its options (μ 1/10, gap 1/20, resolution 1/256),
// and the same three fixels written by hand: on the bottom edge, up; on the
// edge (4,0)-(7,4), (-4, 3)/5; on the edge (3,7)-(0,3), (4, -3)/5.
const char* const kPentagonOutline =
    R"("boundary": [{"type": "polyline", "points": [["0","0"],["4","0"],["7","4"],["3","7"],["0","3"],["0","0"]]}])";

Scene pentagon(const std::string& fixels = "") {
  return parse_scene(R"({"name": "pent", "time_step": "1", "body": {"dof": 3, "mass": "1", )" +
                     std::string(kPentagonOutline) + R"(}, "fixels": [)" + fixels + R"(], "pusher": {"mu": "0"}})");
}

std::vector<DesignCandidate> pentagon_candidates(const Scene& part) {
  return parse_candidates(part, R"({"candidates": [{"curve": 0, "u": "117/1024"},
      {"curve": 0, "u": "1425/1024"}, {"curve": 0, "u": "1839/512"}]})");
}

DesignOptions pentagon_options() {
  DesignOptions o = frictionless();
  o.mu = Rational(1, 10);
  o.resolution = Rational(1, 256);
  o.gap = Rational(1, 20);
  return o;
}

const char* const kPentagonFixelsByHand =
    R"({"point": ["117/256","0"], "normal": ["0","1"], "mu": "1/10", "gap": "1/20"},
       {"point": ["5299/1024","401/256"], "normal": ["-4/5","3/5"], "mu": "1/10", "gap": "1/20"},
       {"point": ["627/512","593/128"], "normal": ["4/5","-3/5"], "mu": "1/10", "gap": "1/20"})";

// The one-step model needs no form closure: ranked by it, a pentagon's
// triple without form closure (it was dropped) is scored, with the fraction
// a region of the scene with those fixels gives: 119/320 at 1/256 (the
// reviewer's case), so more than 0.
GTEST_TEST(Design, RankedByTheOneStepPushATripleWithoutFormClosureIsScoredAsItsRegion) {
  const Scene part = pentagon();
  const auto c = pentagon_candidates(part);
  DesignOptions o = pentagon_options();
  DesignOptions sustained = o;
  EXPECT_EQ(design(part, c, sustained).stats.no_form_closure, 1);  // the sustained ranking drops it
  o.push = DesignPush::kStep;
  const DesignResult r = design(part, c, o);
  EXPECT_EQ(r.stats.no_form_closure, 0);
  ASSERT_EQ(r.layouts.size(), 1u);
  const Scene scene = pentagon(kPentagonFixelsByHand);
  RegionOptions ro;
  ro.resolution = o.resolution;
  Rational in_length = 0;
  for (const auto& i : compute_region(scene, seating_set(scene), ro).intervals)
    if (i.status == RegionStatus::kIn) in_length += i.u1 - i.u0;
  ASSERT_TRUE(r.layouts[0].step_score.has_value());
  EXPECT_EQ(*r.layouts[0].step_score, in_length / 5);
  EXPECT_EQ(*r.layouts[0].step_score, Rational(119, 320));
}

// The one-step ranking takes one μ: an interval is refused naming the
// option's field, in the library's words (the message named the CLI's
// "--push step").
GTEST_TEST(Design, TheOneStepRankingRefusesAFrictionIntervalNamingIt) {
  const Scene part = pentagon();
  DesignOptions o = pentagon_options();
  o.push = DesignPush::kStep;
  o.mu_hi = o.mu + Rational(1, 10);
  try {
    design(part, pentagon_candidates(part), o);
    ADD_FAILURE() << "no UnsupportedError";
  } catch (const UnsupportedError& e) {
    EXPECT_EQ(e.field(), "DesignOptions.mu");
    EXPECT_EQ(e.value(), to_string(o.mu) + "," + to_string(*o.mu_hi));
    EXPECT_EQ(std::string(e.what()),
              "DesignOptions.mu: " + e.value() + " is an interval: the one-step ranking (push step) needs one value");
  }
}

bool same(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
// The same pentagon layout through design_scene: field for field the scene
// written by hand above, and its region gives the one-step score again.
GTEST_TEST(Design, AOneStepLayoutAsASceneIsTheSceneWrittenByHand) {
  const Scene part = pentagon();
  const auto c = pentagon_candidates(part);
  DesignOptions o = pentagon_options();
  o.push = DesignPush::kStep;
  const DesignResult r = design(part, c, o);
  ASSERT_EQ(r.layouts.size(), 1u);
  double angle_error = -1;
  const Scene scene = design_scene(part, r.candidates, r.layouts[0], 1, o, &angle_error);
  EXPECT_EQ(angle_error, 0);
  const Scene by_hand = pentagon(kPentagonFixelsByHand);
  ASSERT_EQ(scene.fixels.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(same(scene.fixels[i].p_AoF_A, by_hand.fixels[i].p_AoF_A)) << i;
    EXPECT_TRUE(same(scene.fixels[i].n_A, by_hand.fixels[i].n_A)) << i;
    EXPECT_EQ(scene.fixels[i].mu, by_hand.fixels[i].mu) << i;
    EXPECT_EQ(scene.fixels[i].gap, by_hand.fixels[i].gap) << i;
    EXPECT_FALSE(scene.fixels[i].off_boundary) << i;
  }
  EXPECT_EQ(scene.name, "pent-layout-1");
  EXPECT_NE(scene.description.find("score 119/320"), std::string::npos) << scene.description;
  // Written and read back as a file would be, then analysed on its own.
  const Scene read = parse_scene(write_scene(scene));
  RegionOptions ro;
  ro.resolution = o.resolution;
  Rational in_length = 0;
  for (const auto& i : compute_region(read, seating_set(read), ro).intervals)
    if (i.status == RegionStatus::kIn) in_length += i.u1 - i.u0;
  EXPECT_EQ(in_length / 5, Rational(119, 320));
}

// On the house every candidate normal has rational length (axis-aligned),
// so the scene is the exact fixture; its sustained region, computed on its
// own from the written file, is the sustained score.
GTEST_TEST(Design, ASustainedLayoutAsASceneReproducesItsScoreThroughTheRegion) {
  const Scene part = house("1/10");
  DesignOptions o = frictionless();
  o.mu = Rational(1, 20);
  o.mu_hi = Rational(1, 10);
  o.pusher_mu = Rational(1, 50);
  const DesignResult r = design(part, house_candidates(part), o);
  ASSERT_FALSE(r.layouts.empty());
  const Scene scene = parse_scene(write_scene(design_scene(part, r.candidates, r.layouts[0], 1, o)));
  ASSERT_EQ(scene.fixels.size(), 3u);
  for (const Fixel& f : scene.fixels) {
    EXPECT_FALSE(f.off_boundary);
    EXPECT_EQ(f.gap, 0);
    EXPECT_EQ(f.mu, Rational(1, 20));
    EXPECT_EQ(f.mu_hi, std::optional<Rational>(Rational(1, 10)));
  }
  EXPECT_EQ(scene.pusher_mu, Rational(1, 50));
  RegionOptions ro;
  ro.resolution = o.resolution;
  Rational in_length = 0;
  for (const auto& i : compute_region(scene, *sustained_target(sustained_set(scene)), ro).intervals)
    if (i.status == RegionStatus::kIn) in_length += i.u1 - i.u0;
  ASSERT_TRUE(r.layouts[0].sustained_score.has_value());
  EXPECT_EQ(in_length / 5, *r.layouts[0].sustained_score);
  EXPECT_GT(in_length, 0);
}

// A normal of irrational length (the roof's (−1, −1) direction) is rounded
// and the fixel marked off_boundary, so the written scene still reads; a
// rank below 1 and a candidate index out of range are refused.
GTEST_TEST(Design, ALayoutWithAnIrrationalNormalIsRoundedAndMarkedOffBoundary) {
  const Scene part = house();
  const auto c = parse_candidates(part, R"({"candidates": [{"curve": 0, "u": "1/4"}, {"curve": 0, "u": "3/4"},
                                                           {"curve": 0, "u": "5/2"}]})");
  DesignStats stats;
  const auto scored = design_batch(part, c, frictionless(), 0, 1, stats);  // the one triple {0, 1, 2}
  ASSERT_EQ(scored.size(), 1u);
  DesignLayout layout = scored[0];
  layout.score = Rational(1, 7);  // not its score: refused (the description would state it)
  EXPECT_THROW(design_scene(part, c, layout, 3, frictionless()), InputError);
  layout.score = scored[0].score;
  double angle_error = 0;
  const Scene scene = design_scene(part, c, layout, 3, frictionless(), &angle_error);
  EXPECT_FALSE(scene.fixels[0].off_boundary);
  EXPECT_FALSE(scene.fixels[1].off_boundary);
  EXPECT_TRUE(scene.fixels[2].off_boundary);
  EXPECT_GT(angle_error, 0);
  EXPECT_LT(angle_error, 1e-7);  // cli.md: "within about 10⁻⁷ rad" (t rounded to 2⁻²⁴: at most 6e-8)
  EXPECT_EQ(scene.fixels[2].n_A.x * scene.fixels[2].n_A.x + scene.fixels[2].n_A.y * scene.fixels[2].n_A.y, 1);
  EXPECT_EQ(scene.name, "house-layout-3");
  EXPECT_NE(scene.description.find("fixel 2 has irrational length"), std::string::npos) << scene.description;
  EXPECT_NO_THROW(parse_scene(write_scene(scene)));
  EXPECT_THROW(design_scene(part, c, layout, 0, frictionless()), InputError);
  layout.fixels = {0, 1, 3};
  try {
    design_scene(part, c, layout, 1, frictionless());
    ADD_FAILURE() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("layout"), std::string::npos) << e.what();
  }
}

GTEST_TEST(Design, FrictionShrinksTheScoreButKeepsTheMirrorTie) {
  const Scene part = house();
  DesignOptions o = frictionless();
  const Rational frictionless_score = design(part, house_candidates(part), o).layouts[0].score;
  o.mu = Rational(1, 10);
  const DesignResult r = design(part, house_candidates(part), o);
  ASSERT_EQ(r.layouts.size(), 2u);
  EXPECT_EQ(r.layouts[0].score, r.layouts[1].score);
  // J(μ) shrinks as μ grows (docs/theory.md §10.4); here strictly, and the
  // tie is between scores that are not 0.
  EXPECT_GT(r.layouts[0].score, 0);
  EXPECT_LT(r.layouts[0].score, frictionless_score);
}

// A pusher friction interval is judged at its upper end, and a layout's
// scene keeps the whole interval (it was written as the upper end alone).
GTEST_TEST(Design, APusherFrictionIntervalIsJudgedAtItsUpperEndAndKeptInTheLayoutsScene) {
  const Scene part = house();
  DesignOptions upper = frictionless();
  upper.pusher_mu = Rational(1, 10);
  DesignOptions ranged = upper;
  ranged.pusher_mu_lo = Rational(1, 20);
  const DesignResult a = design(part, house_candidates(part), ranged), b = design(part, house_candidates(part), upper);
  ASSERT_EQ(a.layouts.size(), b.layouts.size());
  for (std::size_t k = 0; k < a.layouts.size(); ++k) EXPECT_EQ(a.layouts[k].score, b.layouts[k].score);
  ASSERT_FALSE(a.layouts.empty());
  const Scene scene = design_scene(part, a.candidates, a.layouts[0], 1, ranged);
  EXPECT_EQ(scene.pusher_mu, Rational(1, 20));
  EXPECT_EQ(scene.pusher_mu_hi, std::optional<Rational>(Rational(1, 10)));
  EXPECT_FALSE(design_scene(part, b.candidates, b.layouts[0], 1, upper).pusher_mu_hi.has_value());
  ranged.pusher_mu_lo = Rational(1, 5);  // above the upper end
  EXPECT_THROW(design(part, house_candidates(part), ranged), InputError);
}

GTEST_TEST(Design, TheRankingIsTheSameWithOneAndTwoThreads) {
  const Scene part = scene_file("polygon");
  const auto cands = boundary_candidates(part, std::nullopt);
  std::vector<DesignCandidate> few(cands.begin(), cands.begin() + 9);  // 84 triples
  DesignOptions o;
  o.resolution = Rational(1, 32);
  o.top = 84;
  o.jobs = 1;
  const DesignResult one = design(part, few, o);
  o.jobs = 2;
  const DesignResult two = design(part, few, o);
  EXPECT_EQ(two.stats.jobs, 2);
  ASSERT_EQ(one.layouts.size(), two.layouts.size());
  ASSERT_FALSE(one.layouts.empty());
  for (std::size_t k = 0; k < one.layouts.size(); ++k) {
    EXPECT_EQ(one.layouts[k].fixels, two.layouts[k].fixels);
    EXPECT_EQ(one.layouts[k].score, two.layouts[k].score);
  }
  EXPECT_EQ(one.stats.singular, two.stats.singular);
  EXPECT_EQ(one.stats.no_form_closure, two.stats.no_form_closure);
  EXPECT_EQ(one.stats.j_empty, two.stats.j_empty);
  EXPECT_EQ(one.stats.bounded, two.stats.bounded);
  // Every triple is accounted for exactly once.
  EXPECT_EQ(one.stats.singular + one.stats.no_form_closure + one.stats.j_empty + one.stats.regions + one.stats.bounded,
            one.stats.triples);
}

GTEST_TEST(Design, BatchesMergeToTheWholeRun) {
  const Scene part = scene_file("polygon");
  const auto all = boundary_candidates(part, std::nullopt);
  std::vector<DesignCandidate> few(all.begin(), all.begin() + 8);  // 56 triples
  DesignOptions o;
  o.resolution = Rational(1, 32);
  o.top = 5;
  o.jobs = 1;
  o.bound = false;  // batches score every triple, as this run then does
  const DesignResult whole = design(part, few, o);
  std::vector<DesignLayout> merged;
  DesignStats stats;
  for (long first = 0; first < 56; first += 20)
    for (auto& l : design_batch(part, few, o, first, std::min(20L, 56 - first), stats)) merged.push_back(l);
  rank_layouts(merged, o.top);
  ASSERT_EQ(merged.size(), whole.layouts.size());
  for (std::size_t k = 0; k < merged.size(); ++k) {
    EXPECT_EQ(merged[k].fixels, whole.layouts[k].fixels);
    EXPECT_EQ(merged[k].score, whole.layouts[k].score);
  }
  EXPECT_EQ(stats.pruned(), whole.stats.pruned());
}

GTEST_TEST(Design, TheFormClosureRegionIsTheExactOneAndMostlyPreTested) {
  // The form-closure filter's target on the blob (curved pieces) for three
  // of its boundary candidates as fixels: the region JSON is the forced
  // exact path's, and its interval pre-test decides most tests.
  const Scene blob = scene_file("blob");
  const std::vector<DesignCandidate> c = boundary_candidates(blob, std::nullopt);
  ASSERT_GE(c.size(), 24u);
  int with_in = 0;
  for (const std::array<std::size_t, 3> f : {std::array<std::size_t, 3>{0, 8, 16}, {2, 9, 19}, {1, 12, 13}}) {
    std::array<VectorQ, 3> Wn;
    for (int i = 0; i < 3; ++i) Wn[i] = contact_wrench(sub(c[f[i]].point, blob.body.p_AoCm_A), c[f[i]].normal, 3);
    const auto target = internal::form_closure_target(Wn);
    ASSERT_TRUE(target);
    RegionOptions opt;
    opt.resolution = Rational(1, 1024);
    reset_filter_stats();
    const std::string filtered =
        test::run(false, [&] { return test::masked(region_json(blob, compute_region(blob, *target, opt))); });
    const FilterCounts pre = filter_stats().at(FilterSite::kRegionTest);
    EXPECT_EQ(filtered,
              test::run(true, [&] { return test::masked(region_json(blob, compute_region(blob, *target, opt))); }));
    EXPECT_GT(pre.certified, 20 * pre.fallbacks) << pre.certified << " / " << pre.fallbacks;
    with_in += filtered.find("\"status\": \"in\"") != std::string::npos;
  }
  EXPECT_GE(with_in, 1);  // some point of some layout is in form closure
}

// Design asks the form-closure filter only whether some interval of its
// region is not OUT (internal::region_reaches, which stops at the first):
// on 60 of the blob's triples it is the whole region's answer, and both
// answers occur.
GTEST_TEST(Design, TheFormClosureFilterStopsAtItsFirstReachWithTheWholeRegionsAnswer) {
  const Scene blob = scene_file("blob");
  const std::vector<DesignCandidate> c = boundary_candidates(blob, std::nullopt);
  const long n = static_cast<long>(c.size());
  int closure = 0, none = 0;
  for (long index = 0; index < triple_count(n) && closure + none < 60; index += 31) {
    const std::array<int, 3> f = triple_at(n, index);
    std::array<VectorQ, 3> Wn;
    for (int i = 0; i < 3; ++i) Wn[i] = contact_wrench(sub(c[f[i]].point, blob.body.p_AoCm_A), c[f[i]].normal, 3);
    const auto target = internal::form_closure_target(Wn);
    if (!target) continue;
    RegionOptions opt;
    opt.resolution = Rational(1, 256);
    opt.pusher_mu = Rational(0);
    bool whole = false;
    for (const auto& iv : compute_region(blob, *target, opt).intervals)
      whole = whole || iv.status != RegionStatus::kOut;
    EXPECT_EQ(internal::region_reaches(blob, *target, opt), whole) << "triple " << index;
    (whole ? closure : none) += 1;
  }
  EXPECT_GE(closure, 10);
  EXPECT_GE(none, 1);
}

GTEST_TEST(Design, FewerThanThreeCandidatesIsNoLayoutWithAReason) {
  const Scene part = house();
  auto c = house_candidates(part);
  c.resize(2);
  const DesignResult r = design(part, c, frictionless());
  EXPECT_TRUE(r.layouts.empty());
  EXPECT_NE(r.no_layout.find("only 2 candidates"), std::string::npos) << r.no_layout;
}

// The polygon is one polyline with its corners at u = 0, 1, ..., 5 and a
// perimeter of 5/2 + 3/2 + √41/4 + √41/4 + 3/2 = 11/2 + √41/2 ≈ 8.70 m:
// spacing 1/2 puts the candidates at arc lengths 1/4, 3/4, ... below it,
// (k + 1/2)/2 < 8.70 for k = 0..16: 17 of them, none at a corner.
GTEST_TEST(Design, BoundaryCandidatesAvoidCornersAndFollowTheSpacing) {
  const Scene part = scene_file("polygon");
  const auto c = boundary_candidates(part, Rational(1, 2));
  EXPECT_EQ(c.size(), 17u);
  for (const auto& d : c) {
    EXPECT_FALSE(is_zero(d.normal));
    EXPECT_NE(boost::multiprecision::denominator(d.u), 1) << "a candidate at the corner u = " << d.u;
  }
  // The first lies 1/4 m along the bottom edge from (−1, −1): u = 1/4 ÷ 5/2
  // = 1/10, rounded to 1/1024 (placement only).
  EXPECT_EQ(c[0].point.y, -1);
  EXPECT_EQ(c[0].u, Rational(102, 1024));
  const auto d24 = boundary_candidates(part, std::nullopt);
  EXPECT_LE(d24.size(), 24u);
  EXPECT_GE(d24.size(), 20u);
  const auto blob = boundary_candidates(scene_file("blob"), std::nullopt);
  EXPECT_EQ(blob.size(), 24u);  // a smooth outline has no corner to skip
}

// The house's bottom runs over u in [0, 1] of its one polyline curve, so
// u = 1/4 given twice, or as "0.25", is one boundary point.
GTEST_TEST(Design, TwoCandidatesAtOneBoundaryPointAreRefusedNamingTheLater) {
  const Scene part = house();
  for (const char* text : {R"({"candidates": [{"curve": 0, "u": "1/4"}, {"curve": 0, "u": "3/4"},
                                               {"curve": 0, "u": "1/4"}]})",
                           R"({"candidates": [{"curve": 0, "u": "1/4"}, {"curve": 0, "u": "3/4"},
                                               {"curve": 0, "u": "0.25"}]})"}) {
    try {
      parse_candidates(part, text);
      FAIL() << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "candidates[2]");
      EXPECT_NE(std::string(e.what()).find("same boundary point as candidates[0]"), std::string::npos) << e.what();
    }
  }
  // Distinct points pass, and check_candidate_list alone says the same.
  auto distinct = house_candidates(part);
  EXPECT_NO_THROW(check_candidate_list(distinct));
  distinct.push_back(distinct[1]);
  EXPECT_THROW(check_candidate_list(distinct), InputError);
  std::vector<DesignCandidate> many(10001, distinct[0]);
  try {
    check_candidate_list(many);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "candidates");  // the count first, before any comparison
  }
}

GTEST_TEST(Design, AMissingCandidateFileSaysWhyAndADirectoryIsNamed) {
  const Scene part = house();
  const std::string missing = std::string(FIXEL_SOURCE_DIR) + "/data/no_such_candidates.json";
  try {
    load_candidates(part, missing);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), missing);
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
  try {
    load_candidates(part, std::string(FIXEL_SOURCE_DIR) + "/data");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
}

GTEST_TEST(Design, BadInputNamesTheFieldAndValue) {
  const Scene part = house();
  try {
    boundary_candidates(part, Rational(0));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "boundary_candidates(spacing)");
    EXPECT_EQ(e.value(), "0");
  }
  try {
    parse_candidates(part, R"({"candidates": [{"curve": 0, "u": "6"}]})");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "candidates[0].u");
    EXPECT_EQ(e.value(), "6");
  }
  try {
    parse_candidates(part, R"({"candidates": [{"curve": 0, "u": "1/4"}, {"curve": 3, "u": "0"}]})");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "candidates[1].curve");
  }
  try {
    parse_candidates(part, R"({"candidates": [{"curve": 0, "u": "2"}]})");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "candidates[0].u");
    EXPECT_NE(std::string(e.what()).find("corner"), std::string::npos);
  }
  DesignOptions o = frictionless();
  o.top = 0;
  try {
    design(part, house_candidates(part), o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "DesignOptions.top");
    EXPECT_EQ(e.value(), "0");
  }
  const Scene no_outline = scene_file("example2");
  EXPECT_THROW(boundary_candidates(no_outline, std::nullopt), SceneError);
  EXPECT_THROW(design(no_outline, {}, frictionless()), SceneError);
}

// Candidates made for another part (or edited) were scored as if on this
// one; a bad index into the list threw std::out_of_range.
GTEST_TEST(Design, AnotherPartsCandidatesAndABadIndexAreInputErrorsNamingTheEntry) {
  const Scene part = house();
  auto moved = house_candidates(part);
  moved[2].point.x += Rational(1, 8);
  try {
    design(part, moved, frictionless());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "candidates[2]");
    EXPECT_EQ(e.value(), "curve 0, u = 9/2");
  }
  auto twice = house_candidates(part);
  twice.push_back(twice[0]);
  EXPECT_THROW(design(part, twice, frictionless()), InputError);  // the list's own check
  try {
    layout_scene(part, house_candidates(part), {0, 1, 4}, frictionless(), false);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "layout[2]");
    EXPECT_EQ(e.value(), "4");
  }
  EXPECT_THROW(layout_region(part, house_candidates(part), {-1, 1, 2}, frictionless()), InputError);
  EXPECT_FALSE(design(part, house_candidates(part), frictionless()).layouts.empty());  // the same list, unedited
}

// design() checked the whole list, but the entry points that take a layout
// (design_batch, design_scene, layout_region) scored another part's
// candidates, and a layout could put two fixels at one point.
GTEST_TEST(Design, EveryEntryPointThatTakesALayoutRefusesAnotherPartsCandidateOrARepeatedPoint) {
  const Scene part = house();
  auto moved = house_candidates(part);
  moved[1].normal.y += 1;
  const DesignOptions o = frictionless();
  const auto expect_moved = [](const std::function<void()>& run) {
    try {
      run();
      FAIL() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "candidates[1]");
      EXPECT_NE(std::string(e.what()).find("not this part's candidate"), std::string::npos);
    }
  };
  DesignStats stats;
  expect_moved([&] { design_batch(part, moved, o, 0, triple_count(static_cast<long>(moved.size())), stats); });
  expect_moved([&] { design_batch(part, moved, o, std::vector<long>{0}, stats); });  // triple {0, 1, 2}
  DesignLayout layout;
  layout.fixels = {0, 1, 2};
  expect_moved([&] { design_scene(part, moved, layout, 1, o); });
  expect_moved([&] { layout_region(part, moved, {0, 1, 2}, o); });
  // The sustained filter reads every candidate: a batch whose triples do not
  // use candidate 1 is refused too, and so is a search.
  const long n = static_cast<long>(moved.size());
  expect_moved([&] { design_batch(part, moved, o, std::vector<long>{triple_count(n) - 1}, stats); });
  expect_moved([&] { DesignSearch search(part, moved, o); });
  EXPECT_NO_THROW(design_batch(part, house_candidates(part), o, std::vector<long>{triple_count(n) - 1}, stats));
  auto same = house_candidates(part);
  try {
    layout_scene(part, same, {0, 2, 0}, o, false);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "layout[2]");
    EXPECT_EQ(e.value(), "0");
    EXPECT_NE(std::string(e.what()).find("second fixel"), std::string::npos);
  }
  EXPECT_NO_THROW(layout_scene(part, same, {0, 2, 3}, o, false));
}

// design_scene wrote another part's (or run's) score into the scene's
// description: the layout is scored again, and complete_layouts threw
// nothing for another part's candidates (each layout got a note instead).
GTEST_TEST(Design, DesignSceneRefusesALayoutWhoseScoreIsNotItsScoreOnThisPart) {
  const Scene polygon = scene_file("polygon"), fig6 = scene_file("fig6");
  DesignOptions o;
  o.resolution = Rational(1, 32);
  o.top = 1;
  const auto poly_cands = boundary_candidates(polygon, std::nullopt);
  const DesignResult r = design(polygon, poly_cands, o);
  ASSERT_EQ(r.layouts.size(), 1u);
  ASSERT_GT(r.layouts[0].score, 0);
  EXPECT_NO_THROW(design_scene(polygon, poly_cands, r.layouts[0], 1, o));  // its own part and options
  const auto fig6_cands = boundary_candidates(fig6, std::nullopt);
  try {
    design_scene(fig6, fig6_cands, r.layouts[0], 1, o);  // valid fig6 candidates, the polygon's score
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "layout.score");
    EXPECT_EQ(e.value(), to_string(r.layouts[0].score));
  }
  DesignOptions finer = o;
  finer.mu = o.mu + Rational(1, 10);  // another run's options: another score
  EXPECT_THROW(design_scene(polygon, poly_cands, r.layouts[0], 1, finer), InputError);
  auto layouts = r.layouts;
  auto moved = poly_cands;
  moved[static_cast<std::size_t>(layouts[0].fixels[0])].normal.x += 1;
  EXPECT_THROW(complete_layouts(polygon, moved, o, layouts), InputError);
}

// curved_contacts counted a contact at a join of a straight and a curved
// piece by the curve that named it: 0 as the end of edge 0, 1 as the start
// of curve 1. example2_rounded's outline: polyline edges (curves 0, 2, 4,
// 6) and cubic corners (curves 1, 3, 5, 7), each over u in [0, 1].
GTEST_TEST(Design, AContactAtAStraightCurvedJoinCountsAsCurvedWhicheverCurveNamesIt) {
  const Scene part = scene_file("example2_rounded");
  const DesignCandidate end0 = candidate_at(part, 0, Rational(1), "a"),
                        start1 = candidate_at(part, 1, Rational(0), "b");
  ASSERT_EQ(end0.point.x, start1.point.x);
  ASSERT_EQ(end0.point.y, start1.point.y);
  const DesignCandidate edge0 = candidate_at(part, 0, Rational(1, 2), "c"),
                        edge2 = candidate_at(part, 2, Rational(1, 2), "d"),
                        edge4 = candidate_at(part, 4, Rational(1, 2), "e"),
                        corner3 = candidate_at(part, 3, Rational(1, 2), "f");
  EXPECT_EQ(internal::curved_contacts(part, {end0, edge2, edge4}, {0, 1, 2}), 1);
  EXPECT_EQ(internal::curved_contacts(part, {start1, edge2, edge4}, {0, 1, 2}), 1);
  EXPECT_EQ(internal::curved_contacts(part, {edge0, edge2, edge4}, {0, 1, 2}), 0);
  EXPECT_EQ(internal::curved_contacts(part, {edge0, corner3, start1}, {0, 1, 2}), 2);
}

GTEST_TEST(Design, AStoppedRunThrowsStoppedError) {
  const Scene part = scene_file("polygon");
  DesignOptions o;
  o.resolution = Rational(1, 32);
  RunControl control;
  control.cancel = true;
  o.control = &control;
  EXPECT_THROW(design(part, boundary_candidates(part, std::nullopt), o), StoppedError);
}

// The design search polls between layouts only: a ControlScope around it
// does not reach the layouts' own exact steps (their J polls it, as the
// check below shows), so a stop names the layouts done.
GTEST_TEST(Design, AControlScopeAroundTheSearchDoesNotStopItsLayouts) {
  const Scene part = scene_file("polygon");
  const auto cands = boundary_candidates(part, std::nullopt);
  const std::vector<DesignCandidate> few(cands.begin(), cands.begin() + 9);  // 84 triples
  DesignOptions o;
  o.resolution = Rational(1, 32);
  o.jobs = 1;
  const DesignResult free = design(part, few, o);
  ASSERT_GT(free.stats.regions, 0);  // some layout's J was built
  const test::CancelledControl cancelled;
  const ControlScope scope(&cancelled.control);
  EXPECT_THROW(sustained_set(part), StoppedError);
  const DesignResult scoped = design(part, few, o);
  EXPECT_EQ(scoped.stats.regions, free.stats.regions);
  ASSERT_EQ(scoped.layouts.size(), free.layouts.size());
  for (std::size_t k = 0; k < free.layouts.size(); ++k) EXPECT_EQ(scoped.layouts[k].score, free.layouts[k].score);
}
}  // namespace
}  // namespace fixel
