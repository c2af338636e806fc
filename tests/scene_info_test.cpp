#include "fixel/scene_info.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/io_info.h"
#include "fixel/lcp.h"
#include "fixel/on_boundary.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"
#include "test_util.h"

namespace fixel {
namespace {

// A Boundary assembled by hand with nothing in it: every function that
// reads an outline refuses it (some segfaulted, check_simple_loop never
// returned), and a bad fixel index is an InputError, not std::out_of_range.
GTEST_TEST(SceneInfo, AnEmptyHandMadeBoundaryAndABadFixelIndexAreTypedErrors) {
  Scene scene = test::scene_file("polygon");
  scene.body.boundary = std::make_shared<const Boundary>();
  EXPECT_THROW(scene_info(scene), SceneError);
  EXPECT_THROW(check_fixels_on_boundary(scene), SceneError);
  EXPECT_THROW(fit_to_boundary(Boundary{}, Vec2{Rational(0), Rational(0)}), SceneError);
  EXPECT_THROW(check_simple_loop({}), SceneError);
  const Scene polygon = test::scene_file("polygon");
  EXPECT_THROW(polygon.lever_arm(3), InputError);
  EXPECT_THROW(polygon.tangent(-1), InputError);
  EXPECT_EQ(polygon.tangent(0).x, -polygon.fixels[0].n_A.y);
  Scene zero_normal = polygon;  // J was non-empty and "strongly stable"
  zero_normal.fixels[1].n_A = Vec2{Rational(0), Rational(0)};
  EXPECT_THROW(sustained_set(zero_normal), SceneError);
  Scene no_velocity = polygon;  // built in code without one: written as [], which reading refused
  no_velocity.body.velocity.resize(0);
  EXPECT_THROW(write_scene(no_velocity), SceneError);
}

GTEST_TEST(SceneInfo, WarnsWhenTheMassWasDefaultedFromTheArea) {
  const Scene scene = test::scene_file("polygon");  // no "mass": density 1
  ASSERT_TRUE(scene.body.mass_from_area);
  const SceneInfo info = scene_info(scene);
  ASSERT_TRUE(info.area);
  EXPECT_EQ(scene.body.mass, *info.area);
  ASSERT_EQ(info.warnings.size(), 1u);
  EXPECT_NE(info.warnings[0].find("body.mass is not given"), std::string::npos);
  EXPECT_NE(scene_info_text(scene, info).find("warning: body.mass is not given"), std::string::npos);
  EXPECT_NE(scene_info_json(scene, info).find("\"from_area\": true"), std::string::npos);
}

GTEST_TEST(SceneInfo, GivesEachFixelsOwnPositionAndItsPlaceOnTheOutline) {
  const Scene scene = test::scene_file("fig6");
  const SceneInfo info = scene_info(scene);
  ASSERT_EQ(info.p_AoFixel_A.size(), 3u);
  // f = p − ψ n = (0, −35/24) − (1/20)(0, 1).
  EXPECT_EQ(info.p_AoFixel_A[0].x, 0);
  EXPECT_EQ(info.p_AoFixel_A[0].y, Rational(-181, 120));
  ASSERT_EQ(info.on_outline.size(), 3u);
  for (const auto& fit : info.on_outline) {
    EXPECT_TRUE(fit.on_boundary);
    EXPECT_TRUE(fit.normal_matches);
  }
  ASSERT_TRUE(info.on_outline[2].u);
  EXPECT_EQ(*info.on_outline[2].u, Rational(639, 100));
  // Its one warning: the sustained push finds no seated pose (fig6's fixels
  // cannot all touch the outline near the scene pose).
  ASSERT_EQ(info.warnings.size(), 1u);
  EXPECT_NE(info.warnings[0].find("have no seated pose near the scene pose"), std::string::npos) << info.warnings[0];
}

GTEST_TEST(SceneInfo, ReportsTheSeatedPoseOrWhyThereIsNone) {
  const SceneInfo polygon = scene_info(test::scene_file("polygon"));
  ASSERT_TRUE(polygon.seated);
  EXPECT_TRUE(polygon.seated->exact);
  const SceneInfo example2 = scene_info(test::scene_file("example2"));
  EXPECT_FALSE(example2.seated);
  EXPECT_NE(example2.seated_unavailable.find("body.boundary"), std::string::npos);
}

GTEST_TEST(SceneInfo, NamesTheFixelsMarkedOffTheOutline) {
  const Scene scene = test::scene_file("nonunique_part");
  const SceneInfo info = scene_info(scene);
  ASSERT_EQ(info.warnings.size(), 4u);  // three fixels off the outline, and so no seated pose for the sustained push
  EXPECT_NE(info.warnings[0].find("fixels[0] is marked off_boundary"), std::string::npos);
  EXPECT_FALSE(info.on_outline[0].on_boundary);
  EXPECT_FALSE(scene.description.empty());
}

// info said nothing of a scene every analysis refuses: it now warns, with
// the analyses' own reason, before one is run.
GTEST_TEST(SceneInfo, WarnsWhenTheAnalysesRefuseTheSceneWithTheirOwnError) {
  const std::string one_step =
      "the one-step analyses (seat, region, sample, simulate, solutions, push-plan, dump) refuse this scene: ";
  const std::string sustained =
      "the sustained-push analyses (seat --sustained, region --push sustained, dump --sustained) refuse "
      "this scene: ";
  // The warning is the analysis' own error, word for word.
  auto error_of = [](auto analysis) {
    try {
      analysis();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  Scene two = test::scene_file("polygon");
  two.fixels.pop_back();  // n_c = 2 < dof = 3
  const SceneInfo info = scene_info(two);
  ASSERT_EQ(info.warnings.size(), 3u);  // the mass, the one-step rule, the sustained push
  EXPECT_EQ(info.warnings[1], one_step + error_of([&] { seating_set(two); }));
  EXPECT_EQ(info.warnings[1], one_step +
                                  "fixels: 2 fixels but dof is 3: the seating analysis needs exactly dof fixels "
                                  "(n_c == dof)");
  EXPECT_EQ(info.warnings[2], sustained + error_of([&] { sustained_set(two); }));
  // W_n singular: fixel 2 moves onto fixel 1's point.
  Scene singular = test::scene_file("polygon");
  singular.fixels[2].p_AoF_A = singular.fixels[1].p_AoF_A;
  const SceneInfo s = scene_info(singular);
  ASSERT_GE(s.warnings.size(), 2u);
  EXPECT_EQ(s.warnings[1], one_step + error_of([&] { seating_set(singular); }));
  EXPECT_NE(s.warnings[1].find("makes W_n singular"), std::string::npos);
  // A friction interval: the one-step analyses refuse it, the sustained push takes it.
  Scene interval = test::scene_file("polygon");
  interval.fixels[0].mu_hi = Rational(1, 5);
  const SceneInfo f = scene_info(interval);
  ASSERT_EQ(f.warnings.size(), 2u);
  EXPECT_EQ(f.warnings[1], one_step + error_of([&] { seating_set(interval); }));
  EXPECT_NE(f.warnings[1].find("fixels[0].mu: [1/10, 1/5] is an interval"), std::string::npos);
  // The sustained push's own refusals: a point mass, no outline, no seated pose.
  for (const char* name : {"example1", "example2", "blob", "fig6", "nonunique_part"}) {
    const Scene scene = test::scene_file(name);
    const std::string reason = error_of([&] { sustained_set(scene); });
    const auto& w = scene_info(scene).warnings;
    EXPECT_NE(std::find(w.begin(), w.end(), sustained + reason), w.end()) << name << ": " << reason;
    for (const auto& warning : w) EXPECT_EQ(warning.rfind(one_step, 0), std::string::npos) << name << ": " << warning;
  }
  // A scene every analysis accepts gets no such warning.
  for (const char* name : {"polygon", "example2_rounded"})
    for (const auto& w : scene_info(test::scene_file(name)).warnings)
      EXPECT_EQ(w.find("refuse this scene"), std::string::npos) << name << ": " << w;
}

}  // namespace
}  // namespace fixel
