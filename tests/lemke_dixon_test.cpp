#include "fixel/internal/lemke_dixon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "exact_lu_reference.h"
#include "fixel/internal/lemke_dixon_words.h"
#include "fixel/internal/lemke_scaled.h"
#include "fixel/rational.h"

namespace fixel::internal {
namespace {

// A k×k integer system, its entries and right-hand side as the solver takes them.
struct System {
  int k = 0;
  std::vector<Integer> c, y;

  std::vector<const Integer*> c_pointers() const {
    std::vector<const Integer*> out;
    for (const Integer& x : c) out.push_back(&x);
    return out;
  }
  std::vector<const Integer*> y_pointers() const {
    std::vector<const Integer*> out;
    for (const Integer& x : y) out.push_back(&x);
    return out;
  }
  // The reference: Eigen's exact LU over the rationals (a second method).
  bool reference(VectorQ& x) const { return test::exact_lu_solution(k, c, y, x); }
};

// A signed integer of up to `bits` bits; zero with probability `zeros`.
Integer random_integer(std::mt19937_64& rng, int bits, double zeros) {
  if (std::uniform_real_distribution<double>(0, 1)(rng) < zeros) return Integer(0);
  Integer x = 0;
  for (int left = bits; left > 0; left -= 32) {
    const int chunk = left < 32 ? left : 32;
    x = (x << chunk) + Integer(rng() & ((std::uint64_t{1} << chunk) - 1));
  }
  return (rng() & 1) ? Integer(-x) : x;
}

System random_system(std::mt19937_64& rng, int k, int bits, double zeros) {
  System s;
  s.k = k;
  for (int e = 0; e < k * k; ++e) s.c.push_back(random_integer(rng, bits, zeros));
  for (int a = 0; a < k; ++a) s.y.push_back(random_integer(rng, bits, 0.1));
  return s;
}

// Solves s and compares u/d with the reference, value by value, exactly.
void expect_reference_solution(const System& s) {
  VectorQ expected;
  ASSERT_TRUE(s.reference(expected));
  std::vector<Integer> u;
  Integer d;
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d));
  ASSERT_EQ(static_cast<int>(u.size()), s.k);
  EXPECT_GT(d, 0);
  for (int j = 0; j < s.k; ++j) EXPECT_EQ(Rational(u[j], d), expected[j]) << "x_" << j;
}

GTEST_TEST(DixonSolve, AgreesWithExactLuOnRandomSystemsOfEverySizeAndSparsity) {
  std::mt19937_64 rng(7);
  int solved = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int k = 1 + trial % 10;
    const int bits = (trial % 3 == 0) ? 8 : (trial % 3 == 1) ? 60 : 95;  // the seating blocks: 30–91 bits
    const double zeros = (trial % 4) * 0.2;                              // sparse blocks need row swaps
    const System s = random_system(rng, k, bits, zeros);
    VectorQ x;
    if (!s.reference(x)) {
      std::vector<Integer> u;
      Integer d;
      EXPECT_FALSE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d)) << "singular, trial " << trial;
      continue;
    }
    SCOPED_TRACE(trial);
    expect_reference_solution(s);
    ++solved;
  }
  EXPECT_GT(solved, 250);  // most random systems are nonsingular
}

GTEST_TEST(DixonSolve, NeedsPivotsBelowTheDiagonalWhenTheDiagonalIsZero) {
  // An anti-diagonal system: every column's pivot is found by a row swap.
  System s;
  s.k = 4;
  s.c.assign(16, Integer(0));
  for (int a = 0; a < 4; ++a) s.c[static_cast<std::size_t>(a) * 4 + (3 - a)] = Integer(2 * a + 3);
  s.c[1] = Integer(5);  // one more entry in row 0, so that the swaps interact
  s.y = {Integer(1), Integer(-2), Integer(3), Integer(7)};
  expect_reference_solution(s);
}

GTEST_TEST(DixonSolve, RecoversDenominatorsFarLargerThanOnePrime) {
  // 200-bit entries: the values' denominators are about 1,000 bits, some
  // twenty lifting steps.
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 5; ++trial) expect_reference_solution(random_system(rng, 5, 200, 0.0));
}

