// The physics check on Box2D. Runs are short (a few h); longer studies are
// in bench/physics_bench.cpp. Engine results are measurements, so tolerances
// appear only where the issue allows them (the t = 0 mapping).
#include "fixel/physics.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "fixel/error.h"
#include "fixel/progress.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "other_scene_region.h"
#include "test_util.h"

namespace fixel::physics {
namespace {

// A 2 × 2 square about the origin: two fixels on its left side, one below.
Scene square(const std::string& gaps = R"("1/20", "1/20", "1/10")") {
  const std::string text = R"({"name": "square", "time_step": "1",
    "body": {"dof": 3, "mass": "1", "velocity": ["0","0","0"],
      "boundary": [{"type": "polyline", "points": [["-1","-1"],["1","-1"],["1","1"],["-1","1"],["-1","-1"]]}]},
    "fixels": [{"point": ["-1","1/2"], "normal": ["1","0"], "mu": "1/10", "gap": "G0"},
               {"point": ["-1","-1/2"], "normal": ["1","0"], "mu": "1/10", "gap": "G1"},
               {"point": ["1/2","-1"], "normal": ["0","1"], "mu": "1/10", "gap": "G2"}]})";
  std::string s = text;
  std::vector<std::string> g;
  std::string rest = gaps;
  for (std::size_t pos; (pos = rest.find('"')) != std::string::npos;) {
    const auto end = rest.find('"', pos + 1);
    g.push_back(rest.substr(pos + 1, end - pos - 1));
    rest = rest.substr(end + 1);
  }
  for (int i = 0; i < 3; ++i) s.replace(s.find("G" + std::to_string(i)), 2, g[i]);
  return parse_scene(s);
}

PushOptions short_run(const char* T = "3") {
  PushOptions o;
  o.time = parse_rational(T);
  return o;
}

// Euclidean distance from f_i to the exact curve, by dense sampling with
// exact point evaluation (independent of the engine's polygon).
double curve_distance(const Scene& scene, int i) {
  const Fixel& f = scene.fixels[i];
  const double fx = to_double(f.p_AoF_A.x - f.gap * f.n_A.x), fy = to_double(f.p_AoF_A.y - f.gap * f.n_A.y);
  double best = INFINITY;
  for (const auto& piece : scene.body.boundary->pieces) {
    auto d = [&](const Rational& s) {
      const Vec2 p = piece.point(s);
      return std::hypot(to_double(p.x) - fx, to_double(p.y) - fy);
    };
    constexpr int kN = 400;
    int k_best = 0;
    for (int k = 1; k <= kN; ++k)
      if (d(Rational(k, kN)) < d(Rational(k_best, kN))) k_best = k;
    Rational lo(std::max(0, k_best - 1), kN), hi(std::min(kN, k_best + 1), kN);
    for (int it = 0; it < 40; ++it) {
      const Rational a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
      if (d(a) < d(b))
        hi = b;
      else
        lo = a;
      lo = Rational(to_double(lo)), hi = Rational(to_double(hi));  // keep the numbers short
    }
    best = std::min(best, d(lo));
  }
  return best;
}

GTEST_TEST(Physics, AtTimeZeroEachFixelIsItsGapAwayFromTheEnginePart) {
  // The square's normals are its edge normals, so the distance is ψ_i; the
  // blob's normals are rational roundings, so it is the distance to the curve.
  const Scene sq = square();
  const double sq_size = part_polygon(sq).size;
  const auto sq_gaps = initial_engine_gaps(sq);
  for (std::size_t i = 0; i < sq_gaps.size(); ++i)
    EXPECT_NEAR(sq_gaps[i], to_double(sq.fixels[i].gap), 1e-6 * sq_size) << "square fixel " << i;
  const Scene blob = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/blob.json");
  const double size = part_polygon(blob).size;
  const auto gaps = initial_engine_gaps(blob);
  ASSERT_EQ(gaps.size(), blob.fixels.size());
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    EXPECT_NEAR(gaps[i], curve_distance(blob, static_cast<int>(i)), 1e-6 * size) << "blob fixel " << i;
    EXPECT_NEAR(gaps[i], to_double(blob.fixels[i].gap), 1e-4 * size) << "blob fixel " << i;
  }
}

