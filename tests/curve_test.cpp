#include "fixel/curve.h"

#include <gtest/gtest.h>

#include <chrono>

#include <random>

#include "fixel/error.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "test_util.h"

namespace fixel {
namespace {

bool eq(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }

Curve polyline(std::vector<Vec2> pts) {
  Curve c;
  c.type = Curve::Type::kPolyline;
  c.points = std::move(pts);
  return c;
}

Curve bspline(int p, std::vector<Rational> knots, std::vector<Vec2> pts) {
  Curve c;
  c.type = Curve::Type::kBSpline;
  c.degree = p;
  c.knots = std::move(knots);
  c.points = std::move(pts);
  return c;
}

// Second method: Cox–de Boor basis functions N_{i,p}(u), with the last
// span closed on the right.
Rational basis(const std::vector<Rational>& U, int i, int p, const Rational& u, const Rational& u_end) {
  if (p == 0) {
    // Half-open spans [U_i, U_{i+1}), except at the end of the range, where
    // the curve takes its left limit: (U_i, U_{i+1}].
    if (u == u_end) return (U[i] < u && u <= U[i + 1]) ? Rational(1) : Rational(0);
    return (U[i] <= u && u < U[i + 1]) ? Rational(1) : Rational(0);
  }
  Rational r = 0;
  if (U[i + p] != U[i]) r += (u - U[i]) / (U[i + p] - U[i]) * basis(U, i, p - 1, u, u_end);
  if (U[i + p + 1] != U[i + 1]) r += (U[i + p + 1] - u) / (U[i + p + 1] - U[i + 1]) * basis(U, i + 1, p - 1, u, u_end);
  return r;
}
Vec2 cox_de_boor(const Curve& c, const Rational& u) {
  Vec2 out{0, 0};
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const Rational b = basis(c.knots, static_cast<int>(i), c.degree, u, c.u_end());
    out.x += b * c.points[i].x;
    out.y += b * c.points[i].y;
  }
  return out;
}

Curve random_bspline(std::mt19937_64& rng, int p, int n, bool clamped) {
  std::vector<Vec2> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back({test::random_rational(rng, -3, 3, 7), test::random_rational(rng, -3, 3, 7)});
  // Clamped: p + 1 equal end knots; interior knots may repeat (up to p times
  // here, increments are 0 with probability 1/7). Unclamped: strictly increasing.
  std::vector<Rational> knots;
  Rational u = 0;
  for (int i = 0; i < n + p + 1; ++i) {
    if (clamped && i > p && i <= n)
      u += (i == n || i == p + 1 ? Rational(1, 3) : Rational(0)) + test::random_rational(rng, 0, 2, 3);
    if (!clamped && i > 0) u += Rational(1, 3) + test::random_rational(rng, 0, 2, 3);
    knots.push_back(u);
  }
  return bspline(p, knots, pts);
}

// A piece built by hand with an empty parameter range or no control point:
// a typed error (a Boost division by zero, and "a bug in fixel", before).
GTEST_TEST(Curve, AHandMadePieceWithoutRangeOrControlPointsIsAnInputError) {
  BezierPiece piece;
  piece.u0 = piece.u1 = Rational(1);
  piece.control = {Vec2{Rational(0), Rational(0)}, Vec2{Rational(1), Rational(0)}};
  EXPECT_THROW(piece.local(Rational(1)), InputError);
  piece.u1 = Rational(2);
  EXPECT_EQ(piece.local(Rational(3, 2)), Rational(1, 2));
  piece.control.clear();
  EXPECT_THROW(piece.point(Rational(1, 2)), InputError);
}

GTEST_TEST(Curve, PolylinePiecesFollowTheVertexIndex) {
  const Curve c = polyline({{0, 0}, {2, 0}, {2, 1}});
  const auto pieces = c.bezier_pieces(4);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[1].curve, 4);
  EXPECT_EQ(pieces[1].u0, Rational(1));
  EXPECT_TRUE(eq(c.point(Rational(3, 2)), Vec2{2, Rational(1, 2)}));
  EXPECT_TRUE(eq(c.derivative(Rational(1, 2)), Vec2{2, 0}));
  EXPECT_TRUE(eq(c.point(Rational(2)), Vec2{2, 1}));
  EXPECT_THROW(c.point(Rational(3)), InputError);
}

