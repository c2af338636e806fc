#include "fixel/internal/lemke_exact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "fixel/filter.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/lemke.h"
#include "fixel/rational.h"
#include "test_util.h"

namespace fixel::internal {
namespace {

// The reference, by a second method: A_β⁻¹ [A | b] by Eigen's exact LU;
// false when A_β is singular.
bool reference_tableau(const MatrixQ& A, const std::vector<int>& basis, MatrixQ& T) {
  const int n = static_cast<int>(A.rows());
  MatrixQ A_beta(n, n);
  for (int t = 0; t < n; ++t) A_beta.col(t) = A.col(basis[t]);
  const auto lu = exact_lu(A_beta);
  if (!lu.isInvertible()) return false;
  T = lu.solve(A);
  return true;
}

// Value of row t in the BasicValues form: num_t/den, over L_i more when
// basis[t] is w_i.
Rational value_of(const ScaledProblem& P, const std::vector<int>& basis, const BasicValues& v, int t) {
  Rational x(v.num[t], v.den);
  if (basis[t] < P.n()) x /= Rational(P.scale(basis[t]));
  return x;
}

struct RandomLcp {
  MatrixQ B;
  VectorQ b;
};

RandomLcp random_lcp(std::mt19937_64& rng, int n) {
  std::uniform_int_distribution<int> num(-6, 6), den(1, 7);
  RandomLcp p{MatrixQ(n, n), VectorQ(n)};
  for (int i = 0; i < n; ++i) {
    p.b[i] = Rational(num(rng), den(rng));
    for (int j = 0; j < n; ++j) p.B(i, j) = (rng() % 4 == 0) ? Rational(0) : Rational(num(rng), den(rng));
  }
  return p;
}

// A random basis: n distinct columns among w, z and z0.
std::vector<int> random_basis(std::mt19937_64& rng, int n) {
  std::vector<int> all(2 * n + 1);
  for (int v = 0; v <= 2 * n; ++v) all[v] = v;
  std::shuffle(all.begin(), all.end(), rng);
  return {all.begin(), all.begin() + n};
}

GTEST_TEST(ExactTableau, GivesTheSignsAndValuesOfTheTableauAtAnyBasis) {
  std::mt19937_64 rng(31);
  int checked = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const int n = 2 + trial % 4;
    const RandomLcp lcp = random_lcp(rng, n);
    const std::vector<int> basis = random_basis(rng, n);
    const MatrixQ A = test::lemke_tableau_data(lcp.B, lcp.b);
    MatrixQ T;
    if (!reference_tableau(A, basis, T)) continue;
    SCOPED_TRACE("trial " + std::to_string(trial));
    ScaledProblem P;
    P.assign(lcp.B, lcp.b);
    ExactTableau E;
    E.assign(P, basis);
    const int rhs = 2 * n + 1;
    for (int col = 0; col <= rhs; ++col)
      for (int t = 0; t < n; ++t)
        EXPECT_EQ(E.entry_sign(t, col), fixel::sign(T(t, col))) << "entry " << t << ", " << col;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int col = 0; col <= rhs; col += 3)
          EXPECT_EQ(E.cross_sign(i, j, col, n), fixel::sign(T(i, col) * T(j, n) - T(j, col) * T(i, n)));
    BasicValues values;
    E.basic_values(rhs, values);
    EXPECT_GT(values.den, 0);
    for (int t = 0; t < n; ++t) EXPECT_EQ(value_of(P, basis, values, t), T(t, rhs)) << "row " << t;
    // One pivot further, from this basis's columns alone.
    const int r = static_cast<int>(rng() % n);
    const int col = static_cast<int>(rng() % (2 * n + 1));
    std::vector<int> next = basis;
    next[r] = col;
    MatrixQ T_next;
    if (std::find(basis.begin(), basis.end(), col) == basis.end() && reference_tableau(A, next, T_next)) {
      ASSERT_TRUE(E.basic_values_after_pivot(r, col, rhs, values));
      for (int t = 0; t < n; ++t) EXPECT_EQ(value_of(P, next, values, t), T_next(t, rhs)) << "after pivot, row " << t;
    }
    ++checked;
  }
  EXPECT_GT(checked, 60);
}

