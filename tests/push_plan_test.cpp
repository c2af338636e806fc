// plan_push (fixel push-plan): its run control.
#include "fixel/push_plan.h"

#include <gtest/gtest.h>

#include <string>

#include "fixel/io.h"
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

}  // namespace
}  // namespace fixel