GTEST_TEST(Physics, BSplinePolygonStaysWithinTheChordalTolerance) {
  const Scene blob = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/blob.json");
  const PartPolygon p = part_polygon(blob);
  EXPECT_LT(p.chordal_tolerance, 1e-4 * p.size);
  EXPECT_GT(p.pieces.size(), 0u);
}

GTEST_TEST(Physics, SquarePushedStraightIntoItsFixelsEndsSeated) {
  const PushResult r = push(square(), Wrench{-2, -1, 0}, short_run());
  EXPECT_EQ(r.outcome, Outcome::kSeated);
  ASSERT_TRUE(r.time_to_seat.has_value());
  for (double g : r.final_gaps) EXPECT_LT(g, r.gap_tolerance);
  EXPECT_EQ(r.contacts_at_rest.size(), 3u);
  EXPECT_LE(r.dt, 1.0 / 1000);
  EXPECT_LE(0.005 / r.length_scale, 1e-4 * r.part_size);  // b2_linearSlop in metres
}

GTEST_TEST(Physics, ImpulseThatClosesTheGapsInOneStepDoesSoByTimeH) {
  // Left gaps 1/20, bottom gap 1/10, m = 1, h = 1: ν⁺ = (−1/20, −1/10, 0).
  PushOptions once = short_run("1");
  once.stop_at_outcome = false;
  once.impulse = std::array<double, 3>{-0.05, -0.1, 0};
  const PushResult r = push(square(), Wrench{}, once);
  for (double g : r.final_gaps) EXPECT_LT(std::abs(g), r.gap_tolerance);
}

GTEST_TEST(Physics, PureMomentDoesNotSeatTheSquare) {
  const PushResult r = push(square(), Wrench{0, 0, 1}, short_run());
  EXPECT_NE(r.outcome, Outcome::kSeated);
}

GTEST_TEST(Physics, PushAwayFromTheFixelsEscapes) {
  const PushResult r = push(square(), Wrench{1, 1, 0}, short_run());
  EXPECT_EQ(r.outcome, Outcome::kEscaped);
}

GTEST_TEST(Physics, SameRunGivesTheSameOutcomeTwice) {
  const Scene s = square();
  const PushResult a = push(s, Wrench{-1, -0.4, 0.1}, short_run());
  const PushResult b = push(s, Wrench{-1, -0.4, 0.1}, short_run());
  EXPECT_EQ(a.outcome, b.outcome);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.final_pose.theta, b.final_pose.theta);
}

GTEST_TEST(Physics, HalvingTheTimeStepChangesNoOutcomeOnFiftyPushes) {
  const Scene s = square();
  PushOptions coarse = short_run(), fine = short_run();
  fine.steps_per_h = 2 * coarse.steps_per_h;
  coarse.trajectory_samples = fine.trajectory_samples = 1;
  int seated = 0, jammed = 0;
  for (int k = 0; k < 50; ++k) {
    // Force directions facing the fixels and beyond, with a small alternating
    // moment: a mix of seated, jammed, escaped and timeout.
    const double a = M_PI - 0.6 + (M_PI / 2 + 1.2) * (k + 0.5) / 50;
    const Wrench w{2 * std::cos(a), 2 * std::sin(a), (k % 2 ? 0.1 : -0.1)};
    const Outcome o = push(s, w, coarse).outcome;
    EXPECT_EQ(to_string(o), to_string(push(s, w, fine).outcome)) << "push " << k;
    seated += o == Outcome::kSeated;
    jammed += o == Outcome::kJammed;
  }
  EXPECT_GT(seated, 0);  // not a vacuous comparison
  EXPECT_GT(jammed, 0);
}

