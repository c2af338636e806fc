#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <set>
#include <string>

#include "fixel/error.h"
#include "fixel/internal/paper_reference.h"
#include "test_util.h"

namespace fixel {
namespace {

// A valid Example 2 scene with one piece of text replaced.
std::string example2_with(const std::string& from, const std::string& to) {
  std::string s = internal::paper::kExample2Scene;
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

// Expects parse_scene to throw E with exactly this message.
template <typename E>
void expect_error(const std::string& text, const std::string& message, bool analysed = false) {
  try {
    const Scene scene = parse_scene(text, "scene.json");
    if (analysed) seating_set(scene);  // checks that belong to the one-step analyses
    ADD_FAILURE() << "no error; expected: " << message;
  } catch (const E& e) {
    EXPECT_EQ(std::string(e.what()), message);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}

GTEST_TEST(Scene, LoadsExample2Exactly) {
  const Scene s = parse_scene(internal::paper::kExample2Scene);
  EXPECT_EQ(s.name, "example2");
  EXPECT_EQ(s.body.dof, 3);
  ASSERT_EQ(s.num_contacts(), 3);
  EXPECT_EQ(s.fixels[1].gap, Rational(1, 20));
  EXPECT_EQ(s.fixels[2].mu, Rational(1, 10));
  EXPECT_EQ(s.lever_arm(2).x, Rational(1));
  EXPECT_EQ(s.tangent(0).y, Rational(1));  // (1, 0) rotated +90°
  EXPECT_EQ(s.pusher_mu, Rational(0));
  EXPECT_TRUE(s.background_impulse.isZero());
}

GTEST_TEST(Scene, BundledFilesMatchTheBuiltInPaperScenes) {
  const Scene file = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/example2.json");
  const Scene builtin = parse_scene(internal::paper::kExample2Scene);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(file.fixels[i].p_AoF_A.x, builtin.fixels[i].p_AoF_A.x);
    EXPECT_EQ(file.fixels[i].p_AoF_A.y, builtin.fixels[i].p_AoF_A.y);
    EXPECT_EQ(file.fixels[i].gap, builtin.fixels[i].gap);
    EXPECT_EQ(file.fixels[i].mu, builtin.fixels[i].mu);
  }
  const Scene e1 = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/example1.json");
  EXPECT_EQ(e1.body.dof, 2);
  EXPECT_EQ(e1.fixels[0].gap, Rational(3, 10));
  EXPECT_NO_THROW(load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/nonunique.json"));
}

GTEST_TEST(Scene, ReadsJsonNumbersFromTheirDecimalText) {
  // 0.1 as a JSON number must be 1/10, not the double nearest to it.
  const Scene s = parse_scene(example2_with(R"("gap": "1/10")", R"("gap": 0.1)"));
  EXPECT_EQ(s.fixels[0].gap, Rational(1, 10));
  const Scene t =
      parse_scene(example2_with(R"("mu": "1/10", "gap": "1/10")", R"("mu": 1e-1, "gap": 0.10000000000000000000001)"));
  EXPECT_EQ(t.fixels[0].mu, Rational(1, 10));
  EXPECT_EQ(t.fixels[0].gap - Rational(1, 10), parse_rational("1e-23"));
}

GTEST_TEST(Scene, RejectsMalformedJson) {
  try {
    parse_scene("{\"name\": ", "bad.json");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.field(), "bad.json");
    EXPECT_NE(std::string(e.what()).find("is not valid JSON"), std::string::npos);
  }
  EXPECT_THROW(parse_scene("[1, 2]"), SceneError);
}

GTEST_TEST(Scene, RejectsDeeplyNestedJsonInsteadOfOverflowingTheStack) {
  // Found by hand after fuzzing (the fuzzer's 4 KB inputs cannot nest this
  // deep): 200000 nested arrays used to crash in the DOM's destructor.
  const std::string deep = std::string(200000, '[') + std::string(200000, ']');
  try {
    parse_scene(deep, "deep.json");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "deep.json: depth 65 nests deeper than 64 levels");
  }
  const std::string objects = [] {
    std::string s;
    for (int i = 0; i < 100000; ++i) s += "{\"a\":";
    return s + "1" + std::string(100000, '}');
  }();
  EXPECT_THROW(parse_scene(objects, "deep.json"), ParseError);
}

GTEST_TEST(Scene, RejectsDuplicateKeys) {
  expect_error<ParseError>(example2_with(R"("name": "example2")", R"("name": "a", "name": "b")"),
                           "scene.json: key \"name\" appears twice in one object");
}

// Numbers are read as their text, so "name": 5 must be refused before it
// becomes the text "5".
GTEST_TEST(Scene, RejectsANumberOrOtherNonTextAsTheNameOrDescription) {
  expect_error<SceneError>(example2_with(R"("name": "example2")", R"("name": 5)"),
                           "name: 5 must be a string, not a number");
  expect_error<SceneError>(example2_with(R"("name": "example2")", R"("name": "example2", "description": 1e3)"),
                           "description: 1e3 must be a string, not a number");
  expect_error<SceneError>(example2_with(R"("name": "example2")", R"("name": true)"), "name: true must be a string");
  EXPECT_EQ(parse_scene(example2_with(R"("name": "example2")", R"("name": "5")"), "scene.json").name, "5");
}

// The whole text is parsed before its content is judged: a syntax error
// later in the file is the error reported, not the content error before it.
GTEST_TEST(Scene, ASyntaxErrorAfterAContentErrorIsTheOneReported) {
  for (const char* early : {R"("name": 5,)", R"("name": "a", "name": "b",)"}) {
    try {
      parse_scene(example2_with(R"("name": "example2")", early), "scene.json");
      FAIL() << early;
    } catch (const ParseError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("scene.json: at byte ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find("is not valid JSON"), std::string::npos) << e.what();
    }
  }
}

GTEST_TEST(Scene, RejectsMissingFields) {
  expect_error<SceneError>(example2_with(R"("time_step": "1",)", ""), "time_step: is missing");
  expect_error<SceneError>(example2_with(R"("mass": "1", )", ""), "body.mass: is missing");
  expect_error<SceneError>(example2_with(R"("mu": "1/10", "gap": "1/20")", R"("mu": "1/10")"),
                           "fixels[1].gap: is missing");
  expect_error<SceneError>(example2_with(R"("inertia": "1", )", ""),
                           "body.inertia: is missing (required for dof 3 without a boundary)");
}

GTEST_TEST(Scene, RejectsUnknownFields) {
  expect_error<SceneError>(example2_with(R"("time_step": "1",)", R"("time_step": "1", "timestep": "2",)"),
                           "timestep: \"2\" is not a known field");
  expect_error<SceneError>(example2_with(R"("gap": "1/5")", R"("gap": "1/5", "friction": "1")"),
                           "fixels[2].friction: \"1\" is not a known field");
}

GTEST_TEST(Scene, RejectsNonUnitNormal) {
  expect_error<SceneError>(
      example2_with(R"("normal": ["0", "1"], "mu": "1/10", "gap": "1/20")",
                    R"("normal": ["3/5", "3/5"], "mu": "1/10", "gap": "1/20")"),
      "fixels[1].normal: (3/5, 3/5) is not of unit length (x²+y² must be exactly 1, e.g. (3/5, 4/5); the nearest "
      "exact unit normal (within 1e-9 rad) is [\"31509019101/44560482149\", \"31509019100/44560482149\"])");
  // A direction of rational length gets its exact normalisation as the hint.
  expect_error<SceneError>(
      example2_with(R"("normal": ["0", "1"], "mu": "1/10", "gap": "1/20")",
                    R"("normal": ["3", "4"], "mu": "1/10", "gap": "1/20")"),
      "fixels[1].normal: (3, 4) is not of unit length (x²+y² must be exactly 1, e.g. (3/5, 4/5); normalised exactly "
      "it is [\"3/5\", \"4/5\"])");
  // A normal that is unit only to double precision is still rejected.
  EXPECT_THROW(parse_scene(example2_with(R"("normal": ["1", "0"])", R"("normal": ["0.6000000000000000001", "0.8"])")),
               SceneError);
  EXPECT_NO_THROW(parse_scene(example2_with(R"("normal": ["1", "0"])", R"("normal": ["0.6", "0.8"])")));
}

GTEST_TEST(Scene, RejectsNegativeGapAndMu) {
  expect_error<SceneError>(example2_with(R"("gap": "1/20")", R"("gap": "-1/20")"), "fixels[1].gap: -1/20 must be >= 0");
  expect_error<SceneError>(example2_with(R"("mu": "1/10", "gap": "1/5")", R"("mu": "-0.1", "gap": "1/5")"),
                           "fixels[2].mu: -1/10 must be >= 0");
}

GTEST_TEST(Scene, RejectsNonPositiveMassInertiaAndTimeStep) {
  expect_error<SceneError>(example2_with(R"("mass": "1")", R"("mass": "0")"), "body.mass: 0 must be > 0");
  expect_error<SceneError>(example2_with(R"("inertia": "1")", R"("inertia": "-2")"), "body.inertia: -2 must be > 0");
  expect_error<SceneError>(example2_with(R"("time_step": "1")", R"("time_step": "0")"), "time_step: 0 must be > 0");
}

GTEST_TEST(Scene, RejectsBadNumbersNamingThePath) {
  expect_error<ParseError>(example2_with(R"("mass": "1")", R"("mass": "heavy")"),
                           "body.mass: \"heavy\" is not an exact number (use 3, -3/7, 0.1 or 1e-3)");
  expect_error<ParseError>(example2_with(R"("mass": "1")", R"("mass": true)"),
                           "body.mass: true is not an exact number");
}

GTEST_TEST(Scene, RejectsDofOutsideTwoAndThree) {
  expect_error<SceneError>(example2_with(R"("dof": 3)", R"("dof": 4)"),
                           "body.dof: 4 must be 2 (point mass) or 3 (planar rigid body)");
}

GTEST_TEST(Scene, RejectsVectorsWhoseLengthDoesNotMatchDof) {
  std::string e1 = internal::paper::kExample1Scene;
  e1.replace(e1.find(R"("velocity": ["0", "0"])"), 22, R"("velocity": ["0", "0", "0"])");
  expect_error<SceneError>(e1, "body.velocity: [\"0\",\"0\",\"0\"] has 3 entries but dof 2 needs 2");
  expect_error<SceneError>(example2_with(R"("name": "example2",)", R"("name": "x", "background_impulse": ["1", "2"],)"),
                           "background_impulse: [\"1\",\"2\"] has 2 entries but dof 3 needs 3");
  expect_error<SceneError>(
      example2_with(R"("point": ["-1", "0"])", R"("point": ["-1", "0", "0"])"),
      "fixels[0].point: [\"-1\",\"0\",\"0\"] has 3 entries but a planar point or direction needs 2");
}

GTEST_TEST(Scene, RejectsInertiaForAPointMass) {
  std::string e1 = internal::paper::kExample1Scene;
  e1.replace(e1.find(R"("mass": "1")"), 11, R"("mass": "1", "inertia": "1")");
  expect_error<SceneError>(e1, "body.inertia: \"1\" is not allowed for a point mass (dof 2)");
}

// The fixel count and the rank of W_n are the one-step analyses' rules
// (seating, LCP): a scene without them loads (fixture design needs parts
// without fixels), and the analyses reject it with the same message.
GTEST_TEST(Scene, OneStepAnalysesRejectFixelCountDifferentFromDof) {
  const std::string two_fixels = example2_with(
      R"(,
    {"point": ["1", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/5"})",
      "");
  expect_error<SceneError>(
      two_fixels, "fixels: 2 fixels but dof is 3: the seating analysis needs exactly dof fixels (n_c == dof)", true);
  EXPECT_NO_THROW(parse_scene(two_fixels));
}

GTEST_TEST(Scene, OneStepAnalysesRejectSingularFixtureNamingTheDependentFixel) {
  // Fixel 2 at (0, 3) with normal (0, 1) has wrench (0, 1, 0), the same as
  // fixel 1's; sliding it along x to (5, -1) gives moment 5 and independence.
  const std::string independent = example2_with(R"("point": ["1", "-1"])", R"("point": ["5", "-1"])");
  const std::string dependent =
      example2_with(R"("point": ["1", "-1"], "normal": ["0", "1"])", R"("point": ["0", "3"], "normal": ["0", "1"])");
  EXPECT_NO_THROW(seating_set(parse_scene(independent)));
  expect_error<SceneError>(dependent,
                           "fixels[2]: (0, 3) makes W_n singular: its normal wrench is a combination of the earlier "
                           "fixels', so the fixture does not determine the motion",
                           true);
}

GTEST_TEST(Scene, RejectsABoundaryThatIsNotAList) {
  expect_error<SceneError>(example2_with(R"("inertia": "1", )", R"("boundary": {}, )"),
                           "body.boundary: {} must be an array of curves");
  expect_error<SceneError>(example2_with(R"("inertia": "1", )", R"("boundary": [{"type": "circle"}], )"),
                           "body.boundary[0].type: \"circle\" must be \"polyline\" or \"bspline\"");
  expect_error<ParseError>(
      example2_with(R"("inertia": "1", )", R"("boundary": [{"type": "polyline", "points": [["0", "x"]]}], )"),
      "body.boundary[0].points[0][1]: \"x\" is not an exact number (use 3, -3/7, 0.1 or 1e-3)");
}

GTEST_TEST(Scene, ParsesImpulsesAgainstDof) {
  EXPECT_EQ(parse_impulse("-1,-1,-1", 3)[2], Rational(-1));
  try {
    parse_impulse("1,2", 3);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--impulse: \"1,2\" has 2 components but the scene has dof 3");
  }
  EXPECT_THROW(parse_impulse("1,x,2", 3), ParseError);
}

GTEST_TEST(Scene, ReportsUnreadableFile) { EXPECT_THROW(load_scene("/nonexistent/scene.json"), InputError); }

}  // namespace
}  // namespace fixel

namespace fixel {
namespace {

GTEST_TEST(Scene, ValidateSceneAcceptsEveryBundledScene) {
  for (const char* name :
       {"example1", "example2", "example2_rounded", "blob", "blob32", "fig6", "nonunique", "nonunique_part", "polygon"})
    EXPECT_NO_THROW(validate_scene(test::scene_file(name))) << name;
}

GTEST_TEST(Scene, ValidateSceneNamesTheFieldOfACodeBuiltSceneWithTheJsonPath) {
  Scene s = test::scene_file("example2");
  s.fixels[1].gap = Rational(-1, 20);
  try {
    validate_scene(s);
    FAIL() << "a negative gap was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "fixels[1].gap: -1/20 must be >= 0");
  }
  s = test::scene_file("example2");
  s.fixels[0].n_A = {Rational(3, 5), Rational(3, 5)};
  EXPECT_THROW(validate_scene(s), SceneError);
  s = test::scene_file("example2");
  s.fixels[2].mu_hi = s.fixels[2].mu - 1;  // hi below lo
  EXPECT_THROW(validate_scene(s), SceneError);
  s = test::scene_file("example2");
  s.background_impulse = VectorQ::Zero(2);
  EXPECT_THROW(validate_scene(s), SceneError);
}

}  // namespace
}  // namespace fixel

namespace fixel {
namespace {

// A square part [0, 2]² with three fixels; FIXEL1 is the second fixel's JSON.
std::string square_with(const std::string& fixel1) {
  return R"({"name": "square", "time_step": "1",
    "body": {"dof": 3, "mass": "1", "boundary": [{"type": "polyline",
             "points": [["0","0"], ["2","0"], ["2","2"], ["0","2"], ["0","0"]]}]},
    "fixels": [{"point": ["0", "1"], "normal": ["1", "0"], "mu": "0", "gap": "1/10"}, )" +
         fixel1 + R"(, {"point": ["3/2", "0"], "normal": ["0", "1"], "mu": "0", "gap": "1/10"}]})";
}

GTEST_TEST(Scene, AFixelOffTheOutlineIsAnErrorNamingItWithTheDistance) {
  try {
    parse_scene(square_with(R"({"point": ["1/2", "1/10"], "normal": ["0", "1"], "mu": "0", "gap": "0"})"));
    FAIL() << "a fixel 1/10 m inside the part was accepted";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("fixels[1].point: (1/2, 1/10) is not on the part's outline: it is 0.1 m from it", 0), 0u)
        << what;
    EXPECT_NE(what.find("fixels[1].off_boundary: true"), std::string::npos) << what;
  }
  // The opt-out accepts it, and says so.
  const Scene s = parse_scene(
      square_with(R"({"point": ["1/2", "1/10"], "normal": ["0", "1"], "mu": "0", "gap": "0", "off_boundary": true})"));
  EXPECT_TRUE(s.fixels[1].off_boundary);
}

GTEST_TEST(Scene, AnOutwardNormalIsAnErrorGivingTheAngle) {
  expect_error<SceneError>(
      square_with(R"({"point": ["1/2", "0"], "normal": ["0", "-1"], "mu": "0", "gap": "0"})"),
      "fixels[1].normal: (0, -1) is not the outline's inward normal at fixels[1].point (on body.boundary[0] at u ≈ "
      "0.25, where it is (0, 1)): 180° apart. Give \"normal\": \"boundary\", or set fixels[1].off_boundary: true");
}

GTEST_TEST(Scene, NormalBoundaryTakesTheOutlinesExactInwardNormal) {
  const Scene s = parse_scene(square_with(R"({"point": ["2", "1/2"], "normal": "boundary", "mu": "0", "gap": "0"})"));
  EXPECT_EQ(s.fixels[1].n_A.x, -1);
  EXPECT_EQ(s.fixels[1].n_A.y, 0);
  try {
    parse_scene(square_with(R"({"point": ["2", "2"], "normal": "boundary", "mu": "0", "gap": "0"})"));
    FAIL() << "a corner gave a normal";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("fixels[1].normal: \"boundary\" is ambiguous: (2, 2) is a corner"),
              std::string::npos)
        << e.what();
  }
}

GTEST_TEST(Scene, NormalInDegreesIsExactOnlyAtMultiplesOfNinety) {
  const Scene s =
      parse_scene(square_with(R"({"point": ["2", "1/2"], "normal": {"degrees": "-180"}, "mu": "0", "gap": "0"})"));
  EXPECT_EQ(s.fixels[1].n_A.x, -1);
  EXPECT_EQ(s.fixels[1].n_A.y, 0);
  try {
    parse_scene(square_with(R"({"point": ["2", "1/2"], "normal": {"degrees": "30"}, "mu": "0", "gap": "0"})"));
    FAIL() << "30 degrees was accepted";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("fixels[1].normal.degrees: 30 is not an exact direction", 0), 0u) << what;
    EXPECT_NE(what.find("the nearest exact unit normal (within 1e-9 rad) is"), std::string::npos) << what;
  }
  // 10^400 degrees has no double: its hint is 10^400 mod 360 = 280 degrees'
  // (10^400 is 0 mod 40 and 1 mod 9), and -10^400's is 80 degrees'. It said
  // "radians: inf must be finite".
  auto reason = [](const std::string& degrees) {
    try {
      parse_scene(square_with(R"({"point": ["2", "1/2"], "normal": {"degrees": ")" + degrees +
                              R"("}, "mu": "0", "gap": "0"})"));
    } catch (const SceneError& e) {
      EXPECT_EQ(e.field(), "fixels[1].normal.degrees");
      const std::string what = e.what();
      return what.substr(what.find(" is not an exact direction"));
    }
    return std::string("accepted");
  };
  EXPECT_EQ(reason("1e400"), reason("280"));
  EXPECT_EQ(reason("-1e400"), reason("80"));
  EXPECT_NE(reason("280"), reason("80"));
}