GTEST_TEST(Curve, BSplineEvaluationAndBezierPiecesMatchCoxDeBoor) {
  std::mt19937_64 rng(41);
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int p = 1 + trial % 4;
    const Curve c = random_bspline(rng, p, p + 1 + trial % 5, trial % 2 == 0);
    for (int k = 0; k <= 12; ++k) {
      const Rational u = c.u_begin() + (c.u_end() - c.u_begin()) * Rational(k, 12);
      EXPECT_TRUE(eq(c.point(u), cox_de_boor(c, u))) << "trial " << trial << " u " << to_string(u);
      ++checked;
    }
  }
  EXPECT_GT(checked, 700);
}

GTEST_TEST(Curve, DerivativesMatchTheDerivativeBSpline) {
  // d/du Σ N_{i,p} P_i = Σ N_{i,p−1} p (P_{i+1} − P_i) / (U_{i+p+1} − U_{i+1}),
  // on the knot vector without its first and last knot.
  std::mt19937_64 rng(43);
  for (int trial = 0; trial < 30; ++trial) {
    const int p = 2 + trial % 3;
    const Curve c = random_bspline(rng, p, p + 3, true);
    std::vector<Vec2> q;
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      const Rational width = c.knots[i + p + 1] - c.knots[i + 1];
      const Rational w = width == 0 ? Rational(0) : Rational(p) / width;  // 0/0 = 0 convention
      q.push_back({w * (c.points[i + 1].x - c.points[i].x), w * (c.points[i + 1].y - c.points[i].y)});
    }
    const Curve dc = bspline(p - 1, std::vector<Rational>(c.knots.begin() + 1, c.knots.end() - 1), q);
    for (int k = 0; k < 10; ++k) {
      const Rational u = c.u_begin() + (c.u_end() - c.u_begin()) * Rational(k, 10);
      EXPECT_TRUE(eq(c.derivative(u), cox_de_boor(dc, u)));
    }
  }
}

GTEST_TEST(BezierPiece, DeCasteljauSplitReproducesBothHalves) {
  const BezierPiece piece{0, Rational(2), Rational(4), {{0, 0}, {1, 3}, {3, 3}, {4, 0}}};
  const auto [left, right] = piece.split(Rational(1, 3));
  EXPECT_EQ(left.u1, Rational(8, 3));
  EXPECT_EQ(right.u0, Rational(8, 3));
  for (int k = 0; k <= 6; ++k) {
    const Rational s(k, 6);
    EXPECT_TRUE(eq(left.point(s), piece.point(s / 3)));
    EXPECT_TRUE(eq(right.point(s), piece.point(Rational(1, 3) + s * 2 / 3)));
  }
  const BezierPiece mid = piece.restrict_to(Rational(5, 2), Rational(3));
  EXPECT_TRUE(eq(mid.point(0), piece.point(Rational(1, 4))));
  EXPECT_TRUE(eq(mid.point(1), piece.point(Rational(1, 2))));
}

// The halving split (the region's subdivision takes (a + b)/2 with a gcd-free
// halving) gives exactly the control points of the general lerp formula,
// on coordinates with odd denominators.
GTEST_TEST(BezierPiece, HalvingSplitEqualsTheGeneralDeCasteljauSplit) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    BezierPiece piece{0, test::random_rational(rng, -3, 3, 7), 0, {}};
    piece.u1 = piece.u0 + test::random_rational(rng, 1, 4, 9);
    for (int k = 0; k <= 3; ++k)
      piece.control.push_back(
          {test::random_rational(rng, -5, 5, 3 + trial % 5), test::random_rational(rng, -5, 5, 15)});
    // The same split with lerp(a, b, s) = a + s (b − a).
    std::vector<Vec2> left, right(4), pts = piece.control;
    const Rational s(1, 2);
    for (std::size_t level = 0; level < 4; ++level) {
      left.push_back(pts.front());
      right[3 - level] = pts[3 - level];
      for (std::size_t i = 0; i + 1 < 4 - level; ++i)
        pts[i] = {pts[i].x + s * (pts[i + 1].x - pts[i].x), pts[i].y + s * (pts[i + 1].y - pts[i].y)};
    }
    const auto halves = piece.split(s);
    EXPECT_EQ(halves.first.u1, piece.u0 + s * (piece.u1 - piece.u0));
    EXPECT_EQ(halves.second.u0, halves.first.u1);
    for (std::size_t k = 0; k < 4; ++k) {
      EXPECT_TRUE(eq(halves.first.control[k], left[k])) << "trial " << trial << " left " << k;
      EXPECT_TRUE(eq(halves.second.control[k], right[k])) << "trial " << trial << " right " << k;
    }
  }
}

