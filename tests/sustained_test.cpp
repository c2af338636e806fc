#include "fixel/sustained.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <random>
#include <sstream>

#include "filter_test_util.h"
#include "fixel/approach.h"
#include "fixel/cone.h"
#include "fixel/error.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/internal/sustained_core.h"
#include "fixel/io.h"
#include "fixel/physics.h"
#include "fixel/progress.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/scene_json.h"
#include "fixel/seat_report.h"
#include "fixel/seating.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::random_rational;
using test::scene_file;
using test::v3;

const Rational kHair = parse_rational("1e-30");

// The square [−1, 1]² (centre of mass at the origin) with fixels on the
// left edge at (−1, y0) and on the bottom edge at (x1, −1) and (x2, −1).
std::string square_scene(const std::string& mu, const std::string& gaps_json, const std::string& y0 = "0",
                         const std::string& x1 = "-1/2", const std::string& x2 = "1/2") {
  std::istringstream g(gaps_json);
  std::string g0, g1, g2;
  g >> g0 >> g1 >> g2;
  return R"({"name": "square", "time_step": "1",
    "body": {"dof": "3", "mass": "1", "center_of_mass": ["0", "0"],
             "boundary": [{"type": "polyline", "points": [["-1","-1"], ["1","-1"], ["1","1"], ["-1","1"], ["-1","-1"]]}]},
    "fixels": [
      {"point": ["-1", ")" +
         y0 + R"("], "normal": ["1", "0"], "mu": )" + mu + R"(, "gap": ")" + g0 + R"("},
      {"point": [")" +
         x1 + R"(", "-1"], "normal": ["0", "1"], "mu": )" + mu + R"(, "gap": ")" + g1 + R"("},
      {"point": [")" +
         x2 + R"(", "-1"], "normal": ["0", "1"], "mu": )" + mu + R"(, "gap": ")" + g2 + R"("}]})";
}

Scene square(const std::string& mu = "\"1/10\"", const std::string& gaps = "0 0 0") {
  return parse_scene(square_scene(mu, gaps));
}

// W_n of a scene, computed here from its definition (gaps 0: q* = 0).
MatrixQ normal_matrix(const Scene& scene) {
  MatrixQ Wn(3, 3);
  for (int i = 0; i < 3; ++i) {
    const Vec2 r = scene.lever_arm(i), n = scene.fixels[i].n_A;
    Wn.col(i) = v3(n.x, n.y, r.x * n.y - r.y * n.x);
  }
  return Wn;
}

// A wrench w with −w = W_n λ, λ random and positive: inside the cone of (a).
VectorQ random_inward_wrench(std::mt19937_64& rng, const MatrixQ& Wn) {
  return -(Wn * v3(random_rational(rng, 0, 2, 16), random_rational(rng, 0, 2, 16), random_rational(rng, 0, 2, 16)));
}

// −w ∈ int cone(W_n) by an independent exact solve (rational W_n: gaps 0).
bool in_open_normal_cone(const Scene& scene, const VectorQ& w) {
  const MatrixQ Wn = normal_matrix(scene);
  const VectorQ lambda = internal::exact_lu(Wn).solve(VectorQ(-w));
  for (int i = 0; i < 3; ++i)
    if (lambda[i] <= 0) return false;
  return true;
}

GTEST_TEST(SeatedPose, IsTheSceneFrameWhenEveryGapIsZero) {
  const SeatedPose q = seated_pose(square());
  EXPECT_TRUE(q.at_scene_pose);
  ASSERT_TRUE(q.exact.has_value());
  EXPECT_EQ((*q.exact)[2].a, 1);
  EXPECT_EQ((*q.exact)[3].a, 0);
}

// Hand-built: the square turned by cos θ = 24/25, sin θ = 7/25 and moved by
// t = (−1/10, −1/5) puts its points (−1/2, −1), (1/2, −1), (−1, 0) at
// f = (−3/10, −13/10), (33/50, −51/50), (−53/50, −12/25). The scene puts
// the same fixels at gaps 3/10, 1/50 and 3/50 from the unmoved square.
GTEST_TEST(SeatedPose, RecoversAHandBuiltRotationExactly) {
  const Scene scene = parse_scene(square_scene("\"0\"", "3/50 3/10 1/50", "-12/25", "-3/10", "33/50"));
  const SeatedPose q = seated_pose(scene);
  ASSERT_TRUE(q.exact.has_value());
  const auto& e = *q.exact;
  for (const auto& v : e) EXPECT_EQ(v.b, 0) << "expected rational values, got " << v.text();
  EXPECT_EQ(e[0].a, Rational(-1, 10));
  EXPECT_EQ(e[1].a, Rational(-1, 5));
  EXPECT_EQ(e[2].a, Rational(24, 25));
  EXPECT_EQ(e[3].a, Rational(7, 25));
  // Contact points in the body frame are the chosen ones.
  EXPECT_EQ(q.p_BoG_B[0][0].a, -1);
  EXPECT_EQ(q.p_BoG_B[0][1].a, 0);
  EXPECT_EQ(q.p_BoG_B[1][0].a, Rational(-1, 2));
  EXPECT_EQ(q.p_BoG_B[2][0].a, Rational(1, 2));
}