// Loading polls a RunControl (task "load"): progress through the points,
// the simplicity check and the mass properties of a 3,000-edge outline, and
// a cancelled or expired control stops the load with StoppedError.
std::string many_edged_scene(int n) {
  std::string points;
  for (int i = 0; i < n; ++i) points += "[\"" + std::to_string(i) + "\", \"" + std::to_string(i * i) + "\"], ";
  return R"({"time_step": "1", "body": {"dof": 3, "boundary": [{"type": "polyline", "points": [)" + points +
         R"(["0", "0"]]}]}, "fixels": [{"point": ["1", "9"], "normal": ["1", "0"], "mu": "0", "gap": "0",
         "off_boundary": true}, {"point": ["2", "9"], "normal": ["0", "1"], "mu": "0", "gap": "0",
         "off_boundary": true}, {"point": ["3", "30"], "normal": ["-1", "0"], "mu": "0", "gap": "0",
         "off_boundary": true}]})";
}

GTEST_TEST(Scene, LoadingReportsProgressAndStopsWhenAsked) {
  const std::string text = many_edged_scene(3000);
  RunControl control;
  control.interval = std::chrono::milliseconds(0);
  control.start = RunControl::Clock::now() - std::chrono::seconds(1);
  std::set<std::string> units;
  long last_points = -1;
  control.on_progress = [&](const char* task, long done, long total, const char* unit) {
    EXPECT_STREQ(task, "load");
    units.insert(unit);
    if (std::string(unit) == "points read") {
      EXPECT_EQ(total, 3001);
      EXPECT_GT(done, last_points);
      last_points = done;
    }
  };
  const Scene scene = parse_scene(text, "many", &control);
  EXPECT_EQ(scene.body.boundary->pieces.size(), 3000u);
  EXPECT_EQ(units, (std::set<std::string>{"JSON documents parsed", "points read", "curves checked",
                                          "pieces checked for crossings", "pieces integrated (mass properties)"}));
  EXPECT_EQ(last_points, 2816);  // polled every 256 points

  RunControl expired;
  expired.deadline = RunControl::Clock::now();
  EXPECT_THROW(parse_scene(text, "many", &expired), StoppedError);
  RunControl cancelled;
  cancelled.cancel = true;
  try {
    parse_scene(text, "many", &cancelled);
    FAIL();
  } catch (const StoppedError& e) {
    EXPECT_EQ(e.reason(), StopReason::kInterrupted);
    EXPECT_NE(std::string(e.what()).find("load: interrupted after"), std::string::npos) << e.what();
  }
}

