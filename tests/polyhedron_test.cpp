#include "fixel/polyhedron.h"

#include <gtest/gtest.h>

#include <functional>

#include <algorithm>
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

// The definition, row by row: a closed row is an implicit equality iff P
// with that row made strict is empty (the second method for the test below).
int affine_dimension_row_by_row(const Polyhedron& P) {
  if (is_empty(P)) return -1;
  MatrixQ equalities(0, P.dim);
  for (std::size_t k = 0; k < P.closed.size(); ++k) {
    if (P.closed[k].a.isZero()) continue;
    Polyhedron strict_here = P;
    strict_here.closed.erase(strict_here.closed.begin() + static_cast<long>(k));
    strict_here.strict.push_back(P.closed[k]);
    if (!is_empty(strict_here)) continue;
    equalities.conservativeResize(equalities.rows() + 1, P.dim);
    equalities.row(equalities.rows() - 1) = P.closed[k].a.transpose();
  }
  // Rank by fraction-free elimination on the rows.
  int rank = 0;
  for (int col = 0; col < P.dim && rank < equalities.rows(); ++col) {
    int pivot = rank;
    while (pivot < equalities.rows() && equalities(pivot, col) == 0) ++pivot;
    if (pivot == equalities.rows()) continue;
    equalities.row(rank).swap(equalities.row(pivot));
    for (int r = rank + 1; r < equalities.rows(); ++r)
      equalities.row(r) = equalities(rank, col) * equalities.row(r) - equalities(r, col) * equalities.row(rank);
    ++rank;
  }
  return P.dim - rank;
}

GTEST_TEST(Polyhedron, AffineDimensionAgreesWithTheRowByRowDefinitionOnRandomPolyhedra) {
  // Around a point x0: 3 − d equalities hidden as rows whose sum is zero
  // (each alone an inequality), random rows with slack at x0, random rows
  // tight at x0 (not equalities in general position), strict rows with
  // slack; every fifth one also gets a strict row no point can meet.
  std::mt19937_64 rng(2026);
  auto random_vector = [&] {
    VectorQ v(3);
    for (int j = 0; j < 3; ++j) v[j] = test::random_rational(rng, -3, 3, 5);
    return v;
  };
  int by_dimension[5] = {0, 0, 0, 0, 0};
  for (int trial = 0; trial < 60; ++trial) {
    const int d = trial % 4;
    const VectorQ x0 = random_vector();
    Polyhedron P;
    P.dim = 3;
    VectorQ sum = VectorQ::Zero(3);
    for (int e = 0; e < 3 - d; ++e) {
      const VectorQ a = random_vector();
      P.closed.push_back({a, a.dot(x0)});
      sum += a;
    }
    if (d < 3) P.closed.push_back({VectorQ(-sum), Rational(-sum.dot(x0))});
    for (int r = 0; r < 4; ++r) {
      const VectorQ a = random_vector();
      P.closed.push_back({a, a.dot(x0) - test::random_rational(rng, 1, 4, 3)});
    }
    const VectorQ tight = random_vector();
    if (d > 0) P.closed.push_back({tight, tight.dot(x0)});
    const VectorQ open = random_vector();
    P.strict.push_back({open, open.dot(x0) - test::random_rational(rng, 1, 2, 3)});
    int expected = d;
    if (trial % 5 == 4) {
      P.strict.push_back({VectorQ(-open), Rational(-open.dot(x0) + 3)});  // a·p < a·x0 − 3 with a·p > a·x0 − 2
      expected = -1;
    }
    std::shuffle(P.closed.begin(), P.closed.end(), rng);
    const int dimension = affine_dimension(P);
    EXPECT_EQ(dimension, affine_dimension_row_by_row(P)) << "trial " << trial;
    EXPECT_EQ(dimension, expected) << "trial " << trial;
    ++by_dimension[dimension + 1];
  }
  for (int k = 0; k < 5; ++k) EXPECT_GT(by_dimension[k], 0) << "no polyhedron of dimension " << k - 1;
}

// Rows whose length is not P.dim (dim defaults to 3): is_empty and
// affine_dimension read past 2-vectors, subtract and intersect mixed spaces
// and answered wrongly. Each is an InputError naming the row or dim.
GTEST_TEST(Polyhedron, RowsThatDoNotMatchDimAreAnInputErrorNamingTheRow) {
  Polyhedron flat;  // dim left at 3, rows of the plane
  flat.closed = {{v2(1, 0), 0}};
  for (const auto& ask :
       std::vector<std::function<void()>>{[&] { is_empty(flat); }, [&] { affine_dimension(flat); },
                                          [&] { ray_magnitudes(flat, VectorQ::Zero(3), VectorQ::Ones(3)); }}) {
    try {
      ask();
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "P.closed[0]");
    }
  }
  Polyhedron space;  // {x >= 0} in R^3
  space.closed = {{VectorQ::Unit(3, 0), 0}};
  const Polyhedron square = unit_square();
  EXPECT_THROW(subtract(square, space), InputError);
  EXPECT_THROW(square.intersect(space), InputError);
  EXPECT_THROW(space.contains(VectorQ::Zero(2)), InputError);
  // The same questions in one space are answered (the unit square minus
  // {x >= 0} is empty: every point of it has x >= 0).
  Polyhedron half = square;
  half.closed = {{v2(1, 0), 0}};
  EXPECT_TRUE(subtract(square, half).empty());
  EXPECT_EQ(affine_dimension(square), 2);
}

GTEST_TEST(Polyhedron, ALiftedSystemOfInconsistentSizesIsAnInputError) {
  LiftedSystem s;
  s.nx = 1;
  s.np = 2;
  s.A_in = MatrixQ::Zero(2, 3);
  s.b_in = VectorQ::Zero(2);
  s.strict_in = {false, false};
  EXPECT_NO_THROW(project_out_x(s));
  LiftedSystem few_flags = s;
  few_flags.strict_in = {false};
  EXPECT_THROW(project_out_x(few_flags), InputError);
  LiftedSystem wide_x = s;
  wide_x.nx = 50;
  EXPECT_THROW(project_out_x(wide_x), InputError);
  LiftedSystem negative = s;
  negative.nx = -1;
  EXPECT_THROW(project_out_x(negative), InputError);
}

}  // namespace
}  // namespace fixel