GTEST_TEST(Physics, BadInputsThrowTypedErrors) {
  const Scene s = square();
  EXPECT_THROW(push(s, Wrench{-1, -1, 0}, short_run("0")), InputError);
  EXPECT_THROW(push(s, Wrench{-1, -1, 0}, short_run("-1")), InputError);
  EXPECT_THROW(parse_wrench("1,2", 3), InputError);
  EXPECT_THROW(push(s, Wrench{1e200, 0, 0}, short_run()), InputError);
  EXPECT_THROW(parse_wrench("1,x,2", 3), ParseError);
  EXPECT_THROW(parse_curve_point(s, "0:5"), InputError);
  EXPECT_THROW(parse_curve_point(s, "3:0"), InputError);
  EXPECT_THROW(parse_curve_point(s, "zero"), ParseError);
  const auto point = parse_curve_point(s, "0:1/2");
  EXPECT_EQ(point.curve, 0);
  EXPECT_EQ(point.u, Rational(1, 2));
  const Scene no_boundary = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/example2.json");
  EXPECT_THROW(push(no_boundary, Wrench{-1, -1, 0}, short_run()), SceneError);
  // A closed, counter-clockwise loop that crosses itself.
  const std::string bow = R"({"name": "bow", "time_step": "1", "body": {"dof": 3, "mass": "1",
    "velocity": ["0","0","0"], "boundary": [{"type": "polyline",
    "points": [["0","0"],["4","0"],["4","3"],["1","3"],["1","-1"],["0","0"]]}]},
    "fixels": [{"point": ["4","1"], "normal": ["-1","0"], "mu": "0", "gap": "0"},
               {"point": ["3","3"], "normal": ["0","-1"], "mu": "0", "gap": "0"},
               {"point": ["2","0"], "normal": ["0","1"], "mu": "0", "gap": "0"}]})";
  try {  // rejected when the scene is read or when it is polygonised
    push(parse_scene(bow), Wrench{-1, 0, 0}, short_run());
    ADD_FAILURE() << "a self-intersecting part was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("body.boundary"), std::string::npos) << e.what();
  }
}

// An impulse of NaN or 1e300 ran (its velocity change an undefined float
// conversion) and was reported as a timeout; solver iterations <= 0 went to
// Box2D as they came.
GTEST_TEST(Physics, ANonFiniteOrHugeImpulseAndNonPositiveSolverIterationsAreInputErrors) {
  const Scene s = square();
  for (const double bad : {std::nan(""), 1e300, -HUGE_VAL}) {
    PushOptions o = short_run();
    o.impulse = std::array<double, 3>{0, bad, 0};
    try {
      push(s, Wrench{-1, -1, 0}, o);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "PushOptions.impulse");
    }
  }
  for (const int bad : {0, -5, kMaxSolverIterations + 1}) {
    PushOptions o = short_run();
    o.velocity_iterations = bad;
    EXPECT_THROW(push(s, Wrench{-1, -1, 0}, o), InputError) << bad;
    o = short_run();
    o.position_iterations = bad;
    EXPECT_THROW(push(s, Wrench{-1, -1, 0}, o), InputError) << bad;
  }
}

// validate_region checks the engine settings before its first push, so a
// region with no IN interval (no push at all) refuses them too; every push
// reports the settings it ran with.
GTEST_TEST(Physics, ValidatingARegionWithoutAnInIntervalStillRefusesBadEngineSettingsAndTheStepLimit) {
  const Scene s = square();
  const Region none;  // no interval, so nothing to push
  const PushModel model = [](const RegionInterval&, const Rational&) { return Wrench{-1, -1, 0}; };
  // The field and value of the InputError validating `o` throws ("" if none).
  auto refusal = [&](const PushOptions& o) -> std::pair<std::string, std::string> {
    try {
      validate_region(s, none, model, 1, 1, o);
    } catch (const InputError& e) {
      return {e.field(), e.value()};
    }
    return {"", ""};
  };
  PushOptions o = short_run();
  EXPECT_EQ(validate_region(s, none, model, 1, 1, o).total.pushes, 0);
  o.steps_per_h = 999;
  EXPECT_EQ(refusal(o), std::make_pair(std::string("PushOptions.steps_per_h"), std::string("999")));
  o = short_run();
  o.position_iterations = 0;
  EXPECT_EQ(refusal(o).first, "PushOptions.position_iterations");
  // The step limit too: T·steps_per_h ≤ kMaxPushSteps, named by the steps per h that broke it.
  o = short_run();
  o.steps_per_h = kMaxPushSteps / 2;
  o.time = 3;
  EXPECT_EQ(refusal(o).first, "PushOptions.steps_per_h");
  o.steps_per_h = PushOptions{}.steps_per_h;
  o.time = Rational(kMaxPushSteps / PushOptions{}.steps_per_h + 1);
  EXPECT_EQ(refusal(o).first, "PushOptions.time");
  o = short_run();
  o.steps_per_h = 3000;
  o.velocity_iterations = 7;
  o.position_iterations = 9;
  const PushResult r = push(s, Wrench{-1, -1, 0}, o);
  EXPECT_EQ(r.steps_per_h, 3000);
  EXPECT_EQ(r.velocity_iterations, 7);
  EXPECT_EQ(r.position_iterations, 9);
}