GTEST_TEST(SeatedPose, RejectsAFixelOffThePolygon) {
  // The scene reader refuses it first; with the documented opt-out the seated
  // pose must still refuse it on its own.
  const std::string text = square_scene("\"0\"", "1/10 0 0", "0", "-1/2", "3/2");
  EXPECT_THROW(parse_scene(text), SceneError);
  std::string opted = text;
  const std::size_t last = opted.rfind("\"gap\"");
  opted.insert(last, "\"off_boundary\": true, ");
  const Scene scene = parse_scene(opted);
  EXPECT_THROW(seated_pose(scene), SceneError);
}

// The hand-built seat with the bottom edge given as a cubic B-spline whose
// control points are collinear: contacts on a curved piece.
Scene curved_square() {
  return parse_scene(R"({"name": "square", "time_step": "1",
    "body": {"dof": "3", "mass": "1", "center_of_mass": ["0", "0"],
             "boundary": [
               {"type": "bspline", "degree": "3", "knots": ["0","0","0","0","1","1","1","1"],
                "control_points": [["-1","-1"], ["-1/3","-1"], ["1/3","-1"], ["1","-1"]]},
               {"type": "polyline", "points": [["1","-1"], ["1","1"], ["-1","1"], ["-1","-1"]]}]},
    "fixels": [
      {"point": ["-1", "-12/25"], "normal": ["1", "0"], "mu": "0", "gap": "3/50"},
      {"point": ["-3/10", "-1"], "normal": ["0", "1"], "mu": "0", "gap": "3/10"},
      {"point": ["33/50", "-1"], "normal": ["0", "1"], "mu": "0", "gap": "1/50"}]})");
}

GTEST_TEST(SustainedSet, AHandBuiltSceneWithABadValueIsASceneErrorNamingTheField) {
  Scene bad = scene_file("polygon");
  bad.body.velocity = VectorQ();
  try {
    sustained_set(bad);
    ADD_FAILURE() << "a scene with no velocity was analysed";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.field(), "body.velocity");
    EXPECT_EQ(e.value(), "0 entries");
  }
}

GTEST_TEST(SeatedPose, NeedsABoundary) { EXPECT_THROW(seated_pose(scene_file("example2")), SceneError); }

// The same hand-built seat with the bottom edge given as a cubic B-spline
// whose control points are collinear: the curved path (interval Newton,
// Krawczyk) must enclose the exact answer of the polyline path.
GTEST_TEST(SeatedPose, CertifiedEnclosureOnACurvedEdgeHoldsTheExactSeat) {
  const Scene scene = curved_square();
  const SeatedPose q = seated_pose(scene);
  EXPECT_FALSE(q.exact.has_value());
  auto holds = [](const std::array<double, 2>& e, const Rational& x) {
    return Rational(e[0]) <= x && x <= Rational(e[1]) && e[1] - e[0] < 1e-6;
  };
  EXPECT_TRUE(holds(q.enclosure[0], Rational(-1, 10)));
  EXPECT_TRUE(holds(q.enclosure[1], Rational(-1, 5)));
  EXPECT_TRUE(holds(q.cos_sin_enclosure[0], Rational(24, 25)));
  EXPECT_TRUE(holds(q.cos_sin_enclosure[1], Rational(7, 25)));
  // J is computed on the enclosure and agrees, where it decides, with the
  // exact J of the polyline twin: the same square (the B-spline edge is the
  // straight bottom edge), the same fixels and gaps, an exact seat.
  const SustainedSet J = sustained_set(scene);
  EXPECT_FALSE(J.cone.exact);
  const Scene twin = parse_scene(square_scene("\"0\"", "3/50 3/10 1/50", "-12/25", "-3/10", "33/50"));
  const SustainedSet J_exact = sustained_set(twin);
  ASSERT_TRUE(J_exact.cone.exact);
  std::mt19937_64 rng(11);
  int decided = 0, in = 0;
  for (int k = 0; k < 200; ++k) {
    const VectorQ w =
        v3(random_rational(rng, -2, 2, 4), random_rational(rng, -2, 2, 4), random_rational(rng, -2, 2, 4));
    try {
      const bool member = J.contains(w);
      EXPECT_EQ(member, J_exact.contains(w)) << w.transpose();
      ++decided;
      in += member;
    } catch (const UnsupportedError&) {  // the enclosure cannot decide this w
    }
  }
  EXPECT_GT(decided, 150);
  EXPECT_GT(in, 10);
}

