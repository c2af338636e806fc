#include "fixel/polyhedron.h"

#include <gtest/gtest.h>

#include <random>

#include "fixel/error.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::v2;

Polyhedron unit_square() {
  Polyhedron P;
  P.dim = 2;
  P.closed = {{v2(1, 0), 0}, {v2(0, 1), 0}, {v2(-1, 0), -1}, {v2(0, -1), -1}};
  return P;
}

GTEST_TEST(Polyhedron, MembershipOfAPointOfTheWrongLengthIsAnInputError) {
  Polyhedron P;
  P.dim = 3;
  P.closed.push_back(Halfspace{VectorQ::Ones(3), Rational(0)});
  EXPECT_TRUE(P.contains(VectorQ::Ones(3)));
  EXPECT_THROW(P.contains(VectorQ::Ones(2)), InputError);
  EXPECT_THROW(P.closed[0].contains(VectorQ::Ones(4)), InputError);
}

GTEST_TEST(Polyhedron, EmptinessHonoursStrictRows) {
  Polyhedron P = unit_square();
  EXPECT_FALSE(is_empty(P));
  P.strict.push_back({v2(1, 0), 1});  // x > 1 with x <= 1
  EXPECT_TRUE(is_empty(P));
  Polyhedron Q = unit_square();
  Q.closed.push_back({v2(1, 0), 1});  // x >= 1: the right edge
  EXPECT_FALSE(is_empty(Q));
}

GTEST_TEST(Polyhedron, SubtractGivesDisjointPiecesCoveringTheDifference) {
  Polyhedron Q = unit_square();
  Polyhedron P;
  P.dim = 2;
  P.closed = {{v2(1, 0), Rational(1, 2)}};
  P.strict = {{v2(0, 1), Rational(1, 2)}};  // x >= 1/2, y > 1/2
  const auto pieces = subtract(Q, P);
  std::mt19937_64 rng(5);
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const VectorQ p = v2(Rational(i, 8), Rational(j, 8));
      int count = 0;
      for (const auto& piece : pieces) count += piece.contains(p) ? 1 : 0;
      EXPECT_EQ(count, Q.contains(p) && !P.contains(p) ? 1 : 0) << i << "," << j;
    }
}

GTEST_TEST(Polyhedron, ProjectionEliminatesEqualitiesAndFreeVariables) {
  // {p : ∃x1, x2: x1 = p1 + p2, 0 <= x2 <= x1 − 1, x2 > p2 − 3} = {p1 + p2 >= 1, p1 + 2... }
  LiftedSystem s;
  s.nx = 2;
  s.np = 2;
  s.A_eq = MatrixQ(1, 4);
  s.A_eq << 1, 0, -1, -1;
  s.b_eq = VectorQ::Zero(1);
  s.A_in = MatrixQ(3, 4);
  s.A_in << 0, 1, 0, 0,  // x2 >= 0
      1, -1, 0, 0,       // x1 − x2 >= 1
      0, 1, 0, -1;       // x2 − p2 > −3
  s.b_in = VectorQ(3);
  s.b_in << 0, 1, -3;
  s.strict_in = {false, false, true};
  const Polyhedron P = project_out_x(s);
  // Second method: for p on a grid decide ∃x2 directly: x2 ∈ [0, p1+p2−1] ∩ (p2−3, ∞).
  for (int i = -8; i <= 8; ++i)
    for (int j = -8; j <= 8; ++j) {
      const Rational p1(i, 2), p2(j, 2);
      const Rational hi = p1 + p2 - 1, lo = p2 - 3;
      const bool exists = hi >= 0 && hi > lo;
      EXPECT_EQ(P.contains(v2(p1, p2)), exists) << to_string(p1) << "," << to_string(p2);
    }
}

GTEST_TEST(Polyhedron, RayMagnitudesWithStrictRowsHaveOpenEnds) {
  Polyhedron P = unit_square();
  P.strict.push_back({v2(-1, 0), Rational(-1, 2)});  // x < 1/2
  const Magnitudes T = ray_magnitudes(P, v2(0, 0), v2(1, 1));
  EXPECT_FALSE(T.empty);
  EXPECT_TRUE(T.contains(Rational(1, 4)));
  EXPECT_FALSE(T.contains(Rational(1, 2)));
  EXPECT_FALSE(T.hi_closed);
}

GTEST_TEST(Polyhedron, ProjectionDropsRowsWithAZeroLeftSide) {
  // {p : ∃x: x >= p, −x >= −p − 1, x >= 0, −x >= −5}: Fourier–Motzkin pairs
  // x >= 0 with −x >= −5 into 0 >= −5 (always true: dropped) and
  // x >= p with −x >= −p − 1 into 0 >= −1 (dropped too).
  LiftedSystem s;
  s.nx = 1;
  s.np = 1;
  s.A_eq = MatrixQ(0, 2);
  s.b_eq = VectorQ(0);
  s.A_in = MatrixQ(4, 2);
  s.A_in << 1, -1, -1, 1, 1, 0, -1, 0;
  s.b_in = VectorQ(4);
  s.b_in << 0, -1, 0, -5;
  s.strict_in = {false, false, false, true};
  const Polyhedron P = project_out_x(s);
  for (const auto& h : P.closed) EXPECT_FALSE(h.a.isZero()) << to_string(h.c);
  for (const auto& h : P.strict) EXPECT_FALSE(h.a.isZero()) << to_string(h.c);
  for (int i = -12; i <= 12; ++i) {
    const Rational p(i, 2);  // x ∈ [max(p, 0), min(p + 1, 5)) is non-empty iff −1 <= p < 5
    VectorQ v(1);
    v << p;
    EXPECT_EQ(P.contains(v), p >= -1 && p < 5) << to_string(p);
  }
  // x >= 1 and −x > −1 project to 0 > 0: no p at all, the canonical empty form.
  s.A_in = MatrixQ(2, 2);
  s.A_in << 1, 0, -1, 0;
  s.b_in = VectorQ(2);
  s.b_in << 1, -1;
  s.strict_in = {false, true};
  const Polyhedron E = project_out_x(s);
  EXPECT_TRUE(E.is_trivially_empty());
  EXPECT_TRUE(is_empty(E));
  EXPECT_FALSE(P.is_trivially_empty());
}

GTEST_TEST(Polyhedron, AffineDimensionCountsImplicitEqualities) {
  EXPECT_EQ(affine_dimension(unit_square()), 2);
  Polyhedron edge = unit_square();
  edge.closed.push_back({v2(-1, 0), 0});  // x <= 0 with x >= 0: the left edge
  EXPECT_EQ(affine_dimension(edge), 1);
  Polyhedron corner = edge;
  corner.closed.push_back({v2(0, -1), 0});  // and y <= 0: the corner (0, 0)
  EXPECT_EQ(affine_dimension(corner), 0);
  Polyhedron open = unit_square();
  open.strict.push_back({v2(1, 1), Rational(1, 2)});  // x + y > 1/2: still two-dimensional
  EXPECT_EQ(affine_dimension(open), 2);
  Polyhedron none = edge;
  none.strict.push_back({v2(1, 0), 0});  // x > 0 on the edge x = 0
  EXPECT_EQ(affine_dimension(none), -1);
}

}  // namespace
}  // namespace fixel
