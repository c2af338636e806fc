#include "fixel/internal/lemke_scaled.h"

#include <gtest/gtest.h>

#include <random>

#include "fixel/rational.h"

namespace fixel::internal {
namespace {

// The lcm of the denominators of B's row i, by GMP alone.
Integer row_lcm(const MatrixQ& B, int i) {
  Integer L = 1;
  for (int j = 0; j < B.cols(); ++j) mpz_lcm(mp(L), mp(L), mpq_denref(B(i, j).backend().data()));
  return L;
}

// Every entry of ScaledProblem against its definition, in rationals: L_i the
// lcm of row i's denominators, δ the lcm of the denominators of the L_i·b_i,
// entry(i, z_j) = −L_i·B(i, j), entry(i, z0) = −L_i, entry(i, b) = L_i·δ·b_i.
void expect_scaled_as_defined(const MatrixQ& B, const VectorQ& b) {
  ScaledProblem P;
  P.assign(B, b);
  const int n = static_cast<int>(b.size());
  ASSERT_EQ(P.n(), n);
  Integer delta = 1;
  for (int i = 0; i < n; ++i) {
    const Integer L = row_lcm(B, i);
    EXPECT_EQ(P.scale(i), L) << "row " << i;
    const Rational scaled_b = Rational(L) * b[i];
    mpz_lcm(mp(delta), mp(delta), mpq_denref(scaled_b.backend().data()));
  }
  EXPECT_EQ(P.rhs_factor(), delta);
  for (int i = 0; i < n; ++i) {
    const Rational L(P.scale(i));
    for (int j = 0; j < n; ++j) {
      EXPECT_EQ(P.entry(i, j), i == j ? P.scale(i) : Integer(0));
      EXPECT_EQ(Rational(P.entry(i, n + j)), -L * B(i, j)) << "row " << i << ", z" << j;
    }
    EXPECT_EQ(Rational(P.entry(i, 2 * n)), -L);
    EXPECT_EQ(Rational(P.entry(i, 2 * n + 1)), L * Rational(delta) * b[i]) << "row " << i;
  }
  // The word copy: there exactly when every entry but b's is below 2^59,
  // and then equal to them.
  bool fits = true;
  for (int i = 0; i < n; ++i)
    for (int var = 0; var <= 2 * n; ++var) fits = fits && abs(P.entry(i, var)) < (Integer(1) << 59);
  EXPECT_EQ(P.in_words(), fits);
  if (!P.in_words()) return;
  for (int i = 0; i < n; ++i)
    for (int var = 0; var <= 2 * n; ++var) EXPECT_EQ(Integer(P.word(i, var)), P.entry(i, var)) << i << ", " << var;
}

Rational random_fraction(std::mt19937_64& rng, long long max_den) {
  std::uniform_int_distribution<long long> num(-1000000, 1000000), den(1, max_den);
  return Rational(num(rng), den(rng));
}

GTEST_TEST(ScaledProblem, ScalesRowsThatRepeatTheirPredecessorsDenominatorsAsDefined) {
  // Rows in ± pairs with equal denominators (as the seating LCPs' friction
  // rows), rows of integers, zero and repeated b entries: each path of
  // assign (a row like the previous one, words, b's factor reused) runs.
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 9;
    MatrixQ B(n, n);
    VectorQ b(n);
    for (int i = 0; i < n; ++i) {
      const int kind = static_cast<int>(rng() % 4);
      for (int j = 0; j < n; ++j) {
        if (i > 0 && kind == 0)
          B(i, j) = -B(i - 1, j);  // the same denominators as row i − 1
        else if (kind == 1)
          B(i, j) = Rational(static_cast<long long>(rng() % 7) - 3);  // integers
        else
          B(i, j) = random_fraction(rng, trial % 2 ? 100 : 4000000000LL);
      }
      const int b_kind = static_cast<int>(rng() % 4);
      if (i > 0 && b_kind == 0)
        b[i] = -b[i - 1];
      else if (b_kind == 1)
        b[i] = 0;
      else if (b_kind == 2)
        b[i] = Rational(static_cast<long long>(rng() % 5) + 1);  // den 1, as a zero's
      else
        b[i] = random_fraction(rng, 1LL << 40) / random_fraction(rng, 1LL << 30);
      if (b[i] == 0 && i > 0 && rng() % 2) b[i] = b[i - 1];
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_scaled_as_defined(B, b);
  }
}

GTEST_TEST(ScaledProblem, ScalesRowsWhoseLcmPassesAMachineWordAsDefined) {
  // Denominators of 40 bits: their lcm overflows 64 bits, so the general
  // path runs, then a following row with the same denominators (which may
  // not reuse word factors it never computed).
  std::mt19937_64 rng(13);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 3 + trial % 4;
    MatrixQ B(n, n);
    VectorQ b(n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) B(i, j) = i % 2 ? Rational(-B(i - 1, j)) : random_fraction(rng, 1LL << 40);
      b[i] = random_fraction(rng, 1LL << 50);
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_scaled_as_defined(B, b);
  }
}

GTEST_TEST(ScaledProblem, ScalesRightHandSidesWithDenominatorsBeyondAWordAsDefined) {
  // As on the seating LCPs' normal rows: L_i of about 40 bits (two 20-bit
  // denominators per row of B; odd rows negate the row before, as the
  // friction rows come in pairs, and half of them repeat its b) and
  // den(b_i) a multiple of L_i by q·2^30, about 90 bits, so that δ = q·2^30
  // is a word (kind 0). Then den(b_i) with a part of its own past 2^64
  // (kind 1), of three limbs (kind 2), with 41-bit parts of its own whose
  // lcm passes 2^64 (kind 3), and coprime to L_i with δ of 62 bits, so
  // that (L_i/g)·(δ/den) passes a word (kind 4). Each must give the
  // entries as defined, whichever path computes them.
  std::mt19937_64 rng(14);
  std::uniform_int_distribution<long long> twenty_bits(1LL << 19, (1LL << 20) - 1), numerator(-99999, 99999);
  for (int trial = 0; trial < 150; ++trial) {
    const int n = 2 + trial % 6;
    const int kind = trial % 5;
    const Integer q(twenty_bits(rng));
    MatrixQ B(n, n);
    VectorQ b(n);
    for (int i = 0; i < n; ++i) {
      const long long den[2] = {twenty_bits(rng), twenty_bits(rng)};
      for (int j = 0; j < n; ++j) B(i, j) = i % 2 ? Rational(-B(i - 1, j)) : Rational(numerator(rng), den[j % 2]);
      if (i % 2 && rng() % 2) {
        b[i] = -b[i - 1];
        continue;
      }
      const Rational top(numerator(rng) | 1);
      const Integer L = row_lcm(B, i);
      if (kind == 0)
        b[i] = top / Rational(L * q * (Integer(1) << 30));
      else if (kind == 1)
        b[i] = top / Rational(L * ((Integer(1) << 70) + Integer(twenty_bits(rng))));
      else if (kind == 2)
        b[i] = top / Rational((Integer(1) << 130) + Integer(twenty_bits(rng)));
      else if (kind == 3)
        b[i] = top / Rational(L * ((Integer(1) << 40) + Integer(2 * twenty_bits(rng) + 1)));
      else
        b[i] = top / Rational(i % 4 < 2 ? Integer(3) : q * q * q);  // δ = 3·q³ (61–62 bits)
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_scaled_as_defined(B, b);
  }
}

GTEST_TEST(ScaledProblem, ScalesARowWhoseLcmGrowsAfterEarlierQuotientsAsDefined) {
  // Denominators 2, 3, 2, 4, 6, 1: the lcm grows 2 → 6 → 12 after the
  // quotients of the first 2 and 3 were taken, so theirs must grow with it
  // (12/2 = 6, not 6/2 = 3); repeated and dividing ones in between.
  MatrixQ B(2, 6);
  B << Rational(1, 2), Rational(1, 3), Rational(-3, 2), Rational(1, 4), Rational(5, 6), Rational(7), Rational(1, 5),
      Rational(1, 5), Rational(2, 25), Rational(1, 1), Rational(3, 125), Rational(1, 5);
  MatrixQ square(6, 6);
  square.setZero();
  square.topRows(2) = B;
  VectorQ b = VectorQ::Constant(6, Rational(-1, 3));
  ScaledProblem P;
  P.assign(square, b);
  EXPECT_EQ(P.scale(0), Integer(12));
  EXPECT_EQ(P.entry(0, 6), Integer(-6));    // z_0: −12·(1/2)
  EXPECT_EQ(P.entry(0, 7), Integer(-4));    // z_1: −12·(1/3)
  EXPECT_EQ(P.entry(0, 8), Integer(18));    // z_2: −12·(−3/2)
  EXPECT_EQ(P.entry(0, 11), Integer(-84));  // z_5: −12·7
  EXPECT_EQ(P.scale(1), Integer(125));
  expect_scaled_as_defined(square, b);
}

GTEST_TEST(ScaledProblem, ForgetsTheLastProblemsRowsWhenReassigned) {
  // One ScaledProblem reused: the second problem's first row must not be
  // scaled with the first problem's last factors.
  MatrixQ B1(2, 2), B2(2, 2);
  B1 << Rational(1, 3), Rational(1, 5), Rational(2, 3), Rational(4, 5);
  B2 << Rational(1, 3), Rational(1, 5), Rational(1, 7), Rational(1, 11);
  VectorQ b(2);
  b << Rational(-1, 2), Rational(1, 2);
  ScaledProblem P;
  P.assign(B1, b);
  P.assign(B2, b);
  EXPECT_EQ(P.scale(1), Integer(77));
  EXPECT_EQ(Rational(P.entry(1, 2)), Rational(-11));  // variable 2 is z_0: −77·(1/7)
  expect_scaled_as_defined(B2, b);
}

}  // namespace
}  // namespace fixel::internal