GTEST_TEST(DixonSolve, RecoversLargeNumeratorsOverSmallDenominators) {
  // x = 2⁵⁰⁰/3 and an integer of 500 bits: reconstruction looks for
  // numerator and denominator both below √(M/2), so the lifting must go on
  // well past what the denominators need.
  System s;
  s.k = 1;
  s.c = {Integer(3)};
  s.y = {Integer(1) << 500};
  expect_reference_solution(s);
  s.k = 2;
  s.c = {Integer(1), Integer(0), Integer(0), Integer(1)};
  s.y = {(Integer(1) << 500) + 1, -(Integer(1) << 499)};
  expect_reference_solution(s);
}

GTEST_TEST(DixonSolve, MovesToTheNextPrimeWhenTheFirstDividesTheDeterminant) {
  const std::vector<std::uint64_t>& primes = dixon_primes();
  ASSERT_EQ(primes.size(), 3u);
  System s;
  s.k = 2;
  s.c = {Integer(primes[0]), Integer(1), Integer(0), Integer(3)};  // det = 3·p₀
  s.y = {Integer(1), Integer(1)};
  expect_reference_solution(s);
}

GTEST_TEST(DixonSolve, MovesToTheNextPrimeInMachineWordsToo) {
  // det C = p₀ with entries far below 2^59: the word path must start the
  // next prime's lifting from y again.
  const Integer p0(dixon_primes()[0]);
  const Integer two_31 = Integer(1) << 31;
  System s;
  s.k = 2;
  s.c = {two_31, Integer(-(p0 - two_31 * two_31)), Integer(1), two_31};
  s.y = {Integer(5), Integer(-7)};
  std::vector<Integer> u;
  Integer d;
  DixonTrace trace;
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, nullptr, &trace));
  EXPECT_TRUE(trace.words);
  expect_reference_solution(s);
}

// Solves s in machine words and again with GMP: the same u and d, integer
// for integer, and the reference's values.
void expect_words_and_gmp_agree(const System& s, bool words_expected) {
  std::vector<Integer> u_words, u_gmp;
  Integer d_words, d_gmp;
  DixonTrace trace_words, trace_gmp;
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u_words, d_words, nullptr, &trace_words));
  set_dixon_words_allowed(false);
  const bool solved = dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u_gmp, d_gmp, nullptr, &trace_gmp);
  set_dixon_words_allowed(true);
  ASSERT_TRUE(solved);
  EXPECT_EQ(trace_words.words, words_expected);
  EXPECT_FALSE(trace_gmp.words);
  EXPECT_EQ(trace_words.steps, trace_gmp.steps);
  EXPECT_EQ(d_words, d_gmp);
  EXPECT_EQ(u_words, u_gmp);
  expect_reference_solution(s);
  // C given as words already (as a prepared matrix's block is), its
  // integers left out: the same answer when y fits words; else declined,
  // and with C's integers beside its words GMP lifts as before.
  bool entries_fit = s.k <= kWordRows;
  for (const Integer& x : s.c)
    entries_fit = entries_fit && mpz_size(mp(x)) <= 1 && mpz_getlimbn(mp(x), 0) < (mp_limb_t(1) << 59);
  if (!entries_fit) return;
  std::vector<std::int64_t> c_words;
  for (const Integer& x : s.c) c_words.push_back(mpz_get_si(mp(x)));
  std::vector<Integer> u_given;
  Integer d_given;
  DixonTrace trace_given;
  const bool solved_given = dixon_solve(s.k, {}, s.y_pointers(), u_given, d_given, nullptr, &trace_given, &c_words);
  EXPECT_EQ(solved_given, words_expected);
  if (solved_given) {
    EXPECT_TRUE(trace_given.words);
    EXPECT_EQ(d_given, d_words);
    EXPECT_EQ(u_given, u_words);
  }
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u_given, d_given, nullptr, &trace_given, &c_words));
  EXPECT_EQ(trace_given.words, words_expected);
  EXPECT_EQ(d_given, d_words);
  EXPECT_EQ(u_given, u_words);
}

