#include "fixel/on_boundary.h"

#include <gtest/gtest.h>

#include <cmath>

#include "fixel/error.h"
#include "test_util.h"

namespace fixel {
namespace {

Vec2 v(Rational x, Rational y) { return {x, y}; }

// The unit square, counter-clockwise, as one polyline.
Boundary square() {
  Curve c;
  c.points = {v(0, 0), v(1, 0), v(1, 1), v(0, 1), v(0, 0)};
  return make_boundary({c});
}

// A loop whose first curve, x = s², y = s⁴ + s²/3 (s ∈ [0, 1], degree 4),
// passes through (1/2, 5/12) at the irrational s = 1/√2, where its tangent
// is along (3, 4): the inward normal there is the rational (−4/5, 3/5).
Boundary quartic_loop() {
  Curve c;
  c.type = Curve::Type::kBSpline;
  c.degree = 4;
  c.points = {v(0, 0), v(0, 0), v(Rational(1, 6), Rational(1, 18)), v(Rational(1, 2), Rational(1, 6)),
              v(1, Rational(4, 3))};
  c.knots = {0, 0, 0, 0, 0, 1, 1, 1, 1, 1};
  Curve back;
  back.points = {v(1, Rational(4, 3)), v(0, Rational(4, 3)), v(0, 0)};
  return make_boundary({c, back});
}

GTEST_TEST(OnBoundary, APointOnAnEdgeWithTheEdgesInwardNormalFits) {
  const Vec2 n = v(0, 1);
  const BoundaryFit fit = fit_to_boundary(square(), v(Rational(1, 3), 0), &n);
  EXPECT_TRUE(fit.on_boundary);
  EXPECT_TRUE(fit.normal_matches);
  ASSERT_TRUE(fit.u);
  EXPECT_EQ(*fit.u, Rational(1, 3));
  EXPECT_FALSE(fit.corner);
}

GTEST_TEST(OnBoundary, AnOutwardNormalOnAnEdgeDoesNotMatch) {
  const Vec2 n = v(0, -1);
  const BoundaryFit fit = fit_to_boundary(square(), v(Rational(1, 3), 0), &n);
  EXPECT_TRUE(fit.on_boundary);
  EXPECT_FALSE(fit.normal_matches);
  EXPECT_EQ(fit.angle_degrees, 180.0);
}

GTEST_TEST(OnBoundary, AFarPointIsOffTheOutlineWithItsDistance) {
  const BoundaryFit fit = fit_to_boundary(square(), v(10, 10));
  EXPECT_FALSE(fit.on_boundary);
  EXPECT_NEAR(fit.distance, std::sqrt(2.0) * 9, 1e-9);  // display figure only
  // A point inside the square, a hair off the edge, is off too (exact).
  EXPECT_FALSE(fit_to_boundary(square(), v(Rational(1, 2), Rational(1, 1000000000))).on_boundary);
}

GTEST_TEST(OnBoundary, AtACornerAnyNormalBetweenTheTwoEdgeNormalsMatches) {
  const Vec2 inside = v(Rational(3, 5), Rational(4, 5)), outside = v(Rational(-3, 5), Rational(4, 5));
  const BoundaryFit fit = fit_to_boundary(square(), v(0, 0), &inside);
  EXPECT_TRUE(fit.on_boundary);
  EXPECT_TRUE(fit.corner);
  EXPECT_TRUE(fit.normal_matches);
  EXPECT_FALSE(fit_to_boundary(square(), v(0, 0), &outside).normal_matches);
}

GTEST_TEST(OnBoundary, APointOnACurvedPieceAtAnIrrationalParameterIsDecidedExactly) {
  const Boundary b = quartic_loop();
  const Vec2 p = v(Rational(1, 2), Rational(5, 12)), inward = v(Rational(-4, 5), Rational(3, 5)),
             outward = v(Rational(4, 5), Rational(-3, 5)), tilted = v(Rational(-3, 5), Rational(4, 5));
  const BoundaryFit fit = fit_to_boundary(b, p, &inward);
  EXPECT_TRUE(fit.on_boundary);
  EXPECT_TRUE(fit.normal_matches);
  EXPECT_FALSE(fit.u);  // s = 1/√2 is irrational
  EXPECT_NEAR(fit.u_approx, std::sqrt(0.5), 1e-6);
  EXPECT_FALSE(fit_to_boundary(b, p, &outward).normal_matches);
  EXPECT_FALSE(fit_to_boundary(b, p, &tilted).normal_matches);
  EXPECT_FALSE(fit_to_boundary(b, v(Rational(1, 2), Rational(5, 12) + Rational(1, 1000000)), &inward).on_boundary);
}

GTEST_TEST(OnBoundary, ARationalParameterOnACurvedPieceGivesTheExactNormal) {
  const Boundary b = quartic_loop();  // s = 1/2: (1/4, 1/16 + 1/12), tangent (1, 1/2 + 1/3)
  const BoundaryFit fit = fit_to_boundary(b, v(Rational(1, 4), Rational(7, 48)));
  EXPECT_TRUE(fit.on_boundary);
  ASSERT_TRUE(fit.u);
  EXPECT_EQ(*fit.u, Rational(1, 2));
  ASSERT_TRUE(fit.inward_normal);
  EXPECT_EQ(cross(*fit.inward_normal, v(Rational(-5, 6), 1)), 0);
  EXPECT_GT(dot(*fit.inward_normal, v(Rational(-5, 6), 1)), 0);
}

GTEST_TEST(OnBoundary, ExactUnitNormalisesOnlyRationalLengths) {
  const auto u = exact_unit(v(3, 4));
  ASSERT_TRUE(u);
  EXPECT_EQ(u->x, Rational(3, 5));
  EXPECT_EQ(u->y, Rational(4, 5));
  EXPECT_FALSE(exact_unit(v(1, 1)));
}

GTEST_TEST(OnBoundary, TheSuggestedUnitNormalIsExactlyUnitAndWithinANanoradian) {
  for (double angle : {0.3, 2.0, -2.9, 3.14159, 1.0e-12}) {
    const Vec2 n = nearby_exact_unit(angle);
    EXPECT_EQ(n.x * n.x + n.y * n.y, 1) << angle;
    EXPECT_LT(std::abs(std::remainder(std::atan2(to_double(n.y), to_double(n.x)) - angle, 2 * M_PI)), 1e-9) << angle;
  }
}

// NaN went through an undefined cast to a 2,000-digit "unit vector".
GTEST_TEST(OnBoundary, ANonFiniteAngleHasNoSuggestedNormal) {
  for (double angle : {std::nan(""), HUGE_VAL, -HUGE_VAL}) EXPECT_THROW(nearby_exact_unit(angle), InputError) << angle;
}

}  // namespace
}  // namespace fixel