bool same(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
bool same(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(a[i], b[i])) return false;
  return true;
}

void expect_same_scene(const Scene& a, const Scene& b, const std::string& what) {
  EXPECT_EQ(a.name, b.name) << what;
  EXPECT_EQ(a.description, b.description) << what;
  EXPECT_EQ(a.time_step, b.time_step) << what;
  EXPECT_EQ(a.body.dof, b.body.dof) << what;
  EXPECT_EQ(a.body.mass, b.body.mass) << what;
  EXPECT_EQ(a.body.inertia, b.body.inertia) << what;
  EXPECT_EQ(a.body.mass_from_area, b.body.mass_from_area) << what;  // the values the outline gave stay derived
  EXPECT_EQ(a.body.inertia_from_area, b.body.inertia_from_area) << what;
  EXPECT_EQ(a.body.center_of_mass_from_area, b.body.center_of_mass_from_area) << what;
  EXPECT_EQ(a.body.velocity, b.body.velocity) << what;
  EXPECT_TRUE(same(a.body.p_AoCm_A, b.body.p_AoCm_A)) << what;
  ASSERT_EQ(a.body.boundary == nullptr, b.body.boundary == nullptr) << what;
  if (a.body.boundary) {
    const auto &ca = a.body.boundary->curves, &cb = b.body.boundary->curves;
    ASSERT_EQ(ca.size(), cb.size()) << what;
    for (std::size_t k = 0; k < ca.size(); ++k) {
      EXPECT_EQ(ca[k].type, cb[k].type) << what << " curve " << k;
      EXPECT_EQ(ca[k].degree, cb[k].degree) << what << " curve " << k;
      EXPECT_TRUE(same(ca[k].points, cb[k].points)) << what << " curve " << k;
      EXPECT_EQ(ca[k].knots, cb[k].knots) << what << " curve " << k;
    }
  }
  ASSERT_EQ(a.fixels.size(), b.fixels.size()) << what;
  for (std::size_t i = 0; i < a.fixels.size(); ++i) {
    EXPECT_TRUE(same(a.fixels[i].p_AoF_A, b.fixels[i].p_AoF_A)) << what << " fixel " << i;
    EXPECT_TRUE(same(a.fixels[i].n_A, b.fixels[i].n_A)) << what << " fixel " << i;
    EXPECT_EQ(a.fixels[i].mu, b.fixels[i].mu) << what << " fixel " << i;
    EXPECT_EQ(a.fixels[i].mu_hi, b.fixels[i].mu_hi) << what << " fixel " << i;
    EXPECT_EQ(a.fixels[i].gap, b.fixels[i].gap) << what << " fixel " << i;
    EXPECT_EQ(a.fixels[i].off_boundary, b.fixels[i].off_boundary) << what << " fixel " << i;
  }
  EXPECT_EQ(a.pusher_mu, b.pusher_mu) << what;
  EXPECT_EQ(a.pusher_mu_hi, b.pusher_mu_hi) << what;
  EXPECT_EQ(a.background_impulse, b.background_impulse) << what;
}