// A Boundary assembled by hand, not by make_boundary, segfaulted in the
// polygoniser; every analysis's value check now names it.
GTEST_TEST(Physics, AHandAssembledBoundaryWithoutPiecesIsASceneError) {
  Scene s = square();
  auto empty = std::make_shared<Boundary>();
  s.body.boundary = empty;
  EXPECT_THROW(push(s, Wrench{-1, -1, 0}, short_run()), SceneError);
  EXPECT_THROW(validate_scene(s), SceneError);
  auto no_pieces = std::make_shared<Boundary>(*square().body.boundary);
  no_pieces->pieces.clear();
  s.body.boundary = no_pieces;
  try {
    validate_scene(s);
    ADD_FAILURE() << "a boundary without pieces was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("make_boundary"), std::string::npos) << e.what();
  }
  EXPECT_THROW(compute_region(s, seating_set(square()), RegionOptions{}), SceneError);
  auto one_curve_bare = std::make_shared<Boundary>(*square().body.boundary);
  one_curve_bare->curves.push_back(one_curve_bare->curves.front());  // a second curve with no pieces
  s.body.boundary = one_curve_bare;
  EXPECT_THROW(check_scene_values(s), SceneError);
}

// The thresholds are tied to h and dt: a push far slower than h (a "jammed"
// that was a slow seat) or far faster than dt (under-resolved) warns. The
// square: m = 1 kg, bounding-box diagonal 2√2 m, h = 1 s, dt = 1 ms, so a
// force F has the time scale √(2√2/F) s (by hand).
GTEST_TEST(Physics, APushFarSlowerThanHOrFasterThanTheEngineStepWarns) {
  const Scene s = square();
  const auto run = [&](double force) { return push(s, Wrench{-force, 0, 0}, short_run("1/100")); };
  const PushResult usual = run(1);
  EXPECT_NEAR(usual.time_scale, std::sqrt(2 * std::sqrt(2.0)), 1e-9);  // display value, not a decision
  EXPECT_TRUE(usual.warnings.empty());
  const PushResult slow = run(1e-3);  // √(2828) ≈ 53 s > 10 h
  ASSERT_EQ(slow.warnings.size(), 1u);
  EXPECT_NE(slow.warnings[0].find("over 10 h"), std::string::npos) << slow.warnings[0];
  const PushResult fast = run(1e5);  // √(2.8e-5) ≈ 5.3 ms: about 5 engine steps
  ASSERT_EQ(fast.warnings.size(), 1u);
  EXPECT_NE(fast.warnings[0].find("engine steps"), std::string::npos) << fast.warnings[0];
  // A moment alone: √(I/|M|) with I = 2/3 kg·m² (the square's, about its centre).
  const PushResult turn = push(s, Wrench{0, 0, 1}, short_run("1/100"));
  EXPECT_NEAR(turn.time_scale, std::sqrt(2.0 / 3.0), 1e-9);
  EXPECT_NE(push_text(s, Wrench{-1e-3, 0, 0}, slow).find("warning: the push's time scale"), std::string::npos);
  // Nothing to seat against: said, not left to a bare "timeout".
  Scene bare = s;
  bare.fixels.clear();
  const PushResult alone = push(bare, Wrench{-1, 0, 0}, short_run("1/100"));
  ASSERT_EQ(alone.warnings.size(), 1u);
  EXPECT_NE(alone.warnings[0].find("no fixels"), std::string::npos) << alone.warnings[0];
}