GTEST_TEST(Curve, RejectsBadKnotsAndControlCounts) {
  const std::vector<Vec2> pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  auto message = [](Curve c) {
    try {
      make_boundary({c});
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(bspline(3, {0, 0, 0, 0, 1, 1, 1}, pts)),
            "body.boundary[0].knots: 7 knots but 4 control points of degree 3 need 8 (n + degree + 1)");
  EXPECT_EQ(message(bspline(3, {0, 0, 0, 1, 0, 1, 1, 1}, pts)),
            "body.boundary[0].knots[4]: 0 is smaller than the previous knot 1: knots must be non-decreasing");
  EXPECT_EQ(message(bspline(2, {0, 0, 0, 0, 1, 1, 1}, pts)),
            "body.boundary[0].knots: 0 has multiplicity 4 > degree + 1 = 3");
  EXPECT_EQ(message(bspline(3, {0, 0, 0, 0}, {{0, 0}})),
            "body.boundary[0].control_points: 1 point(s) a degree-3 B-spline needs at least 4");
  EXPECT_EQ(message(polyline({{0, 0}, {0, 0}, {1, 1}, {0, 0}})),
            "body.boundary[0].points[1]: (0, 0) repeats the previous point: a zero-length edge has no normal");
}

GTEST_TEST(Boundary, RejectsUnclosedClockwiseAndFlatLoops) {
  EXPECT_THROW(make_boundary({polyline({{0, 0}, {1, 0}, {1, 1}})}), SceneError);
  try {
    make_boundary({polyline({{0, 0}, {0, 1}, {1, 1}, {1, 0}, {0, 0}})});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "body.boundary: signed area -1 runs clockwise; list the loop counter-clockwise (interior on the left)");
  }
  EXPECT_THROW(make_boundary({polyline({{0, 0}, {1, 0}, {2, 0}, {0, 0}})}), SceneError);
  // Two curves that do not join.
  EXPECT_THROW(make_boundary({polyline({{0, 0}, {1, 0}, {1, 1}}), polyline({{1, 2}, {0, 0}})}), SceneError);
  // Two curves that do join: the triangle (0, 0), (1, 0), (1, 1), area 1/2.
  EXPECT_EQ(make_boundary({polyline({{0, 0}, {1, 0}, {1, 1}}), polyline({{1, 1}, {0, 0}})}).mass.area, Rational(1, 2));
}

GTEST_TEST(Boundary, RejectsDegenerateAndDiscontinuousBSplines) {
  // All control points equal: a piece with only zero legs.
  EXPECT_THROW(make_boundary({bspline(1, {0, 0, 1, 1}, {{1, 1}, {1, 1}})}), SceneError);
  // A knot of multiplicity degree + 1 inside the range makes a jump.
  EXPECT_THROW(make_boundary({bspline(1, {0, 0, 1, 1, 2, 2}, {{0, 0}, {1, 0}, {1, 1}, {0, 0}})}), SceneError);
}

GTEST_TEST(MassProperties, RectangleMatchesClosedForms) {
  const Boundary b = make_boundary({polyline({{0, 0}, {4, 0}, {4, 2}, {0, 2}, {0, 0}})});
  EXPECT_EQ(b.mass.area, Rational(8));
  EXPECT_TRUE(eq(b.mass.centroid, Vec2{2, 1}));
  EXPECT_EQ(b.mass.polar_moment_about(b.mass.centroid), Rational(8) * (16 + 4) / 12);  // A (a² + b²) / 12
}

GTEST_TEST(MassProperties, DegreeOneBSplineEqualsThePolygonAndSubdivisionChangesNothing) {
  const std::vector<Vec2> pts = {{0, 0}, {3, 0}, {Rational(7, 2), 2}, {1, 3}, {-1, 1}, {0, 0}};
  const Boundary poly = make_boundary({polyline(pts)});
  const Boundary spline = make_boundary({bspline(1, {0, 0, 1, 2, 3, 4, 5, 5}, pts)});
  EXPECT_EQ(poly.mass.area, spline.mass.area);
  EXPECT_TRUE(eq(poly.mass.centroid, spline.mass.centroid));
  EXPECT_EQ(poly.mass.polar_moment, spline.mass.polar_moment);

  std::mt19937_64 rng(47);
  Curve c = random_bspline(rng, 3, 7, true);
  c.points.back() = c.points.front();  // a closed clamped loop (any orientation)
  std::vector<BezierPiece> pieces = c.bezier_pieces(0), split;
  for (const auto& piece : pieces) {
    const auto [l, r] = piece.split(Rational(2, 7));
    split.push_back(l);
    split.push_back(r);
  }
  const MassProperties a = mass_properties(pieces), b = mass_properties(split);
  EXPECT_EQ(a.area, b.area);
  EXPECT_EQ(a.polar_moment, b.polar_moment);
}