GTEST_TEST(DixonSolve, LiftsInMachineWordsWhenTheEntriesAreSmallWithTheAnswersOfGmp) {
  std::mt19937_64 rng(12);
  int compared = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const int k = 1 + trial % 12;
    System s = random_system(rng, k, trial % 2 ? 52 : 58, (trial % 3) * 0.25);  // the seating blocks: ≤ 52 bits
    for (Integer& y : s.y) y = random_integer(rng, 120, 0.1);
    VectorQ x;
    if (!s.reference(x)) continue;
    SCOPED_TRACE(trial);
    expect_words_and_gmp_agree(s, true);
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

GTEST_TEST(DixonSolve, StaysInMachineWordsAtTheLargestEntriesItAccepts) {
  // k = 16, |C(a, j)| = 2^59 − 1 and |y_a| = 2^125 − 1, random signs: the
  // residuals' bound (2^126 before each division) is reached as nearly as
  // any input can.
  std::mt19937_64 rng(13);
  const Integer c_max = (Integer(1) << 59) - 1, y_max = (Integer(1) << 125) - 1;
  for (int trial = 0; trial < 3; ++trial) {
    System s;
    s.k = 16;
    for (int e = 0; e < 256; ++e) s.c.push_back(rng() & 1 ? c_max : Integer(-c_max));
    for (int a = 0; a < 16; ++a) s.y.push_back(rng() & 1 ? y_max : Integer(-y_max));
    VectorQ x;
    if (!s.reference(x)) continue;
    SCOPED_TRACE(trial);
    expect_words_and_gmp_agree(s, true);
  }
}

GTEST_TEST(DixonSolve, LiftsWithGmpPastTheWordBounds) {
  System s;
  s.k = 2;
  s.c = {Integer(1) << 59, Integer(1), Integer(1), Integer(3)};
  s.y = {Integer(1), Integer(1)};
  expect_words_and_gmp_agree(s, false);  // an entry of 2^59
  s.c = {Integer(5), Integer(1), Integer(1), Integer(3)};
  s.y = {Integer(1) << 125, Integer(1)};
  expect_words_and_gmp_agree(s, false);  // a right-hand side of 2^125
  std::mt19937_64 rng(14);
  System large = random_system(rng, 17, 20, 0.0);
  expect_words_and_gmp_agree(large, false);  // k = 17
}

GTEST_TEST(DixonSolve, DeclinesWhenEveryPrimeDividesTheDeterminant) {
  const std::vector<std::uint64_t>& primes = dixon_primes();
  System s;
  s.k = 2;
  Integer product = 1;
  for (const std::uint64_t p : primes) product *= Integer(p);
  s.c = {product, Integer(0), Integer(0), Integer(1)};
  s.y = {Integer(1), Integer(1)};
  std::vector<Integer> u;
  Integer d;
  EXPECT_FALSE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d));
}

GTEST_TEST(DixonSolve, DeclinesSingularSystemsAndWrongSizes) {
  System s;
  s.k = 2;
  s.c = {Integer(1), Integer(2), Integer(2), Integer(4)};
  s.y = {Integer(1), Integer(2)};  // consistent, but C is singular
  std::vector<Integer> u;
  Integer d;
  EXPECT_FALSE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d));
  EXPECT_FALSE(dixon_solve(3, s.c_pointers(), s.y_pointers(), u, d));
  EXPECT_FALSE(dixon_solve(-1, {}, {}, u, d));
  ASSERT_TRUE(dixon_solve(0, {}, {}, u, d));
  EXPECT_TRUE(u.empty());
  EXPECT_EQ(d, 1);
}

GTEST_TEST(DixonSolve, FindsEveryDenominatorWhenTheCombinationIsAnInteger) {
  // x = (1/3, −1/3): the combination x₀ + 2x₁ = −1/3, but with x = (1/3, 1/3)
  // x₀ + 2x₁ = 1 is an integer and d must grow from each value.
  System s;
  s.k = 2;
  s.c = {Integer(3), Integer(0), Integer(0), Integer(3)};
  s.y = {Integer(1), Integer(1)};
  expect_reference_solution(s);
  s.y = {Integer(1), Integer(-1)};
  expect_reference_solution(s);
}

// Enclosures of the reference solution, one double step outward on each
// side of its nearest double, as the filtered run's interval tableau would
// give them.
DixonHint hint_from(const VectorQ& x) {
  DixonHint hint;
  for (const Rational& v : x) {
    const double mid = to_double(v);
    hint.lo.push_back(std::nextafter(mid, -INFINITY));
    hint.hi.push_back(std::nextafter(mid, INFINITY));
  }
  return hint;
}