GTEST_TEST(WriteScene, EveryBundledSceneReadsBackTheSameAndWritesTheSameText) {
  for (const char* name : {"blob", "blob32", "example1", "example2", "example2_rounded", "fig6", "nonunique",
                           "nonunique_part", "polygon"}) {
    const Scene scene = test::scene_file(name);
    const std::string text = write_scene(scene);
    const Scene again = parse_scene(text, name);
    expect_same_scene(scene, again, name);
    EXPECT_EQ(write_scene(again), text) << name;
  }
  // polygon gives no mass, inertia or centre of mass: the text leaves them
  // out (the reader derives them again), as the bundled file does.
  const std::string polygon = write_scene(test::scene_file("polygon"));
  for (const char* key : {"\"mass\"", "\"inertia\"", "\"center_of_mass\""})
    EXPECT_EQ(polygon.find(key), std::string::npos) << key;
  EXPECT_NE(write_scene(test::scene_file("example2")).find("\"mass\""), std::string::npos);  // given there
  // with_derived writes them out: the same values, now as given.
  const Scene explicit_values = parse_scene(write_scene(test::scene_file("polygon"), true));
  EXPECT_EQ(explicit_values.body.mass, test::scene_file("polygon").body.mass);
  EXPECT_EQ(explicit_values.body.inertia, test::scene_file("polygon").body.inertia);
  EXPECT_FALSE(explicit_values.body.mass_from_area);
}

