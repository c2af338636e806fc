// plan_push (fixel push-plan): its run control, and its J′ verdicts.
#include "fixel/push_plan.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "approach_oracle.h"
#include "fixel/io.h"
#include "fixel/on_boundary.h"
#include "fixel/progress.h"
#include "fixel/scene_json.h"

namespace fixel {
namespace {

Scene blob() { return load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/blob.json"); }

GTEST_TEST(PushPlan, ACancelledControlStopsTheGuaranteedSetAndTheOutcomeEnumeration) {
  const Scene scene = blob();
  RunControl cancelled;
  cancelled.cancel = true;
  EXPECT_THROW(plan_push(scene, 0, Rational(10), true, &cancelled), StoppedError);  // G's modes
  try {
    plan_push(scene, 0, Rational(10), false, &cancelled);  // then the sample impulse's outcomes
    ADD_FAILURE() << "a cancelled plan finished";
  } catch (const StoppedError& e) {
    EXPECT_NE(std::string(e.what()).find("solutions: interrupted"), std::string::npos) << e.what();
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

// Along the polygon's outline (every 1/16 of its parameter, corners
// skipped): J′ ⊆ J; each hold J′ reports at a rational pose is a hold for
// the exact LP of the directly solved pose (approach_oracle.h); and some
// push that J keeps is dropped by J′, so the check is not vacuous.
GTEST_TEST(PushPlan, JPrimeVerdictsAreInsideJAndTheirHoldsAreConfirmedByAnExactLp) {
  const Scene scene = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/polygon.json");
  const Curve& curve = scene.body.boundary->curves[0];
  int kept = 0, dropped_by_hold = 0, corners = 0;
  for (Rational u = curve.u_begin(); u <= curve.u_end(); u += Rational(1, 16)) {
    const PushPlan plan = plan_push(scene, 0, u, false);
    ASSERT_TRUE(plan.in_J.has_value() && plan.approach.has_value());
    if (fit_to_boundary(*scene.body.boundary, plan.point_A).corner) {
      EXPECT_FALSE(plan.in_J_approach.has_value()) << to_string(u);
      EXPECT_NE(plan.J_approach_note.find("corner"), std::string::npos);
      ++corners;
      continue;
    }
    ASSERT_TRUE(plan.in_J_approach.has_value() && plan.in_J_approach->contains.has_value()) << to_string(u);
    if (*plan.in_J_approach->contains) {
      EXPECT_EQ(*plan.in_J, RegionStatus::kIn) << to_string(u);
      ++kept;
      continue;
    }
    if (*plan.in_J != RegionStatus::kIn) continue;
    const auto& hold = plan.in_J_approach->hold;
    ASSERT_TRUE(hold.has_value()) << to_string(u) << ": " << plan.in_J_approach->why_not;
    ASSERT_TRUE(hold->t.has_value() && hold->t->is_rational()) << to_string(u);
    const test::DirectPose d =
        test::direct_pose(scene, plan.approach->J.mu, hold->fixels[0], hold->fixels[1], hold->t->lo);
    EXPECT_TRUE(test::in_cone_lp(d.gens, -plan.wrench_direction)) << to_string(u);
    ++dropped_by_hold;
  }
  EXPECT_EQ(corners, 6);  // the pentagon's five vertices, its first at both ends of the range
  EXPECT_GT(kept, 0);
  EXPECT_GT(dropped_by_hold, 0);
}

GTEST_TEST(PushPlan, ReportsJPrimeInTextAndJson) {
  const Scene scene = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/polygon.json");
  const PushPlan plan = plan_push(scene, 0, Rational(17, 8), false);
  EXPECT_NE(push_plan_text(scene, plan).find("approach-aware J': out: fixels[0] and fixels[2] can hold"),
            std::string::npos)
      << push_plan_text(scene, plan);
  const auto doc = nlohmann::json::parse(push_plan_json(scene, plan));
  const auto& approach = doc.at("sustained").at("approach");
  EXPECT_EQ(doc.at("sustained").at("status"), "in");
  EXPECT_EQ(approach.at("contains"), false);
  EXPECT_EQ(approach.at("hold").at("fixels"), nlohmann::json::array({0, 2}));
  EXPECT_EQ(approach.at("hold").at("t"), "0");
}

}  // namespace
}  // namespace fixel