GTEST_TEST(DixonBasicValues, GivesTheSameValuesWithMachineWordsAsWithGmp) {
  // Words on (B's block from the matrix's word copy, the w numerators'
  // sums in words) against words off (GMP throughout), value for value,
  // and both against the reference tableau. b's denominators of up to
  // 2^100 push y past the word bound in some trials, so that the integers
  // are gathered there although the matrix has words.
  std::mt19937_64 rng(33);
  int checked = 0, matrix_in_words = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 2 + trial % 11;
    RandomLcp lcp = random_lcp(rng, n);
    if (trial % 3 == 2)
      for (int i = 0; i < n; ++i)
        lcp.b[i] /= Rational((Integer(1) << 100) - 1 - Integer(static_cast<long>(rng() % 1000)));
    std::vector<int> basis(n);
    for (int i = 0; i < n; ++i) basis[i] = (rng() % 3) ? n + i : i;  // mostly z basic: a large block
    const MatrixQ A = test::lemke_tableau_data(lcp.B, lcp.b);
    MatrixQ T;
    if (!reference_tableau(A, basis, T)) continue;
    SCOPED_TRACE("trial " + std::to_string(trial));
    ScaledProblem P;
    P.assign(lcp.B, lcp.b);
    matrix_in_words += P.in_words();
    const int rhs = 2 * n + 1;
    std::vector<double> lo(n, -INFINITY), hi(n, INFINITY);
    BasicValues with_words, with_gmp;
    DixonTrace trace;
    ASSERT_TRUE(dixon_basic_values(P, basis, lo, hi, with_words, trace));
    set_dixon_words_allowed(false);
    const bool solved = dixon_basic_values(P, basis, lo, hi, with_gmp, trace);
    set_dixon_words_allowed(true);
    ASSERT_TRUE(solved);
    EXPECT_EQ(with_words.den, with_gmp.den);
    EXPECT_EQ(with_words.num, with_gmp.num);
    for (int t = 0; t < n; ++t) EXPECT_EQ(value_of(P, basis, with_words, t), T(t, rhs)) << "row " << t;
    ++checked;
  }
  EXPECT_GT(checked, 150);
  EXPECT_GT(matrix_in_words, 150);
}

GTEST_TEST(DixonBasicValues, GivesTheBasisValuesWithOrWithoutAUsefulHint) {
  // Complementary bases without z0: lifting's values against the
  // reference, once with exact enclosures as the hint and once with the
  // whole line (no help); the trace says lifting ran.
  std::mt19937_64 rng(32);
  int checked = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const int n = 2 + trial % 5;
    const RandomLcp lcp = random_lcp(rng, n);
    std::vector<int> basis(n);
    for (int i = 0; i < n; ++i) basis[i] = (rng() % 2) ? i : n + i;
    const MatrixQ A = test::lemke_tableau_data(lcp.B, lcp.b);
    MatrixQ T;
    if (!reference_tableau(A, basis, T)) continue;
    SCOPED_TRACE("trial " + std::to_string(trial));
    ScaledProblem P;
    P.assign(lcp.B, lcp.b);
    const int rhs = 2 * n + 1;
    std::vector<double> lo(n), hi(n), whole_lo(n, -INFINITY), whole_hi(n, INFINITY);
    for (int t = 0; t < n; ++t) {
      const double x = to_double(T(t, rhs));
      lo[t] = std::nextafter(x, -INFINITY);
      hi[t] = std::nextafter(x, INFINITY);
    }
    for (const bool useful : {true, false}) {
      BasicValues values;
      DixonTrace trace;
      ASSERT_TRUE(dixon_basic_values(P, basis, useful ? lo : whole_lo, useful ? hi : whole_hi, values, trace));
      EXPECT_GT(values.den, 0);
      for (int t = 0; t < n; ++t) EXPECT_EQ(value_of(P, basis, values, t), T(t, rhs)) << "row " << t;
      // Lifting ran unless short rows fixed every basic z (lemke_dixon_sparse.h).
      const auto basic_z = std::count_if(basis.begin(), basis.end(), [n](int v) { return v >= n; });
      if (trace.unknowns_eliminated < basic_z) {
        EXPECT_GT(trace.steps, 0);
      }
    }
    ++checked;
  }
  EXPECT_GT(checked, 100);
  // z0 basic: not a final basis, declined.
  const RandomLcp lcp = random_lcp(rng, 2);
  ScaledProblem P;
  P.assign(lcp.B, lcp.b);
  BasicValues values;
  DixonTrace trace;
  EXPECT_FALSE(dixon_basic_values(P, {4, 1}, {0, 0}, {0, 0}, values, trace));
}