// The user's value is shown, with the engine's scaled one beside it.
GTEST_TEST(Physics, AWrenchTooLargeForTheEngineIsShownAsGiven) {
  try {
    push(square(), Wrench{1e29, 0, 0}, short_run());
    ADD_FAILURE() << "a wrench beyond the engine's floats ran";
  } catch (const InputError& e) {
    EXPECT_EQ(e.value(), "1e+29");
    EXPECT_NE(std::string(e.what()).find("engine units"), std::string::npos) << e.what();
  }
}

GTEST_TEST(Physics, APushOfMoreThanTheStepLimitIsRefusedNamingItsTime) {
  const Scene s = square();
  // 10^5 h at 1000 steps per h is the limit itself; one more step is over.
  PushOptions o = short_run();
  o.time = Rational(kMaxPushSteps, 1000) + Rational(1, 1000);
  try {
    push(s, Wrench{0, 0, 0}, o);
    ADD_FAILURE() << "a push of more than kMaxPushSteps steps ran";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "PushOptions.time");
    EXPECT_NE(std::string(e.what()).find("100000001 engine steps"), std::string::npos) << e.what();
  }
  // Far beyond a long: once turned into a step count without the check, it was undefined behaviour.
  o.time = Rational(Integer(10) * (Integer(1) << 80));
  EXPECT_THROW(push(s, Wrench{0, 0, 0}, o), InputError);
}

GTEST_TEST(Physics, APushStopsWhenItsControlIsCancelledOrPastItsDeadline) {
  const Scene s = square();
  PushOptions o = short_run();
  o.time = 100000;  // 10^8 steps of a part at rest: minutes, unless stopped
  RunControl cancelled;
  cancelled.cancel = true;
  o.control = &cancelled;
  try {
    push(s, Wrench{0, 0, 0}, o);
    ADD_FAILURE() << "a cancelled push ran";
  } catch (const StoppedError& e) {
    EXPECT_EQ(e.reason(), StopReason::kInterrupted);
    EXPECT_EQ(e.done(), 0);
    EXPECT_EQ(e.total(), kMaxPushSteps);
  }
  RunControl timed;
  timed.deadline = RunControl::Clock::now() + std::chrono::milliseconds(200);
  o.control = &timed;
  try {
    push(s, Wrench{0, 0, 0}, o);
    ADD_FAILURE() << "a push ran past its deadline";
  } catch (const StoppedError& e) {
    EXPECT_EQ(e.reason(), StopReason::kTimeLimit);
    EXPECT_GT(e.done(), 0);
    EXPECT_LT(e.done(), kMaxPushSteps);
  }
}

GTEST_TEST(Physics, UnitPushWrenchAtAPointHasTheNormalAndItsMoment) {
  const Scene s = square();
  // Bottom edge u ∈ [0, 1] at u = 3/4: point (1/2, −1), inward normal (0, 1).
  const Wrench w = push_wrench_at(s, 0, parse_rational("3/4"), Pose{});
  EXPECT_DOUBLE_EQ(w.fx, 0);
  EXPECT_DOUBLE_EQ(w.fy, 1);
  EXPECT_DOUBLE_EQ(w.m, 0.5);
  const Wrench r = push_wrench_at(s, 0, parse_rational("3/4"), Pose{0, 0, M_PI / 2});
  EXPECT_NEAR(r.fx, -1, 1e-15);
  EXPECT_DOUBLE_EQ(r.m, 0.5);
}

GTEST_TEST(Physics, APushWrenchAtANonFinitePoseNamesThePose) {
  try {
    push_wrench_at(square(), 0, Rational(1, 2), Pose{0, 0, std::nan("")});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "pose.theta");  // it blamed the scene and --at
  }
}