// The "derived" flags are plain fields: a mass, inertia or centre of mass
// set in code after loading is written (it was left out, and reading the
// file gave the outline's values back).
GTEST_TEST(WriteScene, AMassInertiaOrCentreOfMassSetAfterLoadingIsWrittenNotDerivedAgain) {
  const Scene loaded = test::scene_file("polygon");
  ASSERT_TRUE(loaded.body.mass_from_area && loaded.body.inertia_from_area && loaded.body.center_of_mass_from_area);
  Scene scene = loaded;
  scene.body.mass = Rational(2);
  scene.body.inertia = Rational(7, 3);
  scene.body.p_AoCm_A = {Rational(1, 7), Rational(-1, 9)};
  const Scene again = parse_scene(write_scene(scene), "edited");
  EXPECT_EQ(again.body.mass, Rational(2));
  EXPECT_EQ(again.body.inertia, Rational(7, 3));
  EXPECT_EQ(again.body.p_AoCm_A.x, Rational(1, 7));
  EXPECT_EQ(again.body.p_AoCm_A.y, Rational(-1, 9));
  EXPECT_FALSE(again.body.mass_from_area || again.body.inertia_from_area || again.body.center_of_mass_from_area);
  // Only the mass changed: the inertia the outline gave for mass 5 is no
  // longer what reading derives for mass 2, so it is written too; the
  // centre of mass is still the centroid and stays derived.
  Scene mass_only = loaded;
  mass_only.body.mass = Rational(2);
  const Scene back = parse_scene(write_scene(mass_only), "mass only");
  EXPECT_EQ(back.body.mass, Rational(2));
  EXPECT_EQ(back.body.inertia, loaded.body.inertia);
  EXPECT_FALSE(back.body.inertia_from_area);
  EXPECT_TRUE(back.body.center_of_mass_from_area);
}

