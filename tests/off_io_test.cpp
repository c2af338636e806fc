#include "fixel/off_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "fixel/error.h"
#include "fixel/internal/paper_reference.h"
#include "fixel/io.h"
#include "fixel/scene_json.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::v3;

GTEST_TEST(PolytopeVertices, UnitCubeHasEightVertices) {
  const Box box{v3(0, 0, 0), v3(1, 1, 1)};
  const auto verts = polytope_vertices(box.halfspaces(), 3);
  EXPECT_EQ(verts.size(), 8u);
  for (const auto& v : verts)
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(v[k] == 0 || v[k] == 1);
}

GTEST_TEST(PolytopeVertices, CubeCutByADiagonalPlaneKeepsACorner) {
  auto hs = Box{v3(0, 0, 0), v3(1, 1, 1)}.halfspaces();
  hs.push_back({v3(-1, -1, -1), Rational(-1)});    // x + y + z <= 1
  EXPECT_EQ(polytope_vertices(hs, 3).size(), 4u);  // the corner simplex
  hs.push_back({v3(1, 1, 1), Rational(2)});        // and x + y + z >= 2: empty
  EXPECT_TRUE(polytope_vertices(hs, 3).empty());
}

GTEST_TEST(SeatingDumpBox, HoldsApexAndEveryRayTip) {
  const SeatingSet S = seating_set(parse_scene(internal::paper::kExample2Scene));
  const Box box = seating_dump_box(S, Rational(2));
  auto inside = [&](const VectorQ& p) {
    for (int k = 0; k < 3; ++k)
      if (p[k] < box.lo[k] || p[k] > box.hi[k]) return false;
    return true;
  };
  EXPECT_TRUE(inside(S.apex));
  for (const auto& r : S.rays) EXPECT_TRUE(inside(VectorQ(S.apex + 2 * r)));
  EXPECT_THROW(seating_dump_box(S, Rational(0)), InputError);
}

GTEST_TEST(WriteOff, SeatingSetIsAPlainOffSurfaceWithTheBoxInItsSidecar) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  const SeatingSet S = seating_set(scene);
  const auto dir = std::filesystem::temp_directory_path() / "fixel_off_test";
  std::filesystem::remove_all(dir);
  const auto paths = dump_off(scene, S, dir.string(), Rational(1));
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(std::filesystem::path(paths[1]).filename(), "seating_set.json");
  std::ifstream in(paths[0]);
  std::string first, line;
  std::getline(in, first);
  EXPECT_EQ(first, "OFF");
  std::getline(in, line);  // the counts follow the header at once: no comment lines
  std::istringstream counts(line);
  std::size_t nv = 0, nf = 0, ne = 0;
  ASSERT_TRUE(counts >> nv >> nf >> ne) << line;
  std::string rest((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(rest.find('#'), std::string::npos);
  // S ∩ box is a bounded convex polytope: Euler's formula V − E + F = 2 for
  // its triangulated hull, where E = 3F/2.
  EXPECT_GE(nv, 4u);
  EXPECT_EQ(2 * nv, nf + 4);
  // The apex is a vertex of S ∩ box: its exact vertices include it.
  std::vector<Halfspace> hs = S.halfspaces;
  for (const auto& h : seating_dump_box(S, Rational(1)).halfspaces()) hs.push_back(h);
  const auto verts = polytope_vertices(hs, 3);
  EXPECT_EQ(verts.size(), nv);
  EXPECT_NE(std::find(verts.begin(), verts.end(), S.apex), verts.end());
  // The metadata is in the sidecar: exact box, apex and the vertex count.
  std::ifstream side(paths[1]);
  std::string meta((std::istreambuf_iterator<char>(side)), std::istreambuf_iterator<char>());
  for (const std::string want :
       {"\"format\": \"fixel OFF sidecar 1\"", "\"off\": \"seating_set.off\"", "\"what\": \"seating_set\"",
        "\"lo\": [\n      \"-11/10\"", "\"apex\": [\n    \"-1/10\"", "\"drawn_dimension\": 3"})
    EXPECT_NE(meta.find(want), std::string::npos) << want << "\n" << meta;
  EXPECT_NE(meta.find("\"vertices\": " + std::to_string(nv) + ","), std::string::npos) << meta;
}

GTEST_TEST(WriteOff, PointMassSetIsOnePolygonInThePlane) {
  const Scene scene = parse_scene(internal::paper::kExample1Scene);
  std::ostringstream out;
  std::vector<Halfspace> hs = seating_set(scene).halfspaces;
  for (const auto& h : seating_dump_box(seating_set(scene), Rational(1)).halfspaces()) hs.push_back(h);
  const std::size_t n = write_polytope_off(out, hs, 2);
  EXPECT_GE(n, 3u);
  EXPECT_EQ(out.str().rfind("OFF\n" + std::to_string(n) + " 1 0\n", 0), 0u) << out.str();
  EXPECT_EQ(out.str().find('#'), std::string::npos);
}

GTEST_TEST(DumpOff, UnwritableDirectoryIsAnInputError) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  EXPECT_THROW(dump_off(scene, seating_set(scene), "/proc/fixel/cannot", Rational(1)), InputError);
}

// "-" made a folder named "-" (Python's to_off too); the CLI refused it.
GTEST_TEST(DumpOff, AFolderNamedDashIsRefusedAndNothingIsMade) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  const bool existed = std::filesystem::exists("-");
  try {
    dump_off(scene, seating_set(scene), "-", Rational(1));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "dump_off(directory)");
    EXPECT_EQ(e.value(), "-");
    EXPECT_NE(std::string(e.what()).find("not an output folder"), std::string::npos);
  }
  EXPECT_EQ(std::filesystem::exists("-"), existed);
}

// Refused before the folder is made: nothing is written.
GTEST_TEST(DumpOff, AnSOrAGOfAnotherSceneIsRefusedNamingItAndNothingIsWritten) {
  const test::SetCheckScenes s = test::set_check_scenes();
  const SeatingSet S = seating_set(s.scene);
  const GuaranteedSet G = guaranteed_set(s.scene, S);
  const auto dir = std::filesystem::temp_directory_path() / "fixel_off_test_other_scene";
  std::filesystem::remove_all(dir);
  const std::string s_named = test::input_error_of([&] { dump_off(s.gapped, S, dir.string(), Rational(1)); });
  EXPECT_EQ(s_named.rfind("S: ", 0), 0u) << s_named;
  const std::string g_named = test::input_error_of([&] { dump_off(s.heavier, S, dir.string(), Rational(1), &G); });
  EXPECT_EQ(g_named.rfind("G: ", 0), 0u) << g_named;
  EXPECT_FALSE(std::filesystem::exists(dir));
  EXPECT_EQ(dump_off(s.scene, S, dir.string(), Rational(1), &G).empty(), false);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fixel