GTEST_TEST(DixonSolve, GivesTheSameAnswersWithAHintOnRandomSystems) {
  std::mt19937_64 rng(7);
  int solved = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int k = 1 + trial % 10;
    const int bits = (trial % 3 == 0) ? 8 : (trial % 3 == 1) ? 60 : 95;
    const System s = random_system(rng, k, bits, (trial % 4) * 0.2);
    VectorQ x;
    if (!s.reference(x)) continue;
    SCOPED_TRACE(trial);
    const DixonHint hint = hint_from(x);
    std::vector<Integer> u;
    Integer d;
    ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &hint));
    for (int j = 0; j < s.k; ++j) EXPECT_EQ(Rational(u[j], d), x[j]) << "x_" << j;
    ++solved;
  }
  EXPECT_GT(solved, 250);
}

GTEST_TEST(DixonSolve, NeverAnswersWronglyWithAWrongHint) {
  // Hints that exclude the solution (shifted, or collapsed to zero): the
  // answer is still the exact one, or none at all.
  std::mt19937_64 rng(8);
  int answered = 0, declined = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const int k = 1 + trial % 6;
    const System s = random_system(rng, k, trial % 2 ? 8 : 40, 0.1);
    VectorQ x;
    if (!s.reference(x)) continue;
    DixonHint hint = hint_from(x);
    for (int j = 0; j < k; ++j) {
      if (trial % 3 == 0) {
        hint.lo[j] = hint.hi[j] = 0;
      } else {
        hint.lo[j] = hint.lo[j] * 1.5 + 7;
        hint.hi[j] = hint.hi[j] * 1.5 + 7;
      }
    }
    std::vector<Integer> u;
    Integer d;
    if (!dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &hint)) {
      ++declined;
      continue;
    }
    ++answered;
    for (int j = 0; j < s.k; ++j) EXPECT_EQ(Rational(u[j], d), x[j]) << "trial " << trial << ", x_" << j;
  }
  // The last step reconstructs without the hint, so every system still
  // gets its answer (115 here), only later.
  EXPECT_GT(answered, 100);
  EXPECT_EQ(declined, 0);
}

GTEST_TEST(DixonSolve, StopsLiftingEarlierWithAHint) {
  // x = 1/3: without a hint reconstruction waits for the second step (a
  // one-prime modulus cannot tell garbage from an answer); the hint's
  // enclosure can, so the first step suffices.
  System s;
  s.k = 1;
  s.c = {Integer(3)};
  s.y = {Integer(1)};
  std::vector<Integer> u;
  Integer d;
  DixonTrace trace;
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, nullptr, &trace));
  EXPECT_EQ(trace.steps, 2);
  EXPECT_EQ(trace.attempts, 1);
  const DixonHint hint = hint_from(VectorQ::Constant(1, Rational(1, 3)));
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &hint, &trace));
  EXPECT_EQ(trace.steps, 1);
  EXPECT_EQ(trace.attempts, 1);
  EXPECT_EQ(Rational(u[0], d), Rational(1, 3));
}

GTEST_TEST(DixonSolve, FindsASmallFactorTheFirstDenominatorLacksByTrial) {
  // x = (1/2, 1/4): the combination x_0 + 2·x_1 = 1 has denominator 1, so
  // d = 1 lacks 2 for x_0 (d becomes 2), then 2 for x_1 (d becomes 4),
  // both found by trial against the hint, no reconstruction of x_j·d.
  System s;
  s.k = 2;
  s.c = {Integer(2), Integer(0), Integer(0), Integer(4)};
  s.y = {Integer(1), Integer(1)};
  VectorQ x(2);
  x << Rational(1, 2), Rational(1, 4);
  const DixonHint hint = hint_from(x);
  std::vector<Integer> u;
  Integer d;
  DixonTrace trace;
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &hint, &trace));
  EXPECT_EQ(d, Integer(4));
  EXPECT_EQ(Rational(u[0], d), x[0]);
  EXPECT_EQ(Rational(u[1], d), x[1]);
  EXPECT_EQ(trace.factors_by_trial, 2);
  EXPECT_EQ(trace.factors_by_reconstruction, 0);
}