// Friction intervals, off_boundary, a velocity and b0 survive the trip (the
// Python dict view once dropped the intervals' upper ends).
GTEST_TEST(WriteScene, FrictionIntervalsAndEveryOptionalFieldSurvive) {
  Scene scene = test::scene_file("polygon");
  scene.fixels[0].mu_hi = Rational(1, 2);
  scene.fixels[1].off_boundary = true;
  scene.pusher_mu = Rational(1, 10);
  scene.pusher_mu_hi = Rational(1, 5);
  scene.body.velocity = VectorQ::Zero(3);
  scene.body.velocity[2] = Rational(-1, 3);
  scene.background_impulse = VectorQ::Zero(3);
  scene.background_impulse[0] = Rational(7, 2);
  scene.description = "d\"quoted\"";
  const std::string text = write_scene(scene);
  EXPECT_NE(text.find(R"("mu": [)"), std::string::npos) << text;
  expect_same_scene(scene, parse_scene(text, "trip"), "trip");
}

GTEST_TEST(WriteScene, InvalidUtf8InANameSetInCodeIsReplacedNotThrown) {
  Scene scene = test::scene_file("example2");
  scene.name = std::string("bad\xff name");
  std::string text;
  ASSERT_NO_THROW(text = write_scene(scene));
  EXPECT_EQ(parse_scene(text).name, "bad\xef\xbf\xbd name");  // U+FFFD
}

