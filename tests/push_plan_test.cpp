// plan_push (fixel push-plan): its run control, and its J′ statuses.
#include "fixel/push_plan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>

#include "fixel/geometry.h"
#include "fixel/guaranteed.h"
#include "fixel/io.h"
#include "fixel/progress.h"
#include "fixel/region_target.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "test_util.h"

namespace fixel {
namespace {

Scene blob() { return load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/blob.json"); }

// The plan's exact steps poll its control (a ControlScope), not only G's
// modes and the outcome enumeration: a cancelled plan stops at its first
// exact step, with or without G, and names that step.
GTEST_TEST(PushPlan, ACancelledControlStopsThePlanAtItsFirstExactStep) {
  const Scene scene = blob();
  test::CancelledControl cancelled;
  for (const bool with_guaranteed : {true, false}) {
    const std::string message =
        test::stop_message([&] { plan_push(scene, 0, Rational(10), with_guaranteed, &cancelled.control); });
    // blob's outline is B-splines: the first exact step evaluates one, and the
    // message names that innermost step.
    EXPECT_EQ(message, "a B-spline's Bezier pieces: interrupted after 0 exact steps; no result") << with_guaranteed;
  }
}

GTEST_TEST(PushPlan, AControlThatDoesNotStopChangesNothing) {
  const Scene scene = blob();
  RunControl control;
  const PushPlan with = plan_push(scene, 0, Rational(10), true, &control);
  const PushPlan without = plan_push(scene, 0, Rational(10), true);
  EXPECT_EQ(push_plan_json(scene, with), push_plan_json(scene, without));
  ASSERT_TRUE(with.sample_impulse.has_value());  // so the enumeration ran and was polled
}

// Along the polygon's outline (every 1/16 of its parameter): J′ ⊆ J; J′'s
// point status is that of the region against J′ wherever a stretch of it
// holds the point inside (the region decides whole stretches by cones, the
// plan one push); and J′ drops pushes J keeps, so the check is not vacuous.
// Exact membership of the world-frame wrench is checked in
// approach_target_test.cpp, on parts with rational seat rotations.
GTEST_TEST(PushPlan, JPrimeStatusesAreInsideJAndAgreeWithTheJPrimeRegion) {
  const Scene scene = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/polygon.json");
  const ApproachSet A = approach_set(scene, sustained_set(scene));
  RegionOptions options;
  options.resolution = Rational(1, 256);
  const Region region = compute_region(scene, *approach_target(A), options);
  const Curve& curve = scene.body.boundary->curves[0];
  int in = 0, cut = 0, corners = 0, compared = 0;
  for (Rational u = curve.u_begin(); u <= curve.u_end(); u += Rational(1, 16)) {
    const PushPlan plan = plan_push(scene, 0, u, false);
    ASSERT_TRUE(plan.in_J.has_value() && plan.in_J_approach.has_value()) << to_string(u) << plan.J_approach_note;
    const RegionStatus j = *plan.in_J, jp = *plan.in_J_approach;
    corners += plan.corner;
    if (jp == RegionStatus::kIn) {
      EXPECT_EQ(j, RegionStatus::kIn) << to_string(u);
    }
    if (j == RegionStatus::kOut) {  // J' ⊆ J, at smooth points and at corners (IN = the whole fan)
      EXPECT_EQ(jp, RegionStatus::kOut) << to_string(u);
    }
    in += jp == RegionStatus::kIn;
    cut += j == RegionStatus::kIn && jp == RegionStatus::kOut;
    for (const auto& r : region.intervals)
      if (r.u0 < u && u < r.u1 && r.status != RegionStatus::kPartial) {
        EXPECT_EQ(jp, r.status) << to_string(u);
        ++compared;
      }
  }
  EXPECT_EQ(corners, 6);  // the pentagon's five vertices, its first at both ends of the range
  EXPECT_GT(in, 0);
  EXPECT_GT(cut, 0);
  EXPECT_GT(compared, 60);
}

// At u = 17/8 fixels 0 and 2 hold the part at θ = 0, before it turns
// (fixel verify's sustained.approach check derives such a hold by an exact
// LP; approach_test.cpp checks holds at rational poses against Cramer's
// rule in Q(√d)).
GTEST_TEST(PushPlan, ReportsJPrimeAndThePairThatHoldsThePartInTextAndJson) {
  const Scene scene = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/polygon.json");
  const PushPlan plan = plan_push(scene, 0, Rational(17, 8), false);
  EXPECT_NE(push_plan_text(scene, plan)
                .find("approach-aware J': out: fixels[0] and fixels[2] can hold the part at "
                      "rest with friction on the way to the seat (at theta ~ 0.0000 rad"),
            std::string::npos)
      << push_plan_text(scene, plan);
  const auto doc = nlohmann::json::parse(push_plan_json(scene, plan));
  const auto& approach = doc.at("sustained").at("approach");
  EXPECT_EQ(doc.at("sustained").at("status"), "in");
  EXPECT_EQ(approach.at("status"), "out");
  EXPECT_EQ(approach.at("contains"), false);
  EXPECT_EQ(approach.at("hold").at("fixels"), nlohmann::json::array({0, 2}));
  EXPECT_EQ(approach.at("hold").at("t"), "0");
  EXPECT_EQ(approach.at("t_star"), "15-1*sqrt(226)");
  EXPECT_EQ(doc.at("corner"), false);
  // At the corner u = 2 a status is for the whole fan, as for J and S: IN
  // only when all of it is in J'. Not every push of the fan is in J (in_J
  // is OUT), so not in J' ⊆ J: the plan says OUT, and so does the J'
  // region's point test, since one edge ray of the fan is certainly outside
  // J' (it once left this fan PARTIAL, testing only the whole fan).
  const PushPlan corner = plan_push(scene, 0, Rational(2), false);
  EXPECT_TRUE(corner.corner);
  EXPECT_FALSE(corner.J_approach_verdict.has_value());
  EXPECT_EQ(point_status(scene, *approach_target(*corner.approach), 0, Rational(2), Rational(0)), RegionStatus::kOut);
  EXPECT_EQ(corner.in_J, RegionStatus::kOut);
  EXPECT_EQ(corner.in_J_approach, RegionStatus::kOut);
  EXPECT_NE(push_plan_text(scene, corner).find("approach-aware J': out (a corner: not every push of its fan is in J'"),
            std::string::npos)
      << push_plan_text(scene, corner);
}

// At a corner S's status is IN or OUT for the whole fan (OUT: not every
// push lands in S), while G's can be PARTIAL (some push lands, perhaps not
// all). With
// every gap 0, G = S on the polygon, and at u = 3 a middle stretch of the
// fan lands in S: "out" beside "partial" read as G ⊄ S, so the text says
// what each means. Second method: the fan's pushes tested one by one,
// exactly, against S's rows (b0 is S's apex, so a push lands iff its
// wrench is in S).
GTEST_TEST(PushPlan, AtACornerSaysWhatSsOutAndGsPartialMean) {
  Scene scene = test::scene_file("polygon");
  for (auto& f : scene.fixels) f.gap = 0;
  const PushPlan plan = plan_push(scene, 0, Rational(3), true);
  ASSERT_TRUE(plan.corner);
  ASSERT_TRUE(plan.in_G.has_value());
  EXPECT_EQ(plan.in_S, RegionStatus::kOut);
  EXPECT_EQ(*plan.in_G, RegionStatus::kPartial);
  const SeatingSet S = seating_set(scene);
  ASSERT_EQ(S.apex, scene.background_impulse);
  const Vec2 p{Rational(1, 4), Rational(3, 2)}, r{p.x - scene.body.p_AoCm_A.x, p.y - scene.body.p_AoCm_A.y};
  const Vec2 n_in{Rational(-1), Rational(-5, 4)}, n_out{Rational(1), Rational(-5, 4)};  // the edges' inward normals
  int landed = 0, missed = 0;
  for (int k = 0; k <= 20; ++k) {
    const Rational s(k, 20);
    const Vec2 d{(1 - s) * n_in.x + s * n_out.x, (1 - s) * n_in.y + s * n_out.y};
    (S.contains(contact_wrench(r, d, 3)) ? landed : missed) += 1;
  }
  EXPECT_GT(landed, 0);
  EXPECT_GT(missed, 0);
  const std::string text = push_plan_text(scene, plan);
  EXPECT_NE(text.find("one-step: can seat: out (a corner: not every push of its fan lands in S)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("one-step: guaranteed: partial (a corner: some pushes of its fan land in G, perhaps not all"),
            std::string::npos)
      << text;
}

// On curved contacts (q* only enclosed) the point test of J could not
// show the push inside J and said PARTIAL, where the region, testing the
// segment, proved OUT. It now asks the region's OUT test of each ray.
// Second method: the region's own interval around the point.
GTEST_TEST(PushPlan, OnCurvedContactsJsOutIsTheRegionsOut) {
  const Scene scene = test::scene_file("example2_rounded");
  const SustainedSet J = sustained_set(scene);
  ASSERT_FALSE(J.pose.exact.has_value());  // the enclosed seat: the case at hand
  RegionOptions opt;
  opt.resolution = Rational(1, 128);
  const Region region = compute_region(scene, *sustained_target(J), opt);
  int checked = 0;
  for (const Rational& u : {Rational(39, 64), Rational(1, 4), Rational(3, 4)}) {
    const PushPlan plan = plan_push(scene, 3, u, false);
    ASSERT_TRUE(plan.in_J.has_value());
    for (const auto& r : region.intervals)
      if (r.curve == 3 && r.u0 < u && u < r.u1 && r.status != RegionStatus::kPartial) {
        EXPECT_EQ(*plan.in_J, r.status) << to_string(u);
        ++checked;
      }
  }
  EXPECT_EQ(checked, 3);
}

// push-plan judges a frictionless finger whatever the scene's pusher μ,
// and says so, with both μ in its JSON: on fig6 (pusher μ 1/5) region and
// sample judge the friction fan and can say OUT where the plan says IN.
GTEST_TEST(PushPlan, SaysItIgnoresTheScenesPusherFriction) {
  const Scene scene = test::scene_file("fig6");
  ASSERT_EQ(scene.pusher_mu_upper(), Rational(1, 5));
  const PushPlan plan = plan_push(scene, 0, Rational(9), false);
  const std::string text = push_plan_text(scene, plan);
  EXPECT_NE(
      text.find("pusher: a frictionless finger pushing along the normal; the scene's pusher mu = 1/5 = 0.2 is not "
                "used here"),
      std::string::npos)
      << text;
  const auto doc = nlohmann::json::parse(push_plan_json(scene, plan));
  EXPECT_EQ(doc.at("pusher_mu"), "0");
  EXPECT_EQ(doc.at("scene_pusher_mu"), "1/5");
  const Scene frictionless = test::scene_file("polygon");
  EXPECT_EQ(push_plan_text(frictionless, plan_push(frictionless, 0, Rational(5, 2), false)).find("pusher:"),
            std::string::npos);
  // An interval's upper end is shown as what it is.
  Scene interval = scene;
  interval.pusher_mu = Rational(1, 10);
  interval.pusher_mu_hi = Rational(3, 10);
  const std::string interval_text = push_plan_text(interval, plan_push(interval, 0, Rational(9), false));
  EXPECT_NE(interval_text.find("the scene's pusher mu = 3/10 = 0.3 (the upper end of its interval [1/10 = 0.1, 3/10 = "
                               "0.3], at which every analysis judges it) is not used here"),
            std::string::npos)
      << interval_text;
}

// push-plan --guaranteed gives G's magnitude window at a point (a point
// test used to leave it empty, and the report said "no single certified
// window"). Checked against G itself: an impulse b0 + τg whose |p| = τ|d|
// lies in the window (decided on squares, exactly) is in G, and the window
// lies in S's (G ⊂ S).
GTEST_TEST(PushPlan, GivesGsMagnitudeWindowAtAPointAndItsImpulsesAreInG) {
  const std::tuple<const char*, int, Rational> points[] = {{"polygon", 0, Rational(5, 2)},
                                                           {"nonunique_part", 0, Rational(8)}};
  for (const auto& [name, curve, u] : points) {
    const Scene scene = test::scene_file(name);
    const PushPlan plan = plan_push(scene, curve, u, true);
    ASSERT_TRUE(plan.in_G.has_value()) << name;
    ASSERT_EQ(*plan.in_G, RegionStatus::kIn) << name;
    const Magnitudes& m = plan.magnitudes_G;
    ASSERT_FALSE(m.empty) << name;
    EXPECT_GE(m.lo, plan.magnitudes_S.lo) << name;
    const VectorQ& g = plan.wrench_direction;
    const Rational d2 = g[0] * g[0] + g[1] * g[1];
    // A magnitude inside the window, then τ = |p|/|d| as the exact value of
    // a double; its |p| is checked to be inside on squares.
    const double p_mid = m.hi ? (to_double(m.lo) + to_double(*m.hi)) / 2 : 2 * to_double(m.lo) + 1;
    const Rational tau(p_mid / std::sqrt(to_double(d2)));
    const Rational p2 = tau * tau * d2;
    ASSERT_GT(p2, m.lo * m.lo) << name;
    if (m.hi) {
      ASSERT_LT(p2, *m.hi * *m.hi) << name;
    }
    const SeatingSet S = seating_set(scene);
    const GuaranteedSet G = guaranteed_set(scene, S);
    EXPECT_TRUE(G.contains(VectorQ(scene.background_impulse + tau * g), S)) << name;
  }
}

// The bundled polygon with every gap 0: at the corner u = 2 the next edge's
// normal (the roof's, the direction printed) has a ray that hits S, but the
// fan also holds the right edge's normal (−1, 0), whose ray misses (by hand
// in region_test.cpp). The status is OUT, so no impulse is shown "inside
// the window": there is none. Just past the corner, on the roof, there is.
GTEST_TEST(PushPlan, AnOutCornerShowsNoSampleImpulseThoughItsNextEdgesRayHits) {
  Scene scene = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/polygon.json");
  for (Fixel& f : scene.fixels) f.gap = 0;
  const PushPlan corner = plan_push(scene, 0, Rational(2), false);
  EXPECT_TRUE(corner.corner);
  EXPECT_EQ(corner.in_S, RegionStatus::kOut);
  EXPECT_FALSE(ray_magnitudes(seating_set(scene), scene.background_impulse, corner.wrench_direction).empty);
  EXPECT_FALSE(corner.sample_impulse.has_value());
  EXPECT_EQ(push_plan_text(scene, corner).find("inside the window"), std::string::npos);
  const PushPlan roof = plan_push(scene, 0, Rational(2001, 1000), false);
  EXPECT_EQ(roof.in_S, RegionStatus::kIn);
  ASSERT_TRUE(roof.sample_impulse.has_value());
  EXPECT_GE(roof.sample_outcomes.seating, 1);  // IN in S: some outcome seats
}

}  // namespace
}  // namespace fixel