GTEST_TEST(SeatedPose, SaysSoWhenNoSeatIsNearTheScenePose) {
  EXPECT_THROW(seated_pose(scene_file("blob")), SceneError);
}

// The hand-derived wrenches of docs/theory.md §10 on the square with μ = 1/10:
// jam cone (1, 2) has the facet −x + y/10 ≥ 0 through (1/10, 1, −2/5) and
// (1/10, 1, 3/5), whose sum v = (1/5, 2, 1/5) = W_n (1/5, 4/5, 6/5) is inside
// cone(W_n).
GTEST_TEST(SustainedSet, AWrenchExactlyOnAJamFacetIsHeldAndNotInJ) {
  const SustainedSet J = sustained_set(square());
  const VectorQ v = v3(Rational(1, 5), 2, Rational(1, 5));
  EXPECT_FALSE(J.contains(-v));
  EXPECT_NE(J.why_not(-v).find("fixels[1] and fixels[2]"), std::string::npos) << J.why_not(-v);
}

GTEST_TEST(SustainedSet, AWrenchAHairOutsideTheJamFacetIsInJ) {
  const SustainedSet J = sustained_set(square());
  const Rational hair = kHair;
  EXPECT_TRUE(J.contains(-v3(Rational(1, 5) + hair, 2, Rational(1, 5))));
  EXPECT_FALSE(J.contains(-v3(Rational(1, 5) - hair, 2, Rational(1, 5))));  // a hair inside the jam cone
}

GTEST_TEST(SustainedSet, TheBoundaryOfTheNormalConeIsNotInJ) {
  const SustainedSet J = sustained_set(square("\"0\""));
  // −w = W_n,1 + W_n,2 = (0, 2, 0): λ_0 = 0, on a face of cone(W_n).
  EXPECT_FALSE(J.contains(v3(0, -2, 0)));
  EXPECT_NE(J.why_not(v3(0, -2, 0)).find("escape"), std::string::npos);
  // A hair inside cone(W_n) it is in J when μ = 0 ...
  const Rational hair = kHair;
  EXPECT_TRUE(J.contains(v3(-hair, -2, 0)));
  // ... and held by the two bottom fixels with friction.
  EXPECT_FALSE(sustained_set(square()).contains(v3(-hair, -2, 0)));
}

GTEST_TEST(SustainedSet, WithoutFrictionIsTheOpenNormalCone) {
  const Scene scene = square("\"0\"");
  const SustainedSet J = sustained_set(scene);
  EXPECT_FALSE(J.empty);
  std::mt19937_64 rng(7);
  int in = 0;
  for (int k = 0; k < 400; ++k) {
    const VectorQ w =
        v3(random_rational(rng, -2, 2, 4), random_rational(rng, -2, 2, 4), random_rational(rng, -2, 2, 4));
    const bool expected = in_open_normal_cone(scene, w);
    EXPECT_EQ(J.contains(w), expected) << w.transpose();
    in += expected;
  }
  EXPECT_GT(in, 10);
}