// The filtered run's own final check, on values solved by hand for
// B = [[1/2, 0], [1, 1]], b = (−1, 1/3): at the basis (z_1, w_2), z_1 = 2 and
// w_2 = 7/3. Row scales L = (2, 3), so with den = 1 the integers are
// num = (z_1, 3·w_2) = (2, 7); den = 2 doubles them.
GTEST_TEST(SolvesLcpAtBasis, AcceptsTheBasisSolutionAndNothingElse) {
  MatrixQ B(2, 2);
  B << Rational(1, 2), 0, 1, 1;
  VectorQ b(2);
  b << -1, Rational(1, 3);
  const std::vector<int> z1_w2 = {2, 1};  // variables: w 0..1, z 2..3, z0 4
  const auto check = [&](const std::vector<int>& basis, std::vector<Integer> num, Integer den) {
    return solves_lcp_at_basis(B, b, basis, num, den);
  };
  // By hand: z_1 = 2, w_2 = 1·2 + 1/3 = 7/3. B's row 2 has no denominator,
  // so L_2 = 1 and w_2 = num/(den·1): z_1 = 6/3, w_2 = 7/3.
  EXPECT_TRUE(check(z1_w2, {6, 7}, 3));
  EXPECT_TRUE(check(z1_w2, {12, 14}, 6));
  EXPECT_FALSE(check(z1_w2, {2, 7}, 1));    // w_2 = 7 (L_2 is not 3 = den b_2): row 2 fails
  EXPECT_FALSE(check(z1_w2, {6, 8}, 3));    // w_2 = 8/3: row 2 fails
  EXPECT_FALSE(check(z1_w2, {9, 7}, 3));    // z_1 = 3: both rows fail
  EXPECT_FALSE(check({2, 0}, {6, 0}, 3));   // z_1 and its complement w_1 both basic
  EXPECT_FALSE(check({2, 4}, {6, 0}, 3));   // z0 still basic
  EXPECT_FALSE(check({0, 1}, {-6, 1}, 3));  // w = b solves the rows (L_1 = 2), but w_1 = −6/(3·2) < 0
  EXPECT_FALSE(check(z1_w2, {6, 7}, 0));
  EXPECT_FALSE(solves_lcp_at_basis(MatrixQ(2, 3), b, z1_w2, {6, 7}, 3));  // B not 2×2: no read past it
  // The filtered run ends at that basis and returns those values.
  ForceExactScope filtered(false);
  const auto r = solve_lcp_lemke(B, b);
  ASSERT_EQ(r.status, LemkeStatus::kSolved);
  EXPECT_EQ(r.z, (VectorQ(2) << 2, 0).finished());
  EXPECT_EQ(r.w, (VectorQ(2) << 0, Rational(7, 3)).finished());
}

}  // namespace
}  // namespace fixel::internal
