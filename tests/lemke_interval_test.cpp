#include "fixel/internal/lemke_interval.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <random>
#include <utility>
#include <vector>

#include "fixel/internal/exact_lu.h"
#include "fixel/rational.h"
#include "test_util.h"

namespace fixel::internal {
namespace {

// The exact tableau A_β⁻¹ [A | b], A = [I, −B, −e], by Eigen's exact LU (a
// second method); columns numbered w 0..n−1, z n..2n−1, z0 2n, b 2n+1.
MatrixQ reference_tableau(const MatrixQ& B, const VectorQ& b, const std::vector<int>& basis) {
  const int n = static_cast<int>(b.size());
  const MatrixQ A = test::lemke_tableau_data(B, b);
  MatrixQ A_beta(n, n);
  for (int t = 0; t < n; ++t) A_beta.col(t) = A.col(basis[t]);
  return exact_lu(A_beta).solve(A);
}

// Whether the interval holds q, compared exactly (a double is a rational).
bool holds(const FI& x, const Rational& q) { return Rational(x.inf()) <= q && q <= Rational(x.sup()); }

// Small random B (a third of its entries zero) and b, rationals of one digit.
void random_data(std::mt19937_64& rng, int n, MatrixQ& B, VectorQ& b) {
  std::uniform_int_distribution<int> num(-9, 9), den(1, 9);
  B.resize(n, n);
  b.resize(n);
  for (int i = 0; i < n; ++i) {
    b[i] = Rational(num(rng), den(rng));
    for (int j = 0; j < n; ++j) B(i, j) = (rng() % 3 == 0) ? Rational(0) : Rational(num(rng), den(rng));
  }
}

// A random nonbasic column whose entry in row r the intervals certify
// nonzero (4n tries), else −1.
int certified_column(IntervalTableau& T, int r, int n, std::mt19937_64& rng) {
  for (int tries = 0; tries < 4 * n; ++tries) {
    const int v = static_cast<int>(rng() % (2 * n + 1));
    const bool basic = std::find(T.basis().begin(), T.basis().end(), v) != T.basis().end();
    if (!basic && certain_sign(T.at(r, v)) != 0 && certain_sign(T.at(r, v)) != kUndecided) return v;
  }
  return -1;
}

GTEST_TEST(IntervalTableau, EnclosesTheExactTableauAfterEveryPivot) {
  // Random pivots (on entries the intervals certify nonzero), more than 2n
  // of them so that the pivots kept are flushed too; after each, every
  // entry of every column encloses the exact tableau's, and the basis is
  // the one pivoted to.
  std::mt19937_64 rng(41);
  int pivots = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 2 + trial % 5;
    MatrixQ B;
    VectorQ b;
    random_data(rng, n, B, b);
    Protect rounding;
    IntervalTableau T(B, b);
    for (int step = 0; step < 3 * n; ++step) {
      const int r = static_cast<int>(rng() % n);
      const int s = certified_column(T, r, n, rng);
      if (s < 0) continue;
      T.pivot(r, s);
      ++pivots;
      ASSERT_EQ(T.basic(r), s);
      const MatrixQ exact = reference_tableau(B, b, T.basis());
      for (int var = 0; var <= T.rhs(); ++var)
        for (int i = 0; i < n; ++i)
          ASSERT_TRUE(holds(T.at(i, var), exact(i, var)))
              << "trial " << trial << ", step " << step << ", entry (" << i << ", " << var << ")";
    }
  }
  EXPECT_GT(pivots, 200);
}

GTEST_TEST(IntervalTableau, APreparedTableauStartsAsTheUnpreparedOneAndKeepsItsFirstEntriesForGuesses) {
  // B's part from IntervalRows, b's entries with numerators and
  // denominators of up to 90 bits or at the 53/54-bit edge (each part
  // enclosed on its own, then divided): the same first tableau, interval
  // for interval, holding the exact entries; after more than 2n pivots
  // (so a flush too), approx() (made late for the prepared one) still
  // gives the first tableau's lower ends, as the unprepared one's does.
  std::mt19937_64 rng(43);
  std::uniform_int_distribution<int> num(-9, 9), den(1, 9);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 2 + trial % 6;
    MatrixQ B(n, n);
    VectorQ b(n);
    for (int i = 0; i < n; ++i) {
      const Integer long_num = (Integer(rng()) << 26) + Integer(rng() % 1000),
                    long_den = (Integer(rng() | 1) << 26) + 1;
      const Integer edge = Integer(1) << 53;
      const Integer edge_num = edge + Integer(static_cast<long>(rng() % 5)) - 2,
                    edge_den = (edge << (rng() % 2)) + Integer(static_cast<long>(rng() % 3)) + 1;
      switch (trial % 4) {
        case 0:
          b[i] = Rational(long_num, long_den) * Rational(num(rng), 1);
          break;
        case 2:
          b[i] = Rational(edge_num, edge_den) * Rational(rng() % 2 ? 1 : -1, 1);
          break;
        default:
          b[i] = Rational(num(rng), den(rng));
      }
      for (int j = 0; j < n; ++j) B(i, j) = (rng() % 3 == 0) ? Rational(0) : Rational(num(rng), den(rng));
    }
    Protect rounding;
    IntervalRows rows;
    rows.assign(B);
    // One tableau at a time: they share per-thread storage.
    std::vector<FI> first;
    std::vector<double> expected;
    {
      IntervalTableau unprepared(B, b);
      for (int i = 0; i < n; ++i)
        for (int var = 0; var <= unprepared.rhs(); ++var) first.push_back(unprepared.at(i, var));
      const ApproxProblem guess = unprepared.approx();
      expected.assign(guess.slots, guess.slots + n * (n + 2));
    }
    IntervalTableau prepared(rows, b);
    for (int i = 0; i < n; ++i)
      for (int var = 0; var <= prepared.rhs(); ++var) {
        const FI a = first[static_cast<std::size_t>(i) * (prepared.rhs() + 1) + var], c = prepared.at(i, var);
        EXPECT_TRUE(a.inf() == c.inf() && a.sup() == c.sup()) << "trial " << trial << ", (" << i << ", " << var << ")";
        const Rational exact = var == prepared.rhs() ? b[i]
                               : var == 2 * n        ? Rational(-1)
                               : var >= n            ? Rational(-B(i, var - n))
                                                     : Rational(i == var ? 1 : 0);
        EXPECT_TRUE(holds(c, exact)) << "trial " << trial << ", (" << i << ", " << var << ")";
      }
    // Pivots on certainly nonzero entries of nonbasic columns (z's, unlike
    // z0's all −1), past 2n so that the kept pivots are flushed, then every
    // column read, which brings it up to date in storage.
    int pivots = 0;
    for (int tries = 0; tries < 50 * n && pivots <= 2 * n; ++tries) {
      const int r = static_cast<int>(rng() % n), v = static_cast<int>(rng() % (2 * n));
      const bool basic = std::find(prepared.basis().begin(), prepared.basis().end(), v) != prepared.basis().end();
      const int sign = basic ? 0 : certain_sign(prepared.at(r, v));
      if (sign == kUndecided || sign == 0) continue;
      prepared.pivot(r, v);
      ++pivots;
    }
    EXPECT_GT(pivots, 2 * n) << "trial " << trial;
    for (int var = 0; var <= prepared.rhs(); ++var)
      if (std::find(prepared.basis().begin(), prepared.basis().end(), var) == prepared.basis().end())
        prepared.at(0, var);
    const ApproxProblem late = prepared.approx();
    ASSERT_EQ(late.n, n);
    EXPECT_EQ(std::vector<double>(late.slots, late.slots + n * (n + 2)), expected) << "trial " << trial;
  }
}