GTEST_TEST(SustainedSet, ShrinksAsFrictionGrows) {
  std::mt19937_64 rng(11);
  int checked = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Rational mu1 = random_rational(rng, 0, 1, 40) / 4, mu2 = mu1 + random_rational(rng, 0, 1, 40) / 8;
    const std::string y0 = to_string(random_rational(rng, -1, 1, 4));
    const std::string x1 = to_string(random_rational(rng, -1, 0, 4)), x2 = to_string(random_rational(rng, 0, 1, 4));
    if (x1 == x2 || y0 == "-1" || y0 == "1" || x1 == "-1" || x2 == "1") continue;
    const Scene s1 = parse_scene(square_scene("\"" + to_string(mu1) + "\"", "0 0 0", y0, x1, x2));
    const Scene s2 = parse_scene(square_scene("\"" + to_string(mu2) + "\"", "0 0 0", y0, x1, x2));
    const SustainedSet J1 = sustained_set(s1), J2 = sustained_set(s2);
    const MatrixQ Wn = normal_matrix(s1);
    for (int k = 0; k < 200; ++k) {
      const VectorQ w = random_inward_wrench(rng, Wn);
      if (J2.contains(w)) {
        EXPECT_TRUE(J1.contains(w)) << "mu " << mu1 << " < " << mu2 << " w " << w.transpose();
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 20);
}

GTEST_TEST(SustainedSet, FrictionIntervalsAreJudgedAtTheirUpperEnds) {
  const SustainedSet Ji = sustained_set(square(R"(["1/20", "1/10"])"));
  const SustainedSet Jhi = sustained_set(square("\"1/10\""));
  EXPECT_EQ(Ji.mu[0], Rational(1, 10));
  std::mt19937_64 rng(3);
  const MatrixQ Wn = normal_matrix(square());
  int in = 0;
  for (int k = 0; k < 200; ++k) {
    const VectorQ w =
        k % 2 ? random_inward_wrench(rng, Wn)
              : v3(random_rational(rng, -2, 2, 8), random_rational(rng, -3, 1, 8), random_rational(rng, -2, 2, 8));
    EXPECT_EQ(Ji.contains(w), Jhi.contains(w));
    in += Jhi.contains(w);
  }
  EXPECT_GT(in, 10);
  EXPECT_THROW(parse_scene(square_scene(R"(["1/5", "1/10"])", "0 0 0")), SceneError);
  EXPECT_THROW(parse_scene(square_scene(R"(["-1/5", "1/10"])", "0 0 0")), SceneError);
}

// At a rational seat (gaps 0: q* = 0) J's rows are made in rationals.
// Second method, from the definitions: K's strict rows vanish on two of
// the rays −W_n,k and are positive on the third; each jam cone's closed
// rows are, up to a positive factor, cone_facet_normals (src/cone.cpp) of
// its generators −(W_n,k ± μ_k W_t,k). Squares with random friction and
// fixel positions, frictionless ones included.
GTEST_TEST(SustainedSet, AtARationalSeatItsRowsAreTheConesOfItsDefinition) {
  std::mt19937_64 rng(29);
  auto rational = [](const std::array<QuadraticIrrational, 3>& a) {
    for (const auto& x : a) EXPECT_EQ(x.b, 0);
    return v3(a[0].a, a[1].a, a[2].a);
  };
  auto same_direction = [](const VectorQ& a, const VectorQ& b) {
    const VectorQ c = v3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
    return c.isZero() && a.dot(b) > 0;
  };
  int trials = 0, jams = 0;
  int frictionless = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::string mu = trial % 4 == 0 ? "0" : to_string(random_rational(rng, 0, 1, 20) / 2);
    const std::string y0 = to_string(random_rational(rng, -1, 1, 4));
    const std::string x1 = to_string(random_rational(rng, -1, 0, 4)), x2 = to_string(random_rational(rng, 0, 1, 4));
    if (x1 == x2 || y0 == "-1" || y0 == "1" || x1 == "-1" || x2 == "1") continue;
    const Scene scene = parse_scene(square_scene("\"" + mu + "\"", "0 0 0", y0, x1, x2));
    const SustainedSet J = sustained_set(scene, false);
    ++trials;
    frictionless += mu == "0";
    const MatrixQ Wn = normal_matrix(scene);
    ASSERT_EQ(J.cone.strict.size(), 3u);
    for (const auto& row : J.cone.strict) {
      const VectorQ a = rational(row);
      int positive = 0, zero = 0;
      for (int k = 0; k < 3; ++k) {
        const Rational s = a.dot(VectorQ(-Wn.col(k)));
        positive += s > 0;
        zero += s == 0;
      }
      EXPECT_EQ(positive, 1);
      EXPECT_EQ(zero, 2);
    }
    for (const auto& jam : J.jam_cones) {
      std::vector<VectorQ> gens;
      for (int k : jam.fixels) {
        const Vec2 r = scene.lever_arm(k), n = scene.fixels[k].n_A, t{-n.y, n.x};
        const Rational m = scene.fixels[k].mu_upper();
        for (int s : {1, -1})
          gens.push_back(-(VectorQ(Wn.col(k)) + Rational(s) * m * v3(t.x, t.y, r.x * t.y - r.y * t.x)));
      }
      const std::vector<VectorQ> expected = cone_facet_normals(gens, 3);
      ASSERT_EQ(jam.cone.closed.size(), expected.size()) << "mu " << mu;
      for (const auto& row : jam.cone.closed) {
        const VectorQ a = rational(row);
        int matches = 0;
        for (const auto& e : expected) matches += same_direction(a, e);
        EXPECT_EQ(matches, 1) << a.transpose();
      }
      ++jams;
    }
  }
  EXPECT_GE(trials, 15);
  EXPECT_GE(frictionless, 2);
  EXPECT_EQ(jams, 3 * trials);
}