// The model read S's apex and magnitudes against any scene's outline.
GTEST_TEST(Physics, TheOneStepPushModelRefusesAnSOfAnotherSceneNamingS) {
  const test::SetCheckScenes s = test::set_check_scenes();
  const SeatingSet S = seating_set(s.scene);
  const std::string e = test::input_error_of([&] { one_step_push_model(s.gapped, S, Rational(0)); });
  EXPECT_EQ(e.rfind("S: ", 0), 0u) << e;
  EXPECT_EQ(test::input_error_of([&] { one_step_push_model(s.scene, S, Rational(0)); }), "(no InputError)");
}

GTEST_TEST(Physics, ValidationRefusesARegionOfAnotherSceneNamingIt) {
  const Scene polygon = test::scene_file("polygon");
  const Region region = test::rounded_region();
  const std::string e =
      test::input_error_of([&] { validate_region(polygon, region, seated_push_model(polygon), 1, 1, short_run("2")); });
  EXPECT_EQ(e.rfind("region: ", 0), 0u) << e;
}

// blob32's one-step pushes are 4.55 engine steps long: every one warns, so
// the seated ones that warned are all the seated ones.
GTEST_TEST(Physics, ValidationCountsTheSeatedPushesThatWarned) {
  const Scene s = test::scene_file("blob32");
  const SeatingSet S = seating_set(s);
  RegionOptions ro;
  ro.resolution = Rational(1, 256);
  const Region region = compute_region(s, S, ro);
  const RegionValidation v = validate_region(s, region, one_step_push_model(s, S, s.pusher_mu), 4, 1, short_run("2"));
  ASSERT_GT(v.total.seated, 0);  // else the equality below says nothing
  EXPECT_EQ(v.total.warned, v.total.pushes);
  EXPECT_EQ(v.total.seated_warned, v.total.seated);
  int seated_warned = 0;
  for (const auto& i : v.intervals)
    if (i) seated_warned += i->seated_warned;
  EXPECT_EQ(seated_warned, v.total.seated_warned);
}

GTEST_TEST(Physics, ValidationRunsEveryPushOfEveryInIntervalAndNoneOfAnOutOne) {
  const Scene s = square(R"("0", "0", "0")");
  Region region;
  RegionInterval in;
  in.curve = 0, in.u0 = parse_rational("1/4"), in.u1 = parse_rational("3/4"), in.status = RegionStatus::kIn;
  RegionInterval out = in;
  out.u0 = 1, out.u1 = 2, out.status = RegionStatus::kOut;
  region.intervals = {in, out};
  // Pushing up on the bottom edge lifts the part off its bottom fixel.
  const RegionValidation v = validate_region(s, region, seated_push_model(s, 2), 3, 7, short_run("2"));
  ASSERT_EQ(v.intervals.size(), 2u);
  ASSERT_TRUE(v.intervals[0].has_value());
  EXPECT_FALSE(v.intervals[1].has_value());
  EXPECT_EQ(v.total.pushes, 3);
  EXPECT_EQ(v.total.seated, 0);
  EXPECT_THROW(validate_region(s, region, seated_push_model(s), 0, 7), InputError);
  for (const double force : {0.0, -1.0, std::nan(""), HUGE_VAL})  // a negative force pulled the part
    EXPECT_THROW(seated_push_model(s, force), InputError) << force;
}

