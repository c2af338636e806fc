#include "fixel/scene_info.h"

#include <gtest/gtest.h>

#include "fixel/io_info.h"
#include "test_util.h"

namespace fixel {
namespace {

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
  EXPECT_TRUE(info.warnings.empty());
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
  ASSERT_EQ(info.warnings.size(), 3u);
  EXPECT_NE(info.warnings[0].find("fixels[0] is marked off_boundary"), std::string::npos);
  EXPECT_FALSE(info.on_outline[0].on_boundary);
  EXPECT_FALSE(scene.description.empty());
}

}  // namespace
}  // namespace fixel