GTEST_TEST(SustainedSet, PiecesAreDisjointAndTheirUnionIsJ) {
  const SustainedSet J = sustained_set(square());
  ASSERT_FALSE(J.pieces.empty());
  // Strong stability, checked by contact-mode enumeration at the (rational) seat.
  EXPECT_EQ(J.stability_checks, static_cast<int>(J.pieces.size()));
  EXPECT_TRUE(J.strongly_stable);
  std::mt19937_64 rng(5);
  const MatrixQ Wn = normal_matrix(square());
  int in = 0;
  auto in_piece = [](const AlgebraicCone& c, const VectorQ& w) {
    // Rational pieces here (gaps 0, θ* = 0): evaluate the rows exactly.
    for (const auto& a : c.closed)
      if (a[0].a * w[0] + a[1].a * w[1] + a[2].a * w[2] < 0) return false;
    for (const auto& a : c.strict)
      if (a[0].a * w[0] + a[1].a * w[1] + a[2].a * w[2] <= 0) return false;
    return true;
  };
  for (int k = 0; k < 400; ++k) {
    const VectorQ w =
        k % 2 ? random_inward_wrench(rng, Wn)
              : v3(random_rational(rng, -2, 2, 8), random_rational(rng, -3, 1, 8), random_rational(rng, -2, 2, 8));
    int count = 0;
    for (const auto& p : J.pieces) count += in_piece(p, w);
    EXPECT_LE(count, 1);
    EXPECT_EQ(count == 1, J.contains(w)) << w.transpose();
    in += count;
  }
  EXPECT_GT(in, 10);
}

// Whether fixels i and j can hold the part at rest under w (gaps 0: the
// scene pose is the seat): −w = Σ a_k g_k, a ≥ 0, over the four edges
// g = W_n,c ± μ W_t,c of their friction cones, by Carathéodory one triple
// of edges at a time, each an exact 3×3 solve (independent of J's cones).
bool pair_holds(const Scene& scene, int i, int j, const Rational& mu, const VectorQ& w) {
  std::vector<VectorQ> edges;
  for (int c : {i, j}) {
    const Vec2 r = scene.lever_arm(c), n = scene.fixels[c].n_A, t = scene.tangent(c);
    const VectorQ wn = v3(n.x, n.y, r.x * n.y - r.y * n.x), wt = v3(t.x, t.y, r.x * t.y - r.y * t.x);
    edges.push_back(wn + mu * wt);
    edges.push_back(wn - mu * wt);
  }
  for (int skip = 0; skip < 4; ++skip) {
    MatrixQ G(3, 3);
    for (int k = 0, col = 0; k < 4; ++k)
      if (k != skip) G.col(col++) = edges[k];
    const auto lu = internal::exact_lu(G);
    if (!lu.isInvertible()) continue;
    const VectorQ a = lu.solve(VectorQ(-w));
    if (a[0] >= 0 && a[1] >= 0 && a[2] >= 0) return true;
  }
  return false;
}

GTEST_TEST(SustainedSet, EmptyWhenAPairHoldsEveryInwardPushAndSaysWhich) {
  // With μ = 3 the pairs are tested in order (0, 1), (0, 2), (1, 2), and
  // the first, the left fixel with the left bottom one, already holds
  // every push that drives the part into its seat: J is empty and says so.
  const Rational mu(3);
  const Scene scene = square("\"3\"");
  const SustainedSet J = sustained_set(scene);
  EXPECT_TRUE(J.empty);
  EXPECT_NE(J.empty_reason.find("fixels[0] and fixels[1] with friction"), std::string::npos) << J.empty_reason;
  // The named pair holds inward pushes, checked on its own friction cones.
  std::mt19937_64 rng(5);
  const MatrixQ Wn = normal_matrix(scene);
  for (int k = 0; k < 100; ++k) {
    const VectorQ w = random_inward_wrench(rng, Wn);
    EXPECT_TRUE(pair_holds(scene, 0, 1, mu, w)) << w.transpose();
  }
  // With μ = 1/10 the same pair does not hold them all.
  const Scene low = square();
  int held = 0;
  for (int k = 0; k < 100; ++k) held += pair_holds(low, 0, 1, Rational(1, 10), random_inward_wrench(rng, Wn));
  EXPECT_LT(held, 100);
}