GTEST_TEST(IntervalTableau, GivesTheSameEnclosuresBitForBitWhetherColumnsAreReadAtOnceOrPivotsLater) {
  // The same pivots twice (one tableau at a time: they share per-thread
  // storage): first read whole after every pivot, then only one step in
  // five, so that a leaving variable's column (made when first read) and
  // the pivots it missed are applied many pivots later, across the flush
  // after 2n pivots. Every entry read late has the same two ends as read at
  // once, and encloses the exact tableau's.
  std::mt19937_64 rng(43);
  int late_reads = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 2 + trial % 5;
    MatrixQ B;
    VectorQ b;
    random_data(rng, n, B, b);
    Protect rounding;
    std::vector<std::pair<int, int>> pivots;
    std::vector<std::vector<FI>> at_once;  // after each pivot, every entry, column by column
    {
      IntervalTableau T(B, b);
      for (int step = 0; step < 4 * n; ++step) {
        const int r = static_cast<int>(rng() % n);
        const int s = certified_column(T, r, n, rng);
        if (s < 0) continue;
        T.pivot(r, s);
        pivots.emplace_back(r, s);
        at_once.emplace_back();
        for (int var = 0; var <= T.rhs(); ++var)
          for (int i = 0; i < n; ++i) at_once.back().push_back(T.at(i, var));
      }
    }
    IntervalTableau late(B, b);
    for (std::size_t p = 0; p < pivots.size(); ++p) {
      late.pivot(pivots[p].first, pivots[p].second);
      if (rng() % 5 != 0 && p + 1 < pivots.size()) continue;
      ++late_reads;
      const MatrixQ exact = reference_tableau(B, b, late.basis());
      for (int var = 0, e = 0; var <= late.rhs(); ++var)
        for (int i = 0; i < n; ++i, ++e) {
          const FI x = late.at(i, var), y = at_once[p][e];
          ASSERT_EQ(x.inf(), y.inf()) << "trial " << trial << ", pivot " << p << ", entry (" << i << ", " << var << ")";
          ASSERT_EQ(x.sup(), y.sup()) << "trial " << trial << ", pivot " << p << ", entry (" << i << ", " << var << ")";
          ASSERT_TRUE(holds(x, exact(i, var)));
        }
    }
  }
  EXPECT_GT(late_reads, 40);
}