GTEST_TEST(Physics, AStoppedValidationSaysHowManyOfItsPushesRan) {
  const Scene s = square(R"("0", "0", "0")");
  Region region;
  RegionInterval in;
  in.curve = 0, in.u0 = parse_rational("1/4"), in.u1 = parse_rational("3/4"), in.status = RegionStatus::kIn;
  region.intervals = {in, in};  // two IN intervals of 1000 pushes each: 2000 in all
  PushOptions o = short_run("2");
  RunControl cancelled;
  cancelled.cancel = true;
  o.control = &cancelled;
  try {
    validate_region(s, region, seated_push_model(s, 2), 1000, 7, o);
    ADD_FAILURE() << "a cancelled validation ran";
  } catch (const StoppedError& e) {
    EXPECT_EQ(std::string(e.what()), "validate: interrupted after 0 of 2000 pushes; no result");
    EXPECT_EQ(e.total(), 2000);
  }
  // Stopped inside a push (at its first poll): the push's own stop is reported as the validation's.
  RunControl timed;
  timed.deadline = RunControl::Clock::now() + std::chrono::milliseconds(100);
  o.control = &timed;
  try {
    validate_region(s, region, seated_push_model(s, 2), 1000, 7, o);
    ADD_FAILURE() << "a validation ran past its deadline";
  } catch (const StoppedError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("validate: time limit reached after ", 0), 0u) << e.what();
    EXPECT_EQ(e.reason(), StopReason::kTimeLimit);
    EXPECT_LT(e.done(), 2000);
    EXPECT_EQ(e.total(), 2000);
  }
}

// A scene built in code with a massless part once ran: Box2D took it for a
// static body. The engine's input is checked like any analysis's.
GTEST_TEST(Physics, AHandBuiltSceneWithABadValueIsASceneErrorAndANonFiniteWrenchIsShown) {
  Scene massless = square();
  massless.body.mass = 0;
  try {
    push(massless, Wrench{1, 0, 0});
    ADD_FAILURE() << "a massless part was pushed";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.field(), "body.mass");
  }
  try {
    push(square(), Wrench{std::nan(""), 0, 0});
    ADD_FAILURE() << "a NaN wrench was pushed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "push(wrench)");
    EXPECT_EQ(e.value(), "(nan, 0, 0)");
  }
}

// A comb of 5,002 vertices: the bottom edge, then a zigzag top from right
// to left. Past 4,096 vertices the partition is Greene's sweep (Hertel–
// Mehlhorn grew as n²: 24.8 s at 40,000). Its pieces must tile the outline
// exactly: convex, made of outline vertices, and of the outline's area,
// summed in exact rationals from the doubles the engine gets.
GTEST_TEST(PartPolygon, ALargeOutlineIsSplitIntoConvexPiecesThatTileItExactly) {
  constexpr int kTeeth = 5000;
  std::string points = R"(["0","0"],[")" + std::to_string(kTeeth) + R"(","0"])";
  for (int i = kTeeth; i >= 0; --i) points += R"(,[")" + std::to_string(i) + R"(",")" + (i % 2 ? "3/2" : "1") + R"("])";
  points += R"(,["0","0"])";
  const Scene comb = parse_scene(R"({"name": "comb", "time_step": "1", "body": {"dof": 3, "mass": "1",
      "boundary": [{"type": "polyline", "points": [)" +
                                 points + R"(]}]},
      "fixels": [{"point": ["1/4","0"], "normal": ["0","1"], "mu": "0", "gap": "0"},
                 {"point": ["4999","0"], "normal": ["0","1"], "mu": "0", "gap": "0"},
                 {"point": ["0","1/2"], "normal": ["1","0"], "mu": "0", "gap": "0"}]})");
  const PartPolygon part = part_polygon(comb);
  ASSERT_GE(part.outline.size(), 4096u);
  auto q = [](double x) { return Rational(x); };  // exact: every double is a rational
  auto area = [&](const std::vector<std::array<double, 2>>& v) {
    Rational twice = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const auto &a = v[k], &b = v[(k + 1) % v.size()];
      twice += q(a[0]) * q(b[1]) - q(b[0]) * q(a[1]);
    }
    return twice / 2;
  };
  std::set<std::array<double, 2>> vertices(part.outline.begin(), part.outline.end());
  Rational pieces_area = 0;
  for (const auto& piece : part.pieces) {
    ASSERT_GE(piece.size(), 3u);
    for (std::size_t k = 0; k < piece.size(); ++k) {
      const auto &a = piece[k], &b = piece[(k + 1) % piece.size()], &c = piece[(k + 2) % piece.size()];
      EXPECT_GE((q(b[0]) - q(a[0])) * (q(c[1]) - q(a[1])) - (q(b[1]) - q(a[1])) * (q(c[0]) - q(a[0])), 0);
      EXPECT_TRUE(vertices.count(a)) << a[0] << ", " << a[1];
    }
    pieces_area += area(piece);
  }
  EXPECT_EQ(pieces_area, area(part.outline));
  EXPECT_EQ(area(part.outline), Rational(kTeeth) + Rational(kTeeth, 4));  // by hand: 5000 × 1 plus 5000 half-unit teeth
}