GTEST_TEST(SustainedSet, CoreWithoutThePublicFormHasTheSameEmptinessAndRegion) {
  // internal::sustained_core (design's ranking) skips the pieces' rays, the
  // public cones and, at an exact seat, every piece after the first: the
  // same J for every decision. Squares with random
  // friction (J empty or not, exact q*), the polygon, and a square with a
  // curved bottom edge (an enclosed q*).
  std::vector<Scene> scenes{square("\"3\""), scene_file("polygon"), curved_square()};
  std::mt19937_64 rng(21);
  for (int trial = 0; trial < 6; ++trial)
    scenes.push_back(square("\"" + to_string(random_rational(rng, 0, 2, 8)) + "\""));
  int empty = 0;
  for (const Scene& scene : scenes) {
    const SustainedSet J = sustained_set(scene, false);
    const internal::SustainedCore core = internal::sustained_core(scene);
    EXPECT_EQ(core.empty, J.empty);
    EXPECT_EQ(core.pieces_decided, J.pieces_decided);
    empty += J.empty;
    if (J.empty) continue;
    RegionOptions opt;
    opt.resolution = Rational(1, 64);
    const Region full = compute_region(scene, *sustained_target(J), opt);
    const Region ranked = compute_region(scene, *internal::sustained_target(core.data), opt);
    EXPECT_EQ(test::masked(region_json(scene, full)), test::masked(region_json(scene, ranked)));
  }
  EXPECT_GE(empty, 1);
  EXPECT_LT(empty, static_cast<int>(scenes.size()));
}

GTEST_TEST(SustainedRegion, IsSoundByExactSamplingOnThePolygon) {
  const Scene scene = scene_file("polygon");
  const SustainedSet J = sustained_set(scene);
  for (const std::string mu : {"0", "1/10"}) {
    auto target = sustained_target(J);
    RegionOptions options;
    options.resolution = Rational(1, 256);
    options.pusher_mu = parse_rational(mu);
    const Region region = compute_region(scene, *target, options);
    EXPECT_EQ(region.push, "sustained");
    int in = 0, out = 0;
    for (const auto& r : region.intervals) {
      if (r.status == RegionStatus::kPartial || r.u0 == r.u1) continue;
      for (int k = 1; k < 8; ++k) {
        const Rational u = r.u0 + (r.u1 - r.u0) * Rational(k, 8);
        const RegionStatus st = point_status(scene, *target, r.curve, u, *options.pusher_mu);
        EXPECT_EQ(st, r.status) << "curve " << r.curve << " u " << u;
        (r.status == RegionStatus::kIn ? in : out)++;
      }
    }
    EXPECT_GT(in, 0);
    EXPECT_GT(out, 0);
  }
}

// A target answers for the scene its set was built from. J of the polygon
// asked about the polygon with one gap changed (same name, same shape, a
// seat turned by another angle) gave that other seat's region silently; the
// region, point and sample functions now refuse it naming J and what
// differs, and J′ and S the same way. An equal scene (read again) passes
// and gives the same region, and so does one that differs only where J
// does not look (the step's h and velocity).
// The writers printed J's (or J′'s) numbers under another scene's name.
GTEST_TEST(SustainedSet, ItsWritersRefuseAJOrJPrimeOfAnotherSceneNamingItAndWriteNothing) {
  const Scene polygon = scene_file("polygon");
  Scene moved = polygon;
  moved.fixels[0].gap = Rational(1, 5);
  const SustainedSet J = sustained_set(polygon), J_moved = sustained_set(moved);
  const ApproachSet A = approach_set(polygon, J);
  auto named = [](const std::function<void()>& call) {
    const std::string e = test::input_error_of(call);
    EXPECT_NE(e.find("belongs to another scene than \"polygon\": fixels[0]"), std::string::npos) << e;
    return e.substr(0, e.find(':'));
  };
  EXPECT_EQ(named([&] { sustained_json(moved, J, std::nullopt); }), "J");
  EXPECT_EQ(named([&] { sustained_text(moved, J, std::nullopt); }), "J");
  EXPECT_EQ(named([&] { sustained_json(moved, J_moved, std::nullopt, &A, std::nullopt); }), "J'");
  EXPECT_EQ(named([&] { sustained_text(moved, J_moved, std::nullopt, &A, std::nullopt); }), "J'");
  const auto dir = std::filesystem::temp_directory_path() / "fixel_sustained_other_scene";
  std::filesystem::remove_all(dir);
  EXPECT_EQ(named([&] { dump_sustained_off(moved, J, dir.string()); }), "J");
  EXPECT_FALSE(std::filesystem::exists(dir));
  // Each scene's own sets are written.
  EXPECT_EQ(test::input_error_of([&] { sustained_json(polygon, J, std::nullopt, &A, std::nullopt); }),
            "(no InputError)");
  EXPECT_EQ(test::input_error_of([&] { sustained_text(moved, J_moved, std::nullopt); }), "(no InputError)");
}

