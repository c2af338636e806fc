#include "fixel/internal/lemke_dixon_sparse.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "exact_lu_reference.h"
#include "fixel/internal/lemke_dixon.h"
#include "fixel/rational.h"

namespace fixel::internal {
namespace {

using Words = std::vector<std::int64_t>;

// C·x = y in words, with the reference solution by Eigen's exact LU (a
// second method, on the whole system).
struct WordSystem {
  int k = 0;
  Words c;
  std::vector<std::int64_t> y;

  std::vector<char> zero_rhs() const {
    std::vector<char> out;
    for (const std::int64_t v : y) out.push_back(static_cast<char>(v == 0));
    return out;
  }
  bool reference(VectorQ& x) const { return test::exact_lu_solution(k, c, y, x); }
};

// dixon_solve on the words, with short rows eliminated or not.
bool solve(const WordSystem& s, bool eliminate, std::vector<Rational>& x, DixonTrace& trace) {
  std::vector<Integer> y;
  for (const std::int64_t v : s.y) y.emplace_back(v);
  std::vector<const Integer*> y_pointers;
  for (const Integer& v : y) y_pointers.push_back(&v);
  set_dixon_sparse_rows_allowed(eliminate);
  std::vector<Integer> u;
  Integer d;
  const bool solved = dixon_solve(s.k, {}, y_pointers, u, d, nullptr, &trace, &s.c);
  set_dixon_sparse_rows_allowed(true);
  x.clear();
  if (!solved) return false;
  for (const Integer& v : u) x.emplace_back(v, d);
  return true;
}

// dixon_solve with short rows eliminated gives the exact-LU values, after
// eliminating `eliminated` unknowns.
void expect_reference_values(const WordSystem& s, int eliminated) {
  VectorQ expected;
  ASSERT_TRUE(s.reference(expected));
  std::vector<Rational> x;
  DixonTrace trace;
  ASSERT_TRUE(solve(s, true, x, trace));
  EXPECT_EQ(trace.unknowns_eliminated, eliminated);
  for (int j = 0; j < s.k; ++j) EXPECT_EQ(x[j], expected[j]) << "x_" << j;
}

GTEST_TEST(SparseRowReduction, FixesAnUnknownAtZeroFromARowWithOneEntry) {
  // Row 1: 7·x_2 = 0. Left: rows 0 and 2 in x_0, x_1.
  const Words c = {2, 3, 5,  //
                   0, 0, 7,  //
                   1, 4, 6};
  SparseRowReduction r;
  ASSERT_TRUE(r.reduce(3, c, {0, 1, 0}));
  EXPECT_EQ(r.reduced, 2);
  EXPECT_EQ(r.rows, (std::vector<int>{0, 2}));
  EXPECT_EQ(r.c_words, (Words{2, 3, 1, 4}));
  EXPECT_EQ(r.unknown, (std::vector<int>{0, 1, -1}));
  EXPECT_EQ(r.multiplier, (Words{1, 1, 1}));
}

GTEST_TEST(SparseRowReduction, TiesTwoUnknownsFromARowWithTwoEntries) {
  // Row 2: 10·x_0 − 4·x_1 = 0, so (α′, β′) = (5, −2) after their gcd 2:
  // x_0 = −2·t, x_1 = −5·t, and t's column is −2·C(·, 0) − 5·C(·, 1)
  // (by hand: row 0 gives −2·1 − 5·2 = −12, row 1 gives −2·3 − 5·(−1) = −1).
  const Words c = {1,  2,  9,  //
                   3,  -1, 8,  //
                   10, -4, 0};
  SparseRowReduction r;
  ASSERT_TRUE(r.reduce(3, c, {0, 0, 1}));
  EXPECT_EQ(r.reduced, 2);
  EXPECT_EQ(r.rows, (std::vector<int>{0, 1}));
  EXPECT_EQ(r.c_words, (Words{-12, 9, -1, 8}));
  EXPECT_EQ(r.unknown, (std::vector<int>{0, 0, 1}));
  EXPECT_EQ(r.multiplier, (Words{-2, -5, 1}));
}

GTEST_TEST(SparseRowReduction, ComposesTiesAndZerosAcrossRounds) {
  // By hand: row 2 (x_0 − x_1 = 0) ties x_0 = x_1 = −t, and t's column is
  // −C(·, 0) − C(·, 1), −2 in row 3. Row 3 is then −2·t + 3·x_3 = 0: t = 3·s,
  // x_3 = 2·s, so x_0 = x_1 = −3·s. Row 4 (9·x_4 = 0) gives x_4 = 0.
  WordSystem s;
  s.k = 5;
  s.c = {4, 1,  2, 7, 1,  //
         1, 5,  3, 2, 2,  //
         1, -1, 0, 0, 0,  //
         0, 2,  0, 3, 0,  //
         0, 0,  0, 0, 9};
  s.y = {11, -6, 0, 0, 0};
  SparseRowReduction r;
  ASSERT_TRUE(r.reduce(s.k, s.c, s.zero_rhs()));
  EXPECT_EQ(r.reduced, 2);  // three rows gone: x_0, x_1, x_3 one unknown, x_4 = 0
  EXPECT_EQ(r.unknown[0], r.unknown[1]);
  EXPECT_EQ(r.unknown[0], r.unknown[3]);
  EXPECT_EQ(r.unknown[4], -1);
  EXPECT_EQ(r.multiplier[0], -3);
  EXPECT_EQ(r.multiplier[1], -3);
  EXPECT_EQ(r.multiplier[3], 2);
  expect_reference_values(s, 3);
}

GTEST_TEST(SparseRowReduction, PassesTheHintOnSoThatASmallAnswerComesAfterOneStep) {
  // x = (2, 5, 3, 0) by hand: row 2 ties x_0 = −2·t, x_1 = −5·t (t = −1),
  // row 3 fixes x_3 = 0, and C′ = [[−12, 3], [1, 1]] gives t and x_2. With
  // the hint x_j ± 1/4, t's enclosure is x_0/(−2) with its ends swapped:
  // the one-limb reconstruction after the first step then answers.
  // Without a hint no attempt comes before the second step.
  std::vector<Integer> y = {Integer(21), Integer(2), Integer(0), Integer(0)};
  std::vector<const Integer*> y_pointers;
  for (const Integer& v : y) y_pointers.push_back(&v);
  const Words c = {1, 2,  3, 4,  //
                   2, -1, 1, 5,  //
                   5, -2, 0, 0,  //
                   0, 0,  0, 7};
  const std::vector<double> x = {2, 5, 3, 0};
  DixonHint hint;
  for (const double v : x) {
    hint.lo.push_back(v - 0.25);
    hint.hi.push_back(v + 0.25);
  }
  std::vector<Integer> u;
  Integer d;
  DixonTrace trace;
  ASSERT_TRUE(dixon_solve(4, {}, y_pointers, u, d, &hint, &trace, &c));
  EXPECT_EQ(trace.unknowns_eliminated, 2);
  EXPECT_EQ(trace.steps, 1);
  EXPECT_EQ(trace.attempts, 1);
  for (int j = 0; j < 4; ++j) EXPECT_EQ(Rational(u[j], d), Rational(static_cast<long>(x[j]))) << "x_" << j;
  ASSERT_TRUE(dixon_solve(4, {}, y_pointers, u, d, nullptr, &trace, &c));
  EXPECT_GT(trace.steps, 1);
  for (int j = 0; j < 4; ++j) EXPECT_EQ(Rational(u[j], d), Rational(static_cast<long>(x[j]))) << "x_" << j;
}

GTEST_TEST(SparseRowReduction, LeavesARowWhoseTieWouldTakeAnEntryTo2To59) {
  // Row 2: 3·x_0 + 2·x_1 = 0; t's column 2·C(·, 0) − 3·C(·, 1) would reach
  // 2·2^58 + 3·2^57 > 2^59 in row 0, so the row stays; row 1's single
  // entry is still taken.
  const std::int64_t big = std::int64_t{1} << 58;
  const Words c = {big, -(big / 2), 1, 5,  //
                   0,   0,          0, 6,  //
                   3,   2,          0, 0,  //
                   1,   1,          1, 1};
  SparseRowReduction r;
  ASSERT_TRUE(r.reduce(4, c, {0, 1, 1, 0}));
  EXPECT_EQ(r.reduced, 3);
  EXPECT_EQ(r.rows, (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(r.unknown, (std::vector<int>{0, 1, 2, -1}));
  EXPECT_EQ(r.c_words, (Words{big, -(big / 2), 1, 3, 2, 0, 1, 1, 1}));
}

GTEST_TEST(SparseRowReduction, ChecksTheBoundInRowsLeftBeforeToo) {
  // Row 1 (y = 0) would tie x_0 and x_1, but row 0's 1 − (−(2^59 − 1))
  // reaches 2^59: row 1 stays. Row 2 (3·x_0 + 2·x_2 = 0) would then write
  // 2·2^58 = 2^59 into row 1, which C′ keeps: it stays too, and nothing is
  // eliminated.
  const std::int64_t big = std::int64_t{1} << 58;
  WordSystem s;
  s.k = 4;
  s.c = {1,   -(2 * big - 1),
         1,   1,  //
         big, big,
         0,   0,  //
         3,   0,
         2,   0,  //
         1,   2,
         3,   4};
  s.y = {5, 0, 0, 7};
  SparseRowReduction r;
  EXPECT_FALSE(r.reduce(s.k, s.c, s.zero_rhs()));
  expect_reference_values(s, 0);
}

GTEST_TEST(SparseRowReduction, MakesNoChangeWithoutShortRowsOfZeroRightHandSide) {
  SparseRowReduction r;
  // Short rows, but y ≠ 0 on them.
  EXPECT_FALSE(r.reduce(2, {1, 0, 0, 1}, {0, 0}));
  // y = 0 on a row of three entries.
  EXPECT_FALSE(r.reduce(3, {1, 1, 1, 2, 0, 1, 0, 3, 1}, {1, 0, 0}));
  // Sizes that do not match, or beyond kWordRows.
  EXPECT_FALSE(r.reduce(2, {1, 0, 0}, {1, 1}));
  EXPECT_FALSE(r.reduce(2, {1, 0, 0, 1}, {1}));
  EXPECT_FALSE(r.reduce(0, {}, {}));
  EXPECT_FALSE(r.reduce(17, Words(17 * 17, 1), std::vector<char>(17, 1)));
}

GTEST_TEST(SparseRowReduction, KeepsASingularSystemSingular) {
  // Row 1 is zero (y_1 = 0): C is singular, and so is what is left.
  WordSystem s;
  s.k = 3;
  s.c = {1, 2, 3, 0, 0, 0, 1, -1, 0};
  s.y = {4, 0, 0};
  VectorQ unused;
  ASSERT_FALSE(s.reference(unused));
  std::vector<Rational> x;
  DixonTrace trace;
  EXPECT_FALSE(solve(s, true, x, trace));
  EXPECT_FALSE(solve(s, false, x, trace));
}

// Seating-like blocks: dense rows of large entries, and rows with y_a = 0
// of one or two small entries (the friction rows).
WordSystem seating_like(std::mt19937_64& rng, int k, int short_rows) {
  WordSystem s;
  s.k = k;
  s.c.assign(static_cast<std::size_t>(k) * k, 0);
  s.y.assign(k, 0);
  std::uniform_int_distribution<std::int64_t> large(-(std::int64_t{1} << 50), std::int64_t{1} << 50);
  std::uniform_int_distribution<std::int64_t> small(-12, 12);
  std::uniform_int_distribution<int> column(0, k - 1);
  for (int a = 0; a < k; ++a) {
    std::int64_t* row = &s.c[static_cast<std::size_t>(a) * k];
    if (a >= k - short_rows) {
      const int p = column(rng), q = column(rng);
      row[p] = small(rng);
      if (rng() % 3 != 0) row[q] = small(rng);  // two entries, or one (p = q too)
      if (row[p] == 0) row[p] = 1;
      continue;
    }
    for (int j = 0; j < k; ++j) row[j] = rng() % 4 == 0 ? 0 : large(rng);
    s.y[a] = large(rng);
  }
  return s;
}

GTEST_TEST(SparseRowReduction, GivesDixonSolveTheSameValuesAsTheWholeSystemAndExactLu) {
  std::mt19937_64 rng(2026);
  int solved = 0, reduced = 0;
  for (int trial = 0; trial < 400; ++trial) {
    SCOPED_TRACE(trial);
    const int k = 2 + trial % 10;
    const WordSystem s = seating_like(rng, k, 1 + trial % (k / 2 + 1));
    VectorQ expected;
    std::vector<Rational> with, without;
    DixonTrace trace_with, trace_without;
    const bool nonsingular = s.reference(expected);
    const bool solved_with = solve(s, true, with, trace_with);
    const bool solved_without = solve(s, false, without, trace_without);
    EXPECT_EQ(trace_without.unknowns_eliminated, 0);
    if (!nonsingular) {
      EXPECT_FALSE(solved_with);
      EXPECT_FALSE(solved_without);
      continue;
    }
    ASSERT_TRUE(solved_with);
    ASSERT_TRUE(solved_without);
    for (int j = 0; j < k; ++j) {
      EXPECT_EQ(with[j], expected[j]) << "x_" << j;
      EXPECT_EQ(without[j], expected[j]) << "x_" << j;
    }
    ++solved;
    reduced += trace_with.unknowns_eliminated > 0;
  }
  EXPECT_GT(solved, 150);
  EXPECT_GT(reduced, solved / 2);  // the short rows were used, not skipped
}

}  // namespace
}  // namespace fixel::internal
