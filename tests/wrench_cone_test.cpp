#include "fixel/wrench_cone.h"

#include <gtest/gtest.h>

#include <random>

#include "fixel/cone.h"
#include "fixel/error.h"
#include "fixel/internal/wrench_cone_detail.h"
#include "fixel/lcp.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "test_util.h"

namespace fixel {
namespace {

// The exact contact wrench (d, r ⊗ d) at local parameter s of a segment.
VectorQ exact_wrench(const BezierPiece& seg, const Rational& s, const Vec2& com, const Vec2& d) {
  return contact_wrench(sub(seg.point(s), com), d, 3);
}

BezierPiece random_piece(std::mt19937_64& rng, int degree) {
  BezierPiece piece{0, Rational(0), Rational(1), {}};
  for (int i = 0; i <= degree; ++i)
    piece.control.push_back({test::random_rational(rng, -2, 2, 9), test::random_rational(rng, -2, 2, 9)});
  return piece;
}

// Containment: every exact wrench of every family at many rational points
// of many random segments lies in the segment's cone, for both methods.
GTEST_TEST(WrenchCone, HoldsEveryContactWrenchOfRandomSegments) {
  std::mt19937_64 rng(53);
  int checked = 0, pointed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    BezierPiece piece = random_piece(rng, 1 + trial % 3 + (trial % 5 == 0 ? 2 : 0));
    // Sub-segments of random pieces, as subdivision produces them.
    const Rational a = test::random_rational(rng, 0, 1, 8),
                   b = a + Rational(1, 8) + test::random_rational(rng, 0, 1, 16) / 2;
    if (b < 1) piece = piece.restrict_to(a, b);
    const Vec2 com{test::random_rational(rng, -1, 1, 5), test::random_rational(rng, -1, 1, 5)};
    const Rational mu = Rational(trial % 4, 5);
    const SegmentBounds bounds = segment_bounds(piece);
    if (!bounds.pointed) continue;
    ++pointed;
    for (auto family : {EdgeFamily::kNormal, EdgeFamily::kMinus, EdgeFamily::kPlus, EdgeFamily::kWholeCone}) {
      for (auto method : {ConeMethod::kTight, ConeMethod::kPaper}) {
        const auto cone = segment_wrench_cone(bounds, com, family, mu, method);
        if (!cone) continue;  // friction widened the directions to π
        for (int k = 0; k <= 16; ++k) {
          const Rational s = Rational(k, 16) + (k < 16 ? test::random_rational(rng, 0, 1, 97) / 16 : Rational(0));
          const Vec2 T = piece.derivative(s);
          std::vector<Vec2> dirs;
          if (family == EdgeFamily::kWholeCone) {
            const Rational lambda = mu * test::random_rational(rng, -1, 1, 13);
            const Vec2 n = push_direction(T, EdgeFamily::kNormal, mu), t{-n.y, n.x};
            dirs = {push_direction(T, EdgeFamily::kMinus, mu),
                    push_direction(T, EdgeFamily::kPlus, mu),
                    {n.x + lambda * t.x, n.y + lambda * t.y}};
          } else {
            dirs = {push_direction(T, family, mu)};
          }
          for (const auto& d : dirs) {
            EXPECT_TRUE(cone->contains(exact_wrench(piece, s, com, d)))
                << "trial " << trial << " family " << to_string(family) << " method " << static_cast<int>(method);
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_GT(pointed, 150);
  EXPECT_GT(checked, 20000);
}

GTEST_TEST(WrenchCone, TightConeLiesInsideThePaperCone) {
  std::mt19937_64 rng(59);
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const BezierPiece piece = random_piece(rng, 3);
    const Vec2 com{test::random_rational(rng, -1, 1, 5), test::random_rational(rng, -1, 1, 5)};
    for (auto family : {EdgeFamily::kNormal, EdgeFamily::kPlus, EdgeFamily::kWholeCone}) {
      const auto tight = segment_wrench_cone(piece, com, family, Rational(1, 5), ConeMethod::kTight);
      const auto paper = segment_wrench_cone(piece, com, family, Rational(1, 5), ConeMethod::kPaper);
      if (!tight || !paper) continue;
      for (const auto& g : tight->generators) EXPECT_TRUE(paper->contains(g)) << "trial " << trial;
      ++compared;
    }
  }
  EXPECT_GT(compared, 200);
}

// The paper's cone without the cos(Δ/2) correction does not hold the paper's
// own bound {unit d in [θ_s, θ_e]} × [X_min, X_max] when all moments are
// positive: the mid-arc direction at X_min is outside. Found exactly.
GTEST_TEST(WrenchCone, PaperConeAsPrintedIsNotConservativeWhenMomentsShareASign) {
  // A quarter arc whose inward normals sweep (−1, 0) → (0, −1), with the
  // centre of mass placed so that every moment is positive.
  const BezierPiece piece{0, Rational(0), Rational(1), {{10, 0}, {10, 10}, {0, 10}}};
  const Vec2 com{20, -20};
  const SegmentBounds b = segment_bounds(piece);
  const auto corrected = segment_wrench_cone(b, com, EdgeFamily::kNormal, 0, ConeMethod::kPaper);
  ASSERT_TRUE(corrected);
  // Uncorrected: the same unit directions with the raw X_min.
  const VectorQ& g0 = corrected->generators[0];
  const Vec2 us{g0[0], g0[1]}, ue{corrected->generators[2][0], corrected->generators[2][1]};
  Rational xmin = 0;
  bool first = true;
  for (const auto& p : b.hull)
    for (const Vec2& u : {us, ue}) {
      const Rational x = cross(sub(p, com), u);
      if (first || x < xmin) xmin = x;
      first = false;
    }
  ASSERT_GT(xmin, 0);
  std::vector<VectorQ> raw;
  for (const Vec2& u : {us, ue}) {
    VectorQ lo(3), hi(3);
    lo << u.x, u.y, xmin;
    hi << u.x, u.y, Rational(1000);
    raw.push_back(lo);
    raw.push_back(hi);
  }
  WrenchCone uncorrected{raw, cone_facet_normals(raw, 3)};
  // Mid-arc unit direction at the point where X is smallest.
  const Vec2 d = internal::unit_direction_outward({-1, -1}, true);
  VectorQ w(3);
  w << d.x, d.y, xmin;
  EXPECT_FALSE(uncorrected.contains(w));
  EXPECT_TRUE(corrected->contains(w));
}

GTEST_TEST(WrenchCone, Fig6SegmentConeHoldsTheDenselySampledFrictionCone) {
  const Scene scene = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/fig6.json");
  const BezierPiece& seg = scene.body.boundary->pieces.front();  // the four leftmost control points
  ASSERT_EQ(seg.u0, Rational(3));
  const Rational mu = scene.pusher_mu;  // 1/5
  for (auto method : {ConeMethod::kTight, ConeMethod::kPaper}) {
    const auto cone = segment_wrench_cone(seg, scene.body.p_AoCm_A, EdgeFamily::kWholeCone, mu, method);
    ASSERT_TRUE(cone);
    for (int k = 0; k <= 1000; ++k) {
      const Rational s(k, 1000);
      const Vec2 T = seg.derivative(s);
      for (auto family : {EdgeFamily::kNormal, EdgeFamily::kMinus, EdgeFamily::kPlus})
        ASSERT_TRUE(cone->contains(exact_wrench(seg, s, scene.body.p_AoCm_A, push_direction(T, family, mu)))) << k;
    }
  }
}

GTEST_TEST(WrenchCone, RepeatedControlPointsStillGiveAConeHoldingEveryPushWhereTheTangentLives) {
  const BezierPiece piece{0, Rational(0), Rational(1), {{0, 0}, {0, 0}, {1, 1}, {2, 1}}};
  const auto cone = segment_wrench_cone(piece, {0, 0}, EdgeFamily::kNormal, 0, ConeMethod::kTight);
  ASSERT_TRUE(cone);
  for (int k = 1; k <= 8; ++k)  // the tangent vanishes only at s = 0
    EXPECT_TRUE(cone->contains(exact_wrench(piece, Rational(k, 8), {0, 0},
                                            push_direction(piece.derivative(Rational(k, 8)), EdgeFamily::kNormal, 0))));
}

GTEST_TEST(WrenchCone, CuspAndFullTurnSegmentsNeedSplitting) {
  const BezierPiece cusp{0, Rational(0), Rational(1), {{0, 0}, {1, 1}, {0, 1}, {1, 0}}};
  EXPECT_FALSE(segment_bounds(cusp).pointed);
  EXPECT_FALSE(segment_wrench_cone(cusp, {0, 0}, EdgeFamily::kNormal, 0, ConeMethod::kTight));
  const BezierPiece loop{0, Rational(0), Rational(1), {{0, 0}, {2, 0}, {2, 2}, {-1, 2}, {-1, -1}, {1, -1}}};
  EXPECT_FALSE(segment_bounds(loop).pointed);
}

GTEST_TEST(WrenchCone, StraightCubicHasAZeroWidthDirectionCone) {
  const BezierPiece line{0, Rational(0), Rational(1), {{0, 0}, {1, 0}, {2, 0}, {4, 0}}};
  const auto cone = segment_wrench_cone(line, {1, 1}, EdgeFamily::kNormal, 0, ConeMethod::kTight);
  ASSERT_TRUE(cone);
  for (int k = 0; k <= 8; ++k) EXPECT_TRUE(cone->contains(exact_wrench(line, Rational(k, 8), {1, 1}, {0, 1})));
  VectorQ off(3);
  off << Rational(1, 1000), 1, 0;  // a direction not normal to the line
  EXPECT_FALSE(cone->contains(off));
  EXPECT_TRUE(segment_wrench_cone(line, {1, 1}, EdgeFamily::kNormal, 0, ConeMethod::kPaper));
}

// A negative μ swapped the friction edges: the cone came back "not
// pointed, split the segment" for every sub-segment, forever; a short
// wrench was read past its end.
GTEST_TEST(WrenchCone, ANegativeFrictionAndAShortWrenchAreInputErrors) {
  const BezierPiece line{0, Rational(0), Rational(1), {{0, 0}, {1, 0}}};
  for (const EdgeFamily family : {EdgeFamily::kWholeCone, EdgeFamily::kMinus, EdgeFamily::kPlus}) {
    EXPECT_THROW(segment_wrench_cone(line, {0, 1}, family, Rational(-1, 2), ConeMethod::kTight), InputError);
    EXPECT_THROW(push_direction({1, 0}, family, Rational(-1, 2)), InputError);
  }
  const auto cone = segment_wrench_cone(line, {0, 1}, EdgeFamily::kNormal, 0, ConeMethod::kTight);
  ASSERT_TRUE(cone);
  try {
    cone->contains(test::v2(1, 1));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "w");
  }
}

GTEST_TEST(WrenchCone, AllZeroLegsIsADegenerateError) {
  const BezierPiece point{0, Rational(0), Rational(1), {{1, 1}, {1, 1}, {1, 1}}};
  EXPECT_THROW(segment_bounds(point), SceneError);
}

GTEST_TEST(CornerCone, HoldsTheWholeFanOfNormalsAtAPolylineCorner) {
  // Corner (2, 0) of the polyline (0,0) → (2,0) → (2,2): normals (0,1) then (−1,0).
  const Vec2 r{2, 0}, n_in{0, 1}, n_out{-1, 0};
  const WrenchCone cone = internal::corner_cone(r, n_in, n_out);
  for (int k = 0; k <= 10; ++k) {
    const Vec2 d{-Rational(k, 10), 1 - Rational(k, 10)};
    EXPECT_TRUE(cone.contains(contact_wrench(r, d, 3)));
  }
  EXPECT_FALSE(cone.contains(contact_wrench(r, {1, 1}, 3)));
}

GTEST_TEST(UnitDirection, IsExactlyUnitAndOnTheRequestedSide) {
  std::mt19937_64 rng(61);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec2 d{test::random_rational(rng, -3, 3, 11), test::random_rational(rng, -3, 3, 11)};
    if (d.x == 0 && d.y == 0) continue;
    for (bool cw : {true, false}) {
      const Vec2 u = internal::unit_direction_outward(d, cw);
      EXPECT_EQ(u.x * u.x + u.y * u.y, Rational(1));
      EXPECT_GE(cw ? cross(u, d) : cross(d, u), 0);
      EXPECT_GT(u.x * d.x + u.y * d.y, 0);  // close to d, not its opposite
    }
  }
  EXPECT_GE(internal::sqrt_upper(Rational(2)) * internal::sqrt_upper(Rational(2)), Rational(2));
  EXPECT_LE(internal::sqrt_lower(Rational(2)) * internal::sqrt_lower(Rational(2)), Rational(2));
}

// The grid point τ = k/2^20 of u: tan(θ/2) = sin θ/(1 + cos θ), of −u when
// d points left (d.x < 0).
Rational grid_tau(const Vec2& u, bool flip) { return flip ? -u.y / (1 - u.x) : u.y / (1 + u.x); }

Vec2 grid_point(const Rational& tau, bool flip) {
  const Rational n = 1 + tau * tau;
  const Vec2 u{(1 - tau * tau) / n, 2 * tau / n};
  return flip ? Vec2{-u.x, -u.y} : u;
}

GTEST_TEST(UnitDirection, IsTheNearestGridPointOnItsSideAndDItselfWhenOnTheGrid) {
  // On the grid: the axes (τ = 0 and ±1, flipped or not) and (3, 4)/5 = u(1/2).
  const std::pair<Vec2, Vec2> on_grid[] = {{{2, 0}, {1, 0}},
                                           {{0, 5}, {0, 1}},
                                           {{-1, 0}, {-1, 0}},
                                           {{0, -3}, {0, -1}},
                                           {{3, 4}, {Rational(3, 5), Rational(4, 5)}},
                                           {{-6, -8}, {Rational(-3, 5), Rational(-4, 5)}},
                                           {{3, -4}, {Rational(3, 5), Rational(-4, 5)}}};
  for (const auto& [d, unit] : on_grid)
    for (bool cw : {true, false}) {
      const Vec2 u = internal::unit_direction_outward(d, cw);
      EXPECT_EQ(u.x, unit.x) << to_string(d.x) << ", " << to_string(d.y) << (cw ? " cw" : " ccw");
      EXPECT_EQ(u.y, unit.y) << to_string(d.x) << ", " << to_string(d.y) << (cw ? " cw" : " ccw");
    }
  std::mt19937_64 rng(63);
  const Rational step(1, 1048576);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec2 d{test::random_rational(rng, -3, 3, 11), test::random_rational(rng, -3, 3, 11)};
    if (d.x == 0 && d.y == 0) continue;
    const bool flip = d.x < 0;
    for (bool cw : {true, false}) {
      const Vec2 u = internal::unit_direction_outward(d, cw);
      const Rational tau = grid_tau(u, flip);
      EXPECT_EQ(boost::multiprecision::denominator(Rational(tau / step)), 1);  // on the grid
      EXPECT_EQ(grid_point(tau, flip).x, u.x);
      // The next grid point inward is on the other side of d (strictly).
      const Vec2 inner = grid_point(cw ? tau + step : tau - step, flip);
      EXPECT_LT(cw ? cross(inner, d) : cross(d, inner), 0);
    }
  }
}

}  // namespace
}  // namespace fixel
