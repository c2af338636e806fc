#include "fixel/svg.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fixel/error.h"
#include "fixel/region_target.h"
#include "other_scene_region.h"
#include "test_util.h"

namespace fixel {
namespace {

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The pictures drew the sets they were given over any scene's outline.
GTEST_TEST(Svg, BothPicturesRefuseAnSOrAGOfAnotherSceneNamingItAndWriteNothing) {
  const test::SetCheckScenes s = test::set_check_scenes();
  const SeatingSet S = seating_set(s.scene);
  const GuaranteedSet G = guaranteed_set(s.scene, S);
  RegionOptions options;
  options.resolution = Rational(1, 16);
  const Region region = compute_region(s.scene, S, options);
  const auto path = std::filesystem::temp_directory_path() / "fixel_svg_test_other_scene.svg";
  std::filesystem::remove(path);
  const Rational theta = default_slice_theta(S);
  auto named = [](const std::function<void()>& call) {
    const std::string e = test::input_error_of(call);
    return e.substr(0, e.find(':'));
  };
  EXPECT_EQ(named([&] { write_region_svg(path.string(), s.gapped, S, region); }), "S");
  EXPECT_EQ(named([&] { write_region_svg(path.string(), s.heavier, S, region, &G); }), "G");
  EXPECT_EQ(named([&] { write_guaranteed_svg(path.string(), s.gapped, S, nullptr, theta, std::nullopt); }), "S");
  EXPECT_EQ(named([&] { write_guaranteed_svg(path.string(), s.heavier, S, &G, theta, std::nullopt); }), "G");
  EXPECT_FALSE(std::filesystem::exists(path));
  // The scene's own sets draw.
  write_region_svg(path.string(), s.scene, S, region, &G);
  EXPECT_NE(read_all(path).find("<svg"), std::string::npos);
  write_guaranteed_svg(path.string(), s.scene, S, &G, theta, std::nullopt);
  EXPECT_NE(read_all(path).find("<svg"), std::string::npos);
  std::filesystem::remove(path);
}

GTEST_TEST(Svg, TheSustainedPictureRefusesAJOfAnotherSceneAndWritesNothing) {
  const Scene polygon = test::scene_file("polygon");
  Scene moved = polygon;
  moved.fixels[0].gap = Rational(1, 5);
  const SustainedSet J = sustained_set(polygon);
  RegionOptions options;
  options.resolution = Rational(1, 16);
  const Region region = compute_region(polygon, *sustained_target(J), options);
  const auto path = std::filesystem::temp_directory_path() / "fixel_svg_test_other_scene_j.svg";
  std::filesystem::remove(path);
  const std::string e = test::input_error_of([&] { write_sustained_region_svg(path.string(), moved, J, region); });
  EXPECT_EQ(e.rfind("J: ", 0), 0u) << e;
  EXPECT_FALSE(std::filesystem::exists(path));
  write_sustained_region_svg(path.string(), polygon, J, region);
  EXPECT_NE(read_all(path).find("<svg"), std::string::npos);
  std::filesystem::remove(path);
}

GTEST_TEST(Svg, TheRegionPictureRefusesARegionOfAnotherSceneAndWritesNothing) {
  const Scene polygon = test::scene_file("polygon");
  const Region region = test::rounded_region();
  const auto path = std::filesystem::temp_directory_path() / "fixel_svg_test_other_region.svg";
  std::filesystem::remove(path);
  const std::string e =
      test::input_error_of([&] { write_region_svg(path.string(), polygon, seating_set(polygon), region); });
  EXPECT_EQ(e.rfind("region: ", 0), 0u) << e;
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace fixel