GTEST_TEST(SaveScene, AFailedSaveLeavesTheEarlierFileWholeAndNamesThePath) {
  const std::string dir = testing::TempDir() + "fixel_save_scene_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/scene.json";
  const Scene polygon = test::scene_file("polygon");
  save_scene(polygon, path);
  expect_same_scene(polygon, load_scene(path), "saved");
  // The write fails half-way (a file-size limit of 1 KiB, as a full disk
  // would): the earlier file stays as it was, and the error names the path.
  const pid_t pid = fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);  // EFBIG instead of the signal
    const rlimit limit{1024, 1024};
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(3);
    try {
      save_scene(test::scene_file("example2_rounded"), path);
      _exit(1);
    } catch (const InputError& e) {
      _exit(std::string(e.what()) == "save_scene(path): " + path + " could not be written completely (File too large)"
                ? 0
                : 2);
    }
  }
  int status = -1;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  expect_same_scene(polygon, load_scene(path), "kept");
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().rfind(".fixel-", 0), std::string::npos) << e.path();
  EXPECT_THROW(save_scene(polygon, dir + "/no such folder/scene.json"), InputError);
  // Through a symbolic link: the link stays, its target gets the scene.
  std::filesystem::create_symlink(path, dir + "/link.json");
  save_scene(test::scene_file("example2"), dir + "/link.json");
  EXPECT_TRUE(std::filesystem::is_symlink(dir + "/link.json"));
  expect_same_scene(test::scene_file("example2"), load_scene(path), "through the link");
  EXPECT_THROW(save_scene(polygon, dir), InputError);  // a folder
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fixel