// J's picture needs its rows in doubles: a centre of mass at ±10^308
// puts them past double range, and the refusal names J (it named the
// CLI's "dump --off --sustained"), with nothing written.
GTEST_TEST(SustainedSet, ItsPictureRefusesRowsBeyondDoubleRangeNamingJ) {
  Scene far = scene_file("polygon");
  far.body.p_AoCm_A = Vec2{parse_rational("1e308"), parse_rational("-1e308")};
  const SustainedSet J = sustained_set(far);
  const auto dir = std::filesystem::temp_directory_path() / "fixel_sustained_beyond_doubles";
  std::filesystem::remove_all(dir);
  const std::string e = test::input_error_of([&] { dump_sustained_off(far, J, dir.string()); });
  EXPECT_EQ(e.substr(0, e.find(':')), "J") << e;
  EXPECT_NE(e.find("a row of J is beyond double range"), std::string::npos) << e;
  EXPECT_FALSE(std::filesystem::exists(dir / "sustained.off"));
}

GTEST_TEST(SustainedRegion, ATargetOfAnotherSceneIsRefusedNamingItsSet) {
  const Scene polygon = scene_file("polygon");
  Scene moved = polygon;
  moved.fixels[0].gap = Rational(1, 5);
  const SustainedSet J = sustained_set(polygon);
  const auto target = sustained_target(J);
  RegionOptions options;
  options.resolution = Rational(1, 64);
  // What the refusal protects: J of `moved` has another region there.
  const auto own = sustained_target(sustained_set(moved));
  const Region polygon_region = compute_region(polygon, *target, options);
  const Region moved_region = compute_region(moved, *own, options);
  bool differs = polygon_region.intervals.size() != moved_region.intervals.size();
  for (std::size_t i = 0; !differs && i < moved_region.intervals.size(); ++i)
    differs = polygon_region.intervals[i].u1 != moved_region.intervals[i].u1 ||
              polygon_region.intervals[i].status != moved_region.intervals[i].status;
  EXPECT_TRUE(differs);
  auto refused = [](const std::function<void()>& f, const std::string& field) {
    try {
      f();
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field);
      EXPECT_NE(std::string(e.what()).find(
                    "built from scene \"polygon\" belongs to another scene than \"polygon\": "
                    "fixels[0].gap is 1/5 here, 1/10 in the scene it was built from; build it from this scene"),
                std::string::npos)
          << e.what();
      return true;
    }
    return false;
  };
  EXPECT_TRUE(refused([&] { compute_region(moved, *target, options); }, "J"));
  EXPECT_TRUE(refused([&] { point_status(moved, *target, 0, Rational(5, 2), Rational(0)); }, "J"));
  EXPECT_TRUE(refused([&] { sample_region(moved, *target, 4); }, "J"));
  EXPECT_TRUE(refused([&] { approach_set(moved, J); }, "J"));
  const auto j_prime = approach_target(approach_set(polygon, J));
  EXPECT_TRUE(refused([&] { compute_region(moved, *j_prime, options); }, "J'"));
  // S is checked exactly against the scene (its own message).
  const auto s_target = seating_target(seating_set(polygon), polygon.background_impulse);
  try {
    compute_region(moved, *s_target, options);
    ADD_FAILURE() << "S of another scene was not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "S");
  }
  // The same scene read again passes, with the same answer.
  const Scene again = scene_file("polygon");
  const Region same = compute_region(again, *target, options);
  ASSERT_EQ(same.intervals.size(), polygon_region.intervals.size());
  for (std::size_t i = 0; i < same.intervals.size(); ++i)
    EXPECT_EQ(same.intervals[i].status, polygon_region.intervals[i].status);
  EXPECT_NO_THROW(compute_region(again, *j_prime, options));
  Scene other_step = polygon;
  other_step.time_step = Rational(1, 100);
  other_step.body.velocity = v3(0, -1, 0);
  EXPECT_NO_THROW(compute_region(other_step, *target, options));
  EXPECT_NO_THROW(compute_region(again, *s_target, options));
}