GTEST_TEST(MassProperties, ParabolicSegmentIsTwoThirdsOfItsControlTriangle) {
  // Archimedes: the region between a quadratic Bézier arc and its chord.
  const Vec2 P0{0, 0}, P1{2, 4}, P2{5, 1};
  const Boundary b =
      make_boundary({bspline(2, {0, 0, 0, 1, 1, 1}, {P2, P1, P0}), polyline({P0, P2})});  // counter-clockwise
  const Rational triangle = ((P1.x - P0.x) * (P2.y - P0.y) - (P1.y - P0.y) * (P2.x - P0.x)) / 2;
  EXPECT_EQ(b.mass.area, Rational(2, 3) * boost::multiprecision::abs(triangle));
}

GTEST_TEST(MassProperties, InscribedPolygonsApproachTheCurveFromBelow) {
  // A convex closed cubic: inscribed polygons have less area, growing with N.
  const Scene scene = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/fig6.json");
  const Curve& c = scene.body.boundary->curves[0];
  Rational previous = 0;
  for (int N : {8, 16, 32, 64}) {
    std::vector<Vec2> pts;
    for (int k = 0; k <= N; ++k) pts.push_back(c.point(c.u_begin() + (c.u_end() - c.u_begin()) * Rational(k, N)));
    const Rational area = make_boundary({polyline(pts)}).mass.area;
    EXPECT_LT(area, scene.body.boundary->mass.area);
    EXPECT_GT(area, previous);
    previous = area;
  }
}

GTEST_TEST(Scene, BoundaryGivesMassCentreAndInertia) {
  const std::string text = R"({"time_step": "1",
    "body": {"dof": 3, "mass": "2",
             "boundary": [{"type": "polyline", "points": [["0","0"],["4","0"],["4","2"],["0","2"],["0","0"]]}]},
    "fixels": [{"point": ["0","1"], "normal": ["1","0"], "mu": "0", "gap": "1/10"},
               {"point": ["1","0"], "normal": ["0","1"], "mu": "0", "gap": "1/10"},
               {"point": ["3","0"], "normal": ["0","1"], "mu": "0", "gap": "1/10"}]})";
  const Scene s = parse_scene(text);
  EXPECT_TRUE(eq(s.body.p_AoCm_A, Vec2{2, 1}));
  EXPECT_EQ(s.body.inertia, Rational(2) * (16 + 4) / 12);  // m (a² + b²) / 12
  EXPECT_EQ(s.lever_arm(0).x, Rational(-2));
  // Without a mass, density 1: m = area.
  std::string no_mass = text;
  no_mass.erase(no_mass.find(R"("mass": "2",)"), 12);
  EXPECT_EQ(parse_scene(no_mass).body.mass, Rational(8));
}

// A B-spline's Bézier pieces poll the calling thread's ControlScope (a
// curve of high degree with long numbers took seconds to load).
GTEST_TEST(Curve, BSplinePiecesStopInsideACancelledControlScope) {
  std::mt19937_64 rng(7);
  const Curve c = random_bspline(rng, 3, 6, false);
  EXPECT_NO_THROW(c.bezier_pieces(0));
  const test::CancelledControl cancelled;
  const ControlScope scope(&cancelled.control);
  EXPECT_EQ(
      test::stop_message([&] { c.bezier_pieces(0); }).rfind("a B-spline's Bezier pieces: interrupted after 0 ", 0), 0u);
}
// The mass properties poll their control at every piece: a degree-20
// B-spline's 40 pieces on long numbers took seconds each, and a poll every
// 256 pieces let a load run 8-115 s past its limit.
GTEST_TEST(Curve, MassPropertiesPollEveryPiece) {
  std::mt19937_64 rng(3);
  const Curve c = random_bspline(rng, 3, 9, true);
  const auto pieces = c.bezier_pieces(0);
  ASSERT_GE(pieces.size(), 3u);
  RunControl control;
  control.interval = std::chrono::milliseconds(0);
  control.start = RunControl::Clock::now() - std::chrono::seconds(1);
  std::vector<long> done;
  control.on_progress = [&](const char*, long d, long total, const char*) {
    EXPECT_EQ(total, static_cast<long>(pieces.size()));
    done.push_back(d);
  };
  mass_properties(pieces, &control);
  ASSERT_EQ(done.size(), pieces.size());
  for (std::size_t k = 0; k < done.size(); ++k) EXPECT_EQ(done[k], static_cast<long>(k));
}

}  // namespace
}  // namespace fixel