GTEST_TEST(DixonSolve, ReconstructsAFactorTheFirstDenominatorLacksWhenTrialCannotFindIt) {
  // x = (1/17, 8/17): x_0 + 2·x_1 = 1 again, and the factor d lacks for
  // x_0 is 17, above the trials (2 to 16): x_0·d's reconstruction finds it,
  // and then x_1·17 = 8 needs nothing.
  System s;
  s.k = 2;
  s.c = {Integer(17), Integer(0), Integer(0), Integer(17)};
  s.y = {Integer(1), Integer(8)};
  VectorQ x(2);
  x << Rational(1, 17), Rational(8, 17);
  const DixonHint hint = hint_from(x);
  std::vector<Integer> u;
  Integer d;
  DixonTrace trace;
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &hint, &trace));
  EXPECT_EQ(d, Integer(17));
  EXPECT_EQ(Rational(u[0], d), x[0]);
  EXPECT_EQ(Rational(u[1], d), x[1]);
  EXPECT_EQ(trace.factors_by_trial, 0);
  EXPECT_EQ(trace.factors_by_reconstruction, 1);
}

GTEST_TEST(DixonSolve, CountsTheMissingFactorsOfTheAttemptThatAnswersOnly) {
  // x = (1/D, (D − 1)/(2D)), D = 2^40 + 15 (odd): x_0 + 2·x_1 = 1, so d = 1
  // lacks D for x_0. After the first step D's reconstruction fails (the
  // modulus is too small); after the third it succeeds, and x_1·D is
  // then an integer. One factor, found once: the failed try is not
  // counted.
  const Integer D = (Integer(1) << 40) + 15;
  System s;
  s.k = 2;
  s.c = {D, Integer(0), Integer(0), Integer(2 * D)};
  s.y = {Integer(1), Integer(D - 1)};
  VectorQ x(2);
  x << Rational(Integer(1), D), Rational(Integer(D - 1), Integer(2 * D));
  const DixonHint hint = hint_from(x);
  std::vector<Integer> u;
  Integer d;
  DixonTrace trace;
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &hint, &trace));
  EXPECT_EQ(Rational(u[0], d), x[0]);
  EXPECT_EQ(Rational(u[1], d), x[1]);
  EXPECT_EQ(trace.attempts, 2);
  EXPECT_EQ(trace.factors_by_trial, 0);
  EXPECT_EQ(trace.factors_by_reconstruction, 1);
}

GTEST_TEST(DixonSolve, WithAHintTriesAfterTheFirstStepThenFromTheThird) {
  // x = 1/D with D = 2^40 + 15: one prime's modulus (about 2^62) is below
  // 8·2·D², two primes' (2^124) is above it, but with a hint the attempt
  // after the second step is skipped, so the answer comes after the third:
  // 3 steps, 2 attempts. Hadamard's bound allows 4 steps here, so the
  // third is not the last (which always tries).
  const Integer D = (Integer(1) << 40) + 15;
  System s;
  s.k = 1;
  s.c = {D};
  s.y = {Integer(1)};
  const DixonHint hint = hint_from(VectorQ::Constant(1, Rational(Integer(1), D)));
  std::vector<Integer> u;
  Integer d;
  DixonTrace trace;
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &hint, &trace));
  EXPECT_EQ(Rational(u[0], d), Rational(Integer(1), D));
  EXPECT_EQ(trace.steps, 3);
  EXPECT_EQ(trace.attempts, 2);
}

GTEST_TEST(DixonSolve, NeedsNoMoreStepsWithAHintWhenTheValuesAreHuge) {
  // 200-bit entries: denominators of about 1,000 bits, past double range.
  // The hint's tests must not overflow into rejecting every candidate
  // (which would lift on to Hadamard's bound), and an enclosure that is the
  // whole line is no hint at all.
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    const System s = random_system(rng, 5, 200, 0.0);
    VectorQ x;
    ASSERT_TRUE(s.reference(x));
    std::vector<Integer> u;
    Integer d;
    DixonTrace plain, hinted, whole_line;
    ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, nullptr, &plain));
    const DixonHint hint = hint_from(x);
    ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &hint, &hinted));
    for (int j = 0; j < s.k; ++j) EXPECT_EQ(Rational(u[j], d), x[j]) << "trial " << trial << ", x_" << j;
    EXPECT_LE(hinted.steps, plain.steps) << "trial " << trial;
    DixonHint line;
    line.lo.assign(s.k, -INFINITY);
    line.hi.assign(s.k, INFINITY);
    ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &line, &whole_line));
    EXPECT_EQ(whole_line.steps, plain.steps) << "trial " << trial;
    for (int j = 0; j < s.k; ++j) EXPECT_EQ(Rational(u[j], d), x[j]) << "trial " << trial << ", x_" << j;
  }
}