GTEST_TEST(SustainedRegion, AFrictionalPusherInIsInForTheWholeFan) {
  // Every IN point for μ_p = 1/10 is IN for μ_p = 0 (the fan only grows).
  const Scene scene = scene_file("polygon");
  const SustainedSet J = sustained_set(scene);
  auto target = sustained_target(J);
  RegionOptions options;
  options.resolution = Rational(1, 256);
  options.pusher_mu = Rational(1, 10);
  const Region region = compute_region(scene, *target, options);
  int checked = 0;
  for (const auto& r : region.intervals) {
    if (r.status != RegionStatus::kIn || r.u0 == r.u1) continue;
    const Rational u = (r.u0 + r.u1) / 2;
    EXPECT_EQ(point_status(scene, *target, r.curve, u, Rational(0)), RegionStatus::kIn);
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace fixel

namespace fixel {
namespace {

// The engine check of the central claim, kept short: a few pushes from the
// polygon's sustained IN interval must seat in Box2D (docs/physics.md).
GTEST_TEST(SustainedRegion, PushesFromItsInIntervalSeatInBox2D) {
  const Scene scene = scene_file("polygon");
  const SustainedSet J = sustained_set(scene);
  auto target = sustained_target(J);
  RegionOptions options;
  options.resolution = Rational(1, 64);
  const Region region = compute_region(scene, *target, options);
  physics::PushOptions push;
  push.time = 10;
  push.trajectory_samples = 1;
  const auto v = physics::validate_region(scene, region, physics::seated_push_model(scene), 3, 1, push);
  ASSERT_GT(v.total.pushes, 0);
  EXPECT_EQ(v.total.seated, v.total.pushes);
}

// The sustained region's document carries J's seated pose with |θ*| and
// the report's note (DESIGN's "report |θ*| always"), before "push".
GTEST_TEST(SustainedJson, TheSustainedRegionDocumentGivesThetaStarAndTheNote) {
  const Scene scene = test::scene_file("example2_rounded");
  const SustainedSet J = sustained_set(scene);
  RegionOptions o;
  o.resolution = Rational(1, 64);
  const Region r = compute_region(scene, *sustained_target(J), o);
  const auto doc = nlohmann::ordered_json::parse(region_json(scene, r, &J.pose));
  EXPECT_EQ(doc.at("seated_pose").at("theta_abs").get<double>(), std::abs(J.pose.approx[2]));
  EXPECT_GE(std::abs(J.pose.approx[2]), 0.2);  // this part turns 0.30 rad: the warning
  EXPECT_EQ(doc.at("seat_note").get<std::string>().rfind("warning: |theta*| = 0.30031 rad", 0), 0u)
      << doc.at("seat_note");
  EXPECT_EQ(doc.items().begin().key(), "scene");
  EXPECT_EQ((--doc.end()).key(), "push");
  EXPECT_FALSE(nlohmann::json::parse(region_json(scene, r)).contains("seated_pose"));  // no seat given
}

// seat --sustained --json adds J's keys to S's (DESIGN §7 "JSON adds"): S's
// keys are those of seat --json, unchanged; with a friction interval S
// cannot be built and the document says why.
GTEST_TEST(SustainedJson, TheSeatDocumentAddsJsKeysToSsOrSaysWhySIsMissing) {
  const Scene scene = test::scene_file("polygon");
  const SustainedSet J = sustained_set(scene);
  const auto with = nlohmann::json::parse(sustained_json(scene, J, std::nullopt, nullptr, std::nullopt, true));
  const SeatingSet S = seating_set(scene);
  const auto seat = nlohmann::json::parse(seat_json(scene, S, seat_report(scene, S, std::nullopt, nullptr, false)));
  for (const auto& item : seat.items()) EXPECT_EQ(with.at(item.key()), item.value()) << item.key();
  const auto without = nlohmann::json::parse(sustained_json(scene, J, std::nullopt));
  EXPECT_FALSE(without.contains("apex"));
  EXPECT_EQ(with.at("sustained"), without.at("sustained"));
  Scene interval = scene;
  interval.fixels[0].mu_hi = Rational(1, 5);
  const SustainedSet Ji = sustained_set(interval);
  const auto doc = nlohmann::json::parse(sustained_json(interval, Ji, std::nullopt, nullptr, std::nullopt, true));
  EXPECT_FALSE(doc.contains("apex"));
  EXPECT_NE(doc.at("seating_unavailable").get<std::string>().find("interval"), std::string::npos);
}

// Building J polls the calling thread's ControlScope between its exact
// steps: on numbers of 20,000 digits it took half a minute and ignored
// --max-seconds.
GTEST_TEST(SustainedSet, BuildingItStopsInsideACancelledControlScopeNamingTheStep) {
  const Scene polygon = scene_file("polygon");
  EXPECT_EQ(test::stop_message([&] { sustained_set(polygon); }), "(no stop)");
  const test::CancelledControl cancelled;
  const ControlScope scope(&cancelled.control);
  // The seated pose comes first (its square roots and bounds in Q(√d))...
  EXPECT_EQ(test::stop_message([&] { sustained_set(polygon); }),
            "seated pose q*: interrupted after 0 exact steps; no result");
  // ... and with every gap 0 (q* the scene pose, no arithmetic) J's own steps.
  Scene seated = polygon;
  for (auto& f : seated.fixels) f.gap = 0;
  EXPECT_EQ(test::stop_message([&] { sustained_set(seated); }),
            "sustained set J: interrupted after 0 exact steps; no result");
}
}  // namespace
}  // namespace fixel