// The push SVG draws the push: an arrow along the force's line of action,
// ending where that line enters the part. For F = (1, 0) and moment -1/2 on
// the square (centre of mass at the origin) the line is y = 1/2 (r × F =
// -y = m), which enters at the left side's (-1, 1/2): fixel 0's height,
// 1/20 right of fixel 0 (drawn at x = -21/20).
GTEST_TEST(Physics, ThePushSvgDrawsTheForceEndingWhereItsLineEntersThePart) {
  const Scene sq = square();
  const Wrench w{1, 0, -0.5};
  const PushResult r = push(sq, w, short_run("1/10"));
  const std::string path = testing::TempDir() + "fixel_push_arrow.svg";
  write_push_svg(path, sq, r, &w);
  std::ifstream in(path);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      svg, m, std::regex(R"re(<line x1="([-0-9.e]+)" y1="([-0-9.e]+)" x2="([-0-9.e]+)" y2="([-0-9.e]+)")re")));
  const double x1 = std::stod(m[1]), y1 = std::stod(m[2]), x2 = std::stod(m[3]), y2 = std::stod(m[4]);
  std::vector<std::array<double, 2>> fixel;  // the fixels' dots, in order
  const std::regex dot(R"re(<circle cx="([-0-9.e]+)" cy="([-0-9.e]+)" r="3" fill="black"/>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), dot); it != std::sregex_iterator(); ++it)
    fixel.push_back({std::stod((*it)[1]), std::stod((*it)[2])});
  ASSERT_EQ(fixel.size(), 3u);
  // The picture maps x and y affinely: fixel 0 is at x = -21/20, fixel 2 at x = 1/2.
  const double x_at_minus_1 = fixel[0][0] + (fixel[2][0] - fixel[0][0]) * (1.0 / 20) / (31.0 / 20);
  const double pixel = 1e-3;  // printed with 6 significant digits: display, not a decision
  EXPECT_NEAR(x2, x_at_minus_1, pixel);
  EXPECT_NEAR(y2, fixel[0][1], pixel);
  EXPECT_NEAR(y1, y2, pixel);  // horizontal, pointing right (+x)
  EXPECT_LT(x1, x2);
  EXPECT_NE(svg.find("magenta: the push (1, 0, -0.5)"), std::string::npos);
  const Wrench moment{0, 0, 1};
  write_push_svg(path, sq, r, &moment);
  std::ifstream again(path);
  const std::string pure((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>());
  EXPECT_EQ(pure.find("<line"), std::string::npos);
  EXPECT_NE(pure.find("the push (0, 0, 1) is a pure moment"), std::string::npos);
  // A near-pure moment: its line passes 10^6 m away. Fitting it in would
  // shrink the part to a dot, so it is told, not drawn.
  const Wrench far{1e-6, 0, 1};
  write_push_svg(path, sq, r, &far);
  std::ifstream far_in(path);
  const std::string far_svg((std::istreambuf_iterator<char>(far_in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(far_svg.find("<line"), std::string::npos);
  EXPECT_NE(far_svg.find("its line of action passes 1e+06 m from the centre of mass, off the picture"),
            std::string::npos);
  std::vector<double> xs;  // the part still spans the picture (640 px wide, 20 px margins)
  for (auto it = std::sregex_iterator(far_svg.begin(), far_svg.end(), dot); it != std::sregex_iterator(); ++it)
    xs.push_back(std::stod((*it)[1]));
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_GT(*std::max_element(xs.begin(), xs.end()) - *std::min_element(xs.begin(), xs.end()), 100);
}

}  // namespace
}  // namespace fixel::physics