GTEST_TEST(DixonSolve, IgnoresAHintOfAnotherSize) {
  System s;
  s.k = 2;
  s.c = {Integer(3), Integer(0), Integer(0), Integer(5)};
  s.y = {Integer(1), Integer(1)};
  DixonHint hint;
  hint.lo = {0.3};
  hint.hi = {0.4, 0.2};
  std::vector<Integer> u;
  Integer d;
  DixonTrace trace;
  ASSERT_TRUE(dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d, &hint, &trace));
  EXPECT_EQ(trace.steps, 2);  // as without a hint
  EXPECT_EQ(Rational(u[0], d), Rational(1, 3));
  EXPECT_EQ(Rational(u[1], d), Rational(1, 5));
}

// The acceptance test takes C·u ≡ d·y (mod M) as given and must tell
// C·u = d·y from every other residual that congruence allows: one more M
// in a u_j (a residual that is a nonzero multiple of M), and one more
// M·2^128 (a residual ≡ 0 mod 2^128 too, which only the size bound can
// catch). Over moduli large enough for the word test (p^20 always, p³ and
// p for the smaller systems) and too small for it (3, 1), where the exact
// products decide.
GTEST_TEST(DixonAccepts, TellsTheSolutionFromEveryResidualTheCongruenceAllows) {
  std::mt19937_64 rng(29);
  const Integer p = Integer(dixon_primes()[0]);
  const Integer two_128 = Integer(1) << 128;
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int k = 1 + trial % 16;
    const System s = random_system(rng, k, trial % 2 == 0 ? 52 : 90, 0.2);
    std::vector<Integer> u;
    Integer d;
    if (!dixon_solve(s.k, s.c_pointers(), s.y_pointers(), u, d)) continue;  // singular
    SCOPED_TRACE(trial);
    Integer p_20 = 1;
    for (int e = 0; e < 20; ++e) p_20 *= p;
    for (const Integer& M : {p_20, Integer(p * p * p), Integer(p), Integer(3), Integer(1)}) {
      EXPECT_TRUE(dixon_accepts(s.k, s.c_pointers(), s.y_pointers(), u, d, M)) << "M = " << M;
      for (const Integer& shift : {M, Integer(M * two_128), Integer(-M * two_128)}) {
        std::vector<Integer> wrong = u;
        const int j = static_cast<int>(rng() % static_cast<unsigned>(k));
        wrong[j] += shift;
        EXPECT_FALSE(dixon_accepts(s.k, s.c_pointers(), s.y_pointers(), wrong, d, M))
            << "M = " << M << ", u_" << j << " shifted by " << shift;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
  // Malformed sizes: no answer.
  std::vector<Integer> u{Integer(1)};
  EXPECT_FALSE(dixon_accepts(2, {}, {}, u, Integer(1), p));
}

GTEST_TEST(DixonAccepts, RejectsAResidualOfExactlyMTimes2To128) {
  // C = (1), d = 1, u = y ± M·2^128: the residual ±M·2^128 is ≡ 0 both
  // modulo M and modulo 2^128, and |r| = M·2^128 is just outside what the
  // size bound may admit; a bound looser by 2 bits accepts it.
  const Integer p = Integer(dixon_primes()[0]);
  const Integer two_128 = Integer(1) << 128;
  System s;
  s.k = 1;
  s.c = {Integer(1)};
  s.y = {Integer(12345)};
  for (const Integer& M : {Integer(1), Integer(3), p, Integer(p * p * p)}) {
    EXPECT_TRUE(dixon_accepts(1, s.c_pointers(), s.y_pointers(), {s.y[0]}, Integer(1), M)) << "M = " << M;
    for (const int sign : {1, -1}) {
      const std::vector<Integer> wrong{s.y[0] + sign * M * two_128};
      EXPECT_FALSE(dixon_accepts(1, s.c_pointers(), s.y_pointers(), wrong, Integer(1), M))
          << "M = " << M << ", sign " << sign;
    }
  }
}

}  // namespace
}  // namespace fixel::internal