GTEST_TEST(TwoLimbMagnitude, EnclosesEveryIntegerBelow2To128WithinTwoUlps) {
  // Random sizes from 1 to 128 bits and the edges (2^53 ± 1, 2^64 ± 1,
  // 2^127, 2^128 − 1, all ones below a limb's top), both signs: the ends
  // hold |z|, compared exactly, and are within two ulps of each other.
  std::mt19937_64 rng(47);
  std::vector<Integer> values;
  for (const int e : {52, 53, 54, 63, 64, 65, 117, 127, 128}) {
    values.push_back((Integer(1) << e) - 1);
    values.push_back(Integer(1) << e);
    values.push_back((Integer(1) << e) + 1);
  }
  for (int trial = 0; trial < 3000; ++trial) {
    const int bits = 1 + trial % 128;
    Integer x = 0;
    for (int left = bits; left > 0; left -= 32) {
      const int chunk = left < 32 ? left : 32;
      x = (x << chunk) + Integer(rng() & ((std::uint64_t{1} << chunk) - 1));
    }
    x |= Integer(1) << (bits - 1);  // exactly `bits` bits
    values.push_back(x);
  }
  // In every rounding mode (the tableau's is upward): the conversion of
  // the top 64 bits rounds either way.
  const auto check = [&values](int& exact) {
    for (const Integer& x : values) {
      if (x == 0 || x >= (Integer(1) << 128)) continue;
      for (const Integer& z : {x, Integer(-x)}) {
        const FI m = two_limb_magnitude(mp(z));
        ASSERT_LE(Rational(m.inf()), Rational(x)) << x;
        ASSERT_GE(Rational(m.sup()), Rational(x)) << x;
        ASSERT_LE(Rational(m.sup()) - Rational(m.inf()), Rational(m.inf()) / Rational(Integer(1) << 51)) << x;
        exact += m.inf() == m.sup();
      }
    }
  };
  int exact = 0;
  for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
    const int before = std::fegetround();
    std::fesetround(mode);
    check(exact);
    std::fesetround(before);
  }
  EXPECT_GT(exact, 400);  // below 2^53: points
}

GTEST_TEST(IntervalTableau, KeepsExactZerosAndPointsExact) {
  // Integer data: the first tableau is exact, and an entry whose pivot
  // column entry is an exact zero stays untouched by that pivot.
  MatrixQ B(2, 2);
  B << 2, 0, 0, 3;
  VectorQ b(2);
  b << -4, 6;
  Protect rounding;
  IntervalTableau T(B, b);
  EXPECT_EQ(T.at(0, 2).inf(), -2);  // −B(0, 0), z_0 is variable n = 2
  EXPECT_EQ(T.at(0, 2).sup(), -2);
  EXPECT_EQ(T.at(1, T.rhs()).inf(), 6);
  T.pivot(0, 2);  // z_0 enters in row 0: row 0 divided by −2
  const FI value = T.at(0, T.rhs());
  EXPECT_EQ(value.inf(), 2);  // z_0 = 2, exactly
  EXPECT_EQ(value.sup(), 2);
  EXPECT_EQ(T.at(1, T.rhs()).inf(), 6);  // T(1, z_0) was an exact 0: row 1 untouched
  EXPECT_EQ(T.at(1, T.rhs()).sup(), 6);
}

}  // namespace
}  // namespace fixel::internal
