#include "fixel/lemke.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/internal/lemke_filtered.h"
#include "fixel/internal/paper_reference.h"
#include "fixel/lcp.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::mat;
using test::vec;

// Second method: every solution with a nonsingular principal block B_SS,
// found by trying all 2^n complementary bases.
std::vector<VectorQ> brute_force_solutions(const MatrixQ& B, const VectorQ& b) {
  const int n = static_cast<int>(b.size());
  std::vector<VectorQ> out;
  for (int mask = 0; mask < (1 << n); ++mask) {
    std::vector<int> S;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i)) S.push_back(i);
    VectorQ z = VectorQ::Zero(n);
    if (!S.empty()) {
      MatrixQ BSS(S.size(), S.size());
      VectorQ bS(S.size());
      for (std::size_t r = 0; r < S.size(); ++r) {
        bS[r] = -b[S[r]];
        for (std::size_t c = 0; c < S.size(); ++c) BSS(r, c) = B(S[r], S[c]);
      }
      const auto lu = internal::exact_lu(BSS);
      if (!lu.isInvertible()) continue;
      const VectorQ zS = lu.solve(bS);
      for (std::size_t r = 0; r < S.size(); ++r) z[S[r]] = zS[r];
    }
    // Degenerate problems reach one solution from several bases.
    if (is_solution(B, b, VectorQ(B * z + b), z) && std::find(out.begin(), out.end(), z) == out.end()) out.push_back(z);
  }
  return out;
}

GTEST_TEST(Lemke, SolvesPaperExample2AndItsNormalImpulsesAreTheEq27Values) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  VectorQ p = vec({-1, -1, -1});
  const TimeSteppingLcp lcp = build_lcp(scene);
  const LemkeResult r = solve_lcp_lemke(lcp.B, lcp.b(p));
  ASSERT_EQ(r.status, LemkeStatus::kSolved);
  EXPECT_TRUE(is_solution(lcp.B, lcp.b(p), r.w, r.z));
  EXPECT_TRUE(r.w.head(3).isZero());  // ρ_n = ψ^{ℓ+1}/h = 0: seated
  const VectorQ y = seating_system(scene, seating_set(scene)).y(p);
  EXPECT_EQ(VectorQ(r.z.head(3)), VectorQ(y.segment(3, 3)));  // p_n = (161/202, 183/505, 337/505)
  EXPECT_EQ(r.z[0], Rational(161, 202));
}

GTEST_TEST(Lemke, OneByOneProblemsAreSolvedOrEndOnARayExactlyWhenNoSolutionExists) {
  auto solve = [](int B, int b) { return solve_lcp_lemke(mat({{B}}), vec({b})); };
  const auto a = solve(1, -1);
  ASSERT_EQ(a.status, LemkeStatus::kSolved);
  EXPECT_EQ(a.z[0], Rational(1));
  EXPECT_EQ(a.w[0], Rational(0));
  EXPECT_EQ(solve(2, 0).status, LemkeStatus::kSolved);
  // w = −z − 1 ≥ 0 has no solution; Siconos 4.4's driver reports it solved.
  EXPECT_EQ(solve(-1, -1).status, LemkeStatus::kRayTermination);
  EXPECT_EQ(solve(0, -1).status, LemkeStatus::kRayTermination);
  EXPECT_EQ(solve(0, 3).z[0], Rational(0));
}

GTEST_TEST(Lemke, AnInfeasibleProblemEndsOnARay) {
  // w1 = −z2 − 1 can never be ≥ 0; B is skew (copositive-plus), so Lemke's
  // ray is a certificate of infeasibility.
  const MatrixQ B = mat({{0, -1}, {1, 0}});
  EXPECT_TRUE(brute_force_solutions(B, vec({-1, -1})).empty());
  EXPECT_EQ(solve_lcp_lemke(B, vec({-1, -1})).status, LemkeStatus::kRayTermination);
  EXPECT_EQ(solve_lcp_lemke(mat({{-1, 0}, {0, -1}}), vec({-1, -1})).status, LemkeStatus::kRayTermination);
}

GTEST_TEST(Lemke, TiesInTheRatioTestStillEndWithASolution) {
  // b has zeros and equal negative entries: both the first pivot and later
  // ratio tests tie; the lexicographic rule must still end with a solution.
  const MatrixQ B = mat({{1, 2, 0, 0}, {0, 1, 2, 0}, {0, 0, 1, 2}, {2, 0, 0, 1}});
  const VectorQ b = vec({-1, -1, 0, 0});
  const auto r = solve_lcp_lemke(B, b);
  ASSERT_EQ(r.status, LemkeStatus::kSolved);
  EXPECT_TRUE(is_solution(B, b, r.w, r.z));
  const MatrixQ I = MatrixQ::Identity(4, 4);
  const auto r2 = solve_lcp_lemke(I, vec({0, -1, 0, -1}));
  ASSERT_EQ(r2.status, LemkeStatus::kSolved);
  EXPECT_EQ(r2.z, vec({0, 1, 0, 1}));
}

GTEST_TEST(Lemke, PivotLimitIsAStatusNotASolution) {
  const MatrixQ B = mat({{1, 2, 0}, {0, 1, 2}, {2, 0, 1}});
  const auto r = solve_lcp_lemke(B, vec({-1, -1, -1}), 1);
  EXPECT_EQ(r.status, LemkeStatus::kPivotLimit);
  EXPECT_EQ(r.z.size(), 0);
}

GTEST_TEST(Lemke, RejectsMismatchedSizes) { EXPECT_THROW(solve_lcp_lemke(mat({{1, 0}}), vec({1})), InputError); }

// Lemke's theorem: for positive semidefinite B (copositive-plus), the
// lexicographic method ends with a solution exactly when one exists. Random
// degenerate problems (b with many zeros and repeated values) check this
// against brute force.
GTEST_TEST(Lemke, SolvesExactlyTheSolvableDegeneratePsdProblems) {
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int> small(-2, 2), size(1, 6);
  int solved = 0, unsolvable = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int n = size(rng);
    MatrixQ A(n, n), S(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = small(rng);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) S(i, j) = small(rng), S(j, i) = -S(i, j);
    for (int i = 0; i < n; ++i) S(i, i) = 0;
    const MatrixQ B = A.transpose() * A + S;  // PSD plus skew: copositive-plus
    VectorQ b(n);
    for (int i = 0; i < n; ++i) b[i] = trial % 3 == 0 ? Rational(small(rng)) : Rational(small(rng) < 0 ? -1 : 0);
    const auto r = solve_lcp_lemke(B, b);
    const bool exists = !brute_force_solutions(B, b).empty();
    ASSERT_NE(r.status, LemkeStatus::kPivotLimit);
    EXPECT_EQ(r.status == LemkeStatus::kSolved, exists) << "trial " << trial;
    if (r.status == LemkeStatus::kSolved) {
      EXPECT_TRUE(is_solution(B, b, r.w, r.z));
      ++solved;
    } else {
      ++unsolvable;
    }
  }
  EXPECT_GT(solved, 200);
  EXPECT_GE(unsolvable, 5);
}

// P-matrices have exactly one solution; Lemke must return it.
GTEST_TEST(Lemke, FindsTheUniqueSolutionOfPMatrixProblems) {
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<int> small(-3, 3);
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 2 + trial % 5;
    MatrixQ A(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = Rational(small(rng), 1 + trial % 4);
    const MatrixQ B = A.transpose() * A + MatrixQ::Identity(n, n);  // positive definite
    VectorQ b(n);
    for (int i = 0; i < n; ++i) b[i] = Rational(small(rng), 3);
    const auto all = brute_force_solutions(B, b);
    ASSERT_EQ(all.size(), 1u);
    const auto r = solve_lcp_lemke(B, b);
    ASSERT_EQ(r.status, LemkeStatus::kSolved);
    EXPECT_EQ(r.z, all[0]);
  }
}

// The filtered run (interval tableau) and the forced exact run agree on
// status, pivots, w and z, problem by problem: seating LCPs of random
// scenes at impulses around S, and random degenerate PSD problems.
LemkeResult solve_forced_exact(const MatrixQ& B, const VectorQ& b) {
  ForceExactScope exact;
  return solve_lcp_lemke(B, b);
}

// The seating LCP of a random 3-fixel scene at an impulse around its S, as
// lemke_bench's problems; false when the scene has no seating set.
bool random_seating_lcp(std::mt19937_64& rng, TimeSteppingLcp& lcp, VectorQ& b) {
  const Scene scene = test::random_scene(rng, 3);
  SeatingSet S;
  try {
    S = seating_set(scene);
  } catch (const Error&) {
    return false;
  }
  VectorQ p = S.apex;
  for (int j = 0; j < 3; ++j) p -= test::random_rational(rng, -1, 3, 7) * S.generators[j];
  lcp = build_lcp(scene);
  b = lcp.b(p);
  return true;
}

// An n×n LCP of small fractions: entries in [−3, 3] over 1 + trial % 3
// (B) and 1 + trial % 4 (b), with `diagonal` added to B's diagonal.
void random_small_lcp(std::mt19937_64& rng, int n, int trial, int diagonal, MatrixQ& B, VectorQ& b) {
  std::uniform_int_distribution<int> small(-3, 3);
  B.resize(n, n);
  b.resize(n);
  for (int i = 0; i < n; ++i) {
    b[i] = Rational(small(rng), 1 + trial % 4);
    for (int j = 0; j < n; ++j) B(i, j) = Rational(small(rng), 1 + trial % 3);
    B(i, i) += diagonal;
  }
}

void expect_same(const LemkeResult& a, const LemkeResult& b, int trial) {
  EXPECT_EQ(a.status, b.status) << "trial " << trial;
  EXPECT_EQ(a.pivots, b.pivots) << "trial " << trial;
  EXPECT_EQ(a.w, b.w) << "trial " << trial;
  EXPECT_EQ(a.z, b.z) << "trial " << trial;
}

GTEST_TEST(FilteredLemke, GivesTheForcedExactAnswerOnSeatingLcpsOfRandomScenes) {
  ForceExactScope filtered(false);
  reset_filter_stats();
  internal::reset_final_value_counts();
  std::mt19937_64 rng(2026);
  int problems = 0;
  while (problems < 40) {
    TimeSteppingLcp lcp;
    VectorQ b;
    if (!random_seating_lcp(rng, lcp, b)) continue;
    const LemkeResult solved = solve_lcp_lemke(lcp.B, b);
    expect_same(solved, solve_forced_exact(lcp.B, b), problems);
    if (!(b.array() >= Rational(0)).all()) {
      // The pivot path alone ends where the whole run does, at a basis that
      // holds every nonzero value of the answer.
      LemkeResult path;
      std::vector<int> basis;
      ASSERT_TRUE(internal::filtered_lemke_path(lcp.B, b, 100 * 13, path, basis));
      EXPECT_EQ(path.status, solved.status);
      EXPECT_EQ(path.pivots, solved.pivots);
      EXPECT_TRUE(path.w.size() == 0 && path.z.size() == 0);
      const int n = static_cast<int>(b.size());
      for (int i = 0; i < n; ++i) {
        const bool w_basic = std::find(basis.begin(), basis.end(), i) != basis.end();
        const bool z_basic = std::find(basis.begin(), basis.end(), n + i) != basis.end();
        if (solved.w[i] != 0) {
          EXPECT_TRUE(w_basic) << "w_" << i << ", problem " << problems;
        }
        if (solved.z[i] != 0) {
          EXPECT_TRUE(z_basic) << "z_" << i << ", problem " << problems;
        }
      }
      EXPECT_EQ(std::find(basis.begin(), basis.end(), 2 * n), basis.end());  // z0 left
    }
    ++problems;
  }
  // Most decisions are certified by the intervals. The exact ratio ties of
  // the friction-cone rows, which no interval can certify, are proved by
  // integer null vectors (kLemkeTie) or, when they set the z0 row against
  // another in the last ratio test of a run with values, settled by the
  // final values' signs; the few left over are decided on exact tableau
  // columns. Here the pivot-path runs prove 47 ties and leave none, and the
  // full runs settle 28 z0-row decisions, none of them wrong.
  const FilterCounts c = filter_stats().at(FilterSite::kLemke);
  const FilterCounts ties = filter_stats().at(FilterSite::kLemkeTie);
  EXPECT_GT(c.certified, c.fallbacks);
  EXPECT_GT(ties.certified, 10 * ties.fallbacks);
  EXPECT_GE(c.fallbacks, ties.fallbacks);  // an unproved tie is decided exactly
  // The final values came from p-adic lifting (internal/lemke_dixon.h),
  // which never declined here, on the solved runs whose final basis's exact
  // columns were not at hand already (most of them).
  const internal::FinalValueCounts values = internal::final_value_counts();
  EXPECT_GT(values.dixon, problems / 2);
  EXPECT_LE(values.dixon, problems);
  EXPECT_EQ(values.factored, 0);
  EXPECT_GT(values.z0_settled, 0);
  EXPECT_EQ(values.z0_reruns, 0);
  // Factors the combination's denominator lacked were found by trial here
  // (the answers above are the forced exact run's all the same).
  EXPECT_GT(values.factors_by_trial, 0);
  // The friction rows of the final blocks (y_a = 0, one or two entries) fix
  // unknowns before lifting (internal/lemke_dixon_sparse.h): more than one
  // a block on average, with the same answers as above.
  EXPECT_GT(values.unknowns_eliminated, values.dixon);
}

// The test switch leaves every comparison of the z0 row to the final values
// and keeps the z0 row in every ratio test where its entry is positive, so
// the run often ends too early on purpose: a negative final value must then
// send it to the second run, and the answer must not change.
GTEST_TEST(FilteredLemke, GivesTheForcedExactAnswerWhenEveryZ0RowDecisionIsLeftToTheFinalValues) {
  ForceExactScope filtered(false);
  struct Switch {
    Switch() { internal::set_lemke_leave_every_z0_comparison_unordered(true); }
    ~Switch() { internal::set_lemke_leave_every_z0_comparison_unordered(false); }
  } on;
  internal::reset_final_value_counts();
  std::mt19937_64 rng(2027);
  int problems = 0;
  while (problems < 30) {
    TimeSteppingLcp lcp;
    VectorQ b;
    if (!random_seating_lcp(rng, lcp, b)) continue;
    expect_same(solve_lcp_lemke(lcp.B, b), solve_forced_exact(lcp.B, b), problems);
    ++problems;
  }
  std::uniform_int_distribution<int> size(2, 6);
  for (int trial = 0; trial < 200; ++trial) {
    MatrixQ B;
    VectorQ b;
    random_small_lcp(rng, size(rng), trial, 4, B, b);  // mostly P-matrices, so that most runs solve
    expect_same(solve_lcp_lemke(B, b), solve_forced_exact(B, b), trial);
  }
  const internal::FinalValueCounts values = internal::final_value_counts();
  EXPECT_GT(values.z0_settled, 0);
  EXPECT_GT(values.z0_reruns, 0);
}

// One LemkeResult reused across a mix of problems (seating LCPs, b ≥ 0,
// ray terminations, pivot limits, sizes that change), filtered and forced
// exact: each answer is the returning overload's, field for field, so no
// value of an earlier problem survives into a later one.
GTEST_TEST(Lemke, GivesTheSameAnswersIntoOneReusedResult) {
  std::mt19937_64 rng(2028);
  std::uniform_int_distribution<int> size(1, 5);
  LemkeResult reused;
  int solved = 0, unsolved = 0;
  for (int trial = 0; trial < 150; ++trial) {
    MatrixQ B;
    VectorQ b;
    int max_pivots = 0;
    if (trial < 40) {  // seating LCPs back to back: size 12 each time
      TimeSteppingLcp lcp;
      if (!random_seating_lcp(rng, lcp, b)) continue;
      B = lcp.B;
    } else {  // size 4, then sizes that change
      random_small_lcp(rng, trial < 100 ? 4 : size(rng), trial, 0, B, b);
      if (trial % 7 == 0) max_pivots = 2;
    }
    ForceExactScope exact(trial % 5 == 0);
    solve_lcp_lemke(B, b, reused, max_pivots);
    const LemkeResult fresh = solve_lcp_lemke(B, b, max_pivots);
    expect_same(reused, fresh, trial);
    ++(fresh.status == LemkeStatus::kSolved ? solved : unsolved);
  }
  EXPECT_GT(solved, 60);
  EXPECT_GT(unsolved, 10);
}

GTEST_TEST(FilteredLemke, GivesTheForcedExactAnswerOnDegeneratePsdProblems) {
  ForceExactScope filtered(false);
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int> small(-2, 2), size(1, 6);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = size(rng);
    MatrixQ A(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = Rational(small(rng), 1 + trial % 3);
    const MatrixQ B = A.transpose() * A;
    VectorQ b(n);
    for (int i = 0; i < n; ++i) b[i] = trial % 2 ? Rational(small(rng), 3) : Rational(small(rng) < 0 ? -1 : 0);
    expect_same(solve_lcp_lemke(B, b), solve_forced_exact(B, b), trial);
  }
}

// Ratio ties between rows whose entries are not exact in double (thirds):
// the intervals cannot certify the tie, so it is decided on the exact
// tableau's columns, and the run gives the forced-exact answer.
GTEST_TEST(FilteredLemke, DecidesATieTheIntervalsCannotCertifyOnExactTableauColumns) {
  ForceExactScope filtered(false);
  const MatrixQ B = mat({{1, 0}, {0, 1}});
  VectorQ b(2);
  b << Rational(-1, 3), Rational(-1, 3);
  reset_filter_stats();
  const auto r = solve_lcp_lemke(B, b);
  EXPECT_GE(filter_stats().at(FilterSite::kLemke).fallbacks, 1);
  ASSERT_EQ(r.status, LemkeStatus::kSolved);
  EXPECT_EQ(r.z, (VectorQ(2) << Rational(1, 3), Rational(1, 3)).finished());
  expect_same(r, solve_forced_exact(B, b), 0);
  // The same tie in dyadic numbers is exact in double: every decision certified.
  reset_filter_stats();
  b << Rational(-1, 4), Rational(-1, 4);
  EXPECT_EQ(solve_lcp_lemke(B, b).z, (VectorQ(2) << Rational(1, 4), Rational(1, 4)).finished());
  EXPECT_EQ(filter_stats().at(FilterSite::kLemke).fallbacks, 0);
  EXPECT_GT(filter_stats().at(FilterSite::kLemke).certified, 0);
}

// A zero entry of the entering column that the intervals cannot certify
// (1/3 − 1/3 after the first pivot), in a row that would lose the ratio
// test whatever its sign (rhs 6 against the winner's 1 at entry 1/3): no
// exact decision is needed. By hand: z0 leaves at the second pivot, with
// z = (3, 0, 0) and w = Bz + b = (0, 6, 10).
GTEST_TEST(FilteredLemke, AZeroEntryInARowThatCertainlyLosesNeedsNoExactSign) {
  ForceExactScope filtered(false);
  MatrixQ B = mat({{0, 0, 0}, {0, 1, 0}, {1, 0, 1}});
  B(0, 0) = Rational(1, 3);
  B(1, 0) = Rational(1, 3);
  const VectorQ b = vec({-1, 5, 7});
  reset_filter_stats();
  const auto r = solve_lcp_lemke(B, b);
  EXPECT_EQ(filter_stats().at(FilterSite::kLemke).fallbacks, 0);
  ASSERT_EQ(r.status, LemkeStatus::kSolved);
  EXPECT_EQ(r.pivots, 2);
  EXPECT_EQ(r.z, vec({3, 0, 0}));
  EXPECT_EQ(r.w, vec({0, 6, 10}));
  expect_same(r, solve_forced_exact(B, b), 0);
}

// Degenerate problems whose ties come late in the path (several z's basic):
// the exact columns then need the LU of a larger block, with row swaps.
GTEST_TEST(FilteredLemke, GivesTheForcedExactAnswerWhenTiesNeedALargerExactBlock) {
  ForceExactScope filtered(false);
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> small(-3, 3);
  reset_filter_stats();
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 5 + trial % 4;
    MatrixQ A(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = Rational(small(rng), 3 + trial % 5);
    const MatrixQ B = A.transpose() * A;  // PSD, often singular blocks: zero pivots to swap past
    VectorQ b(n);
    for (int i = 0; i < n; ++i) b[i] = i % 2 ? Rational(0) : Rational(small(rng) - 3, 7);
    expect_same(solve_lcp_lemke(B, b), solve_forced_exact(B, b), trial);
  }
  EXPECT_GT(filter_stats().at(FilterSite::kLemke).fallbacks, 0);
}

// Denominators whose lcm per row needs more than 64 bits (products of the
// primes 2^61 − 1 and 2^31 − 1), in B and in b: the exact side scales those
// rows in GMP integers rather than machine words, and b's column by its own
// large factor δ. Answers must still be the forced exact run's.
GTEST_TEST(FilteredLemke, GivesTheForcedExactAnswerWithDenominatorsBeyondSixtyFourBits) {
  ForceExactScope filtered(false);
  const Integer p61 = (Integer(1) << 61) - 1, p31 = (Integer(1) << 31) - 1;
  const Integer dens[] = {p61, p31, p61 * p31, Integer(3) * p61};
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> small(-3, 3), pick(0, 3);
  int solved = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 2 + trial % 4;
    MatrixQ A(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = Rational(Integer(small(rng)), dens[pick(rng)]);
    const MatrixQ B = A.transpose() * A + MatrixQ::Identity(n, n) * Rational(Integer(1), dens[pick(rng)]);
    VectorQ b(n);
    for (int i = 0; i < n; ++i) b[i] = Rational(Integer(small(rng) - 1), dens[pick(rng)]);
    const auto r = solve_lcp_lemke(B, b);
    expect_same(r, solve_forced_exact(B, b), trial);
    solved += r.status == LemkeStatus::kSolved;
  }
  EXPECT_EQ(solved, 60);  // B positive definite: every LCP has a solution, which Lemke finds
}

// A prepared matrix (LemkeMatrix) against the bare one: each B prepared
// once and solved for several b in turn, filtered and forced exact,
// returned and into one reused result. Every answer must be the bare
// matrix's forced exact answer, field for field. The problems: seating
// LCPs of random scenes (three impulses around S each), degenerate PSD
// problems (ties, zero pivots), and rows whose denominators need more than
// 64 bits (scaled in GMP integers, not words).
GTEST_TEST(LemkeMatrix, GivesTheBareMatrixsAnswerForEveryRightHandSide) {
  std::mt19937_64 rng(2029);
  std::vector<std::pair<MatrixQ, std::vector<VectorQ>>> problems;
  const int scenes = test::sanitizer_scaled(20);
  while (static_cast<int>(problems.size()) < scenes) {
    const Scene scene = test::random_scene(rng, 3);
    SeatingSet S;
    try {
      S = seating_set(scene);
    } catch (const Error&) {
      continue;
    }
    const TimeSteppingLcp lcp = build_lcp(scene);
    std::vector<VectorQ> rhs;
    for (int k = 0; k < 3; ++k) {
      VectorQ p = S.apex;
      for (int j = 0; j < 3; ++j) p -= test::random_rational(rng, -1, 3, 7) * S.generators[j];
      rhs.push_back(lcp.b(p));
    }
    problems.emplace_back(lcp.B, rhs);
  }
  std::uniform_int_distribution<int> small(-2, 2), size(1, 6);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = size(rng);
    MatrixQ A(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = Rational(small(rng), 1 + trial % 3);
    std::vector<VectorQ> rhs(2, VectorQ(n));
    for (VectorQ& b : rhs)
      for (int i = 0; i < n; ++i) b[i] = i % 2 ? Rational(0) : Rational(small(rng) - 1, 3);
    problems.emplace_back(A.transpose() * A, rhs);
  }
  const Integer p61 = (Integer(1) << 61) - 1, p31 = (Integer(1) << 31) - 1;
  for (int trial = 0; trial < 10; ++trial) {
    const int n = 2 + trial % 4;
    MatrixQ A(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = Rational(Integer(small(rng)), (i + j) % 2 ? p61 : p61 * p31);
    std::vector<VectorQ> rhs(2, VectorQ(n));
    for (VectorQ& b : rhs)
      for (int i = 0; i < n; ++i) b[i] = Rational(Integer(small(rng) - 1), i % 2 ? p31 : Integer(3));
    problems.emplace_back(A.transpose() * A + MatrixQ::Identity(n, n), rhs);
  }
  int solved = 0, unsolved = 0, solves = 0;
  LemkeResult reused;
  for (const auto& [B, rhs] : problems) {
    const LemkeMatrix prepared(B);
    ASSERT_EQ(prepared.size(), B.rows());
    ASSERT_EQ(prepared.matrix(), B);
    for (const VectorQ& b : rhs) {
      const LemkeResult expected = solve_forced_exact(B, b);
      // The filtered runs also take the same decisions, on the same
      // evidence: a prepared tableau that lost anything would show as more
      // exact fallbacks, even where the fallback restores the answer.
      FilterCounts bare, twice;
      for (const bool exact : {false, true}) {
        ForceExactScope scope(exact);
        reset_filter_stats();
        expect_same(solve_lcp_lemke(prepared, b), expected, solves);
        solve_lcp_lemke(prepared, b, reused);
        expect_same(reused, expected, solves);
        if (!exact) twice = filter_stats().at(FilterSite::kLemke);
      }
      // The bare run after the prepared ones: its scaled rows must not be
      // what the prepared run read.
      {
        ForceExactScope filtered(false);
        reset_filter_stats();
        expect_same(solve_lcp_lemke(B, b), expected, solves);
        bare = filter_stats().at(FilterSite::kLemke);
      }
      EXPECT_EQ(twice.certified, 2 * bare.certified) << "solve " << solves;
      EXPECT_EQ(twice.fallbacks, 2 * bare.fallbacks) << "solve " << solves;
      ++(expected.status == LemkeStatus::kSolved ? solved : unsolved);
      ++solves;
    }
  }
  // Most seating LCPs and PSD problems solve; every one beyond 64 bits does
  // (B positive definite).
  EXPECT_GT(solved, 2 * scenes);
  EXPECT_GE(solves, 3 * scenes + 100);
}

// One LemkeMatrix shared by two threads, each solving its own right-hand
// sides: the prepared data is only read, and each thread's answers are the
// ones it gets alone.
GTEST_TEST(LemkeMatrix, OneMatrixSolvedFromTwoThreadsGivesEachThreadsOwnAnswers) {
  std::mt19937_64 rng(2030);
  TimeSteppingLcp lcp;
  VectorQ b;
  while (!random_seating_lcp(rng, lcp, b)) {
  }
  const LemkeMatrix prepared(lcp.B);
  std::vector<VectorQ> rhs;
  for (int k = 0; k < 8; ++k) rhs.push_back(lcp.b(VectorQ::Constant(3, Rational(-1 - k, 3 + k))));
  std::vector<LemkeResult> alone;
  for (const VectorQ& x : rhs) alone.push_back(solve_lcp_lemke(lcp.B, x));
  std::vector<LemkeResult> first(rhs.size()), second(rhs.size());
  std::thread t([&] {
    for (std::size_t k = 0; k < rhs.size(); ++k) first[k] = solve_lcp_lemke(prepared, rhs[k]);
  });
  for (std::size_t k = rhs.size(); k-- > 0;) second[k] = solve_lcp_lemke(prepared, rhs[k]);
  t.join();
  int solved = 0;
  for (std::size_t k = 0; k < rhs.size(); ++k) {
    expect_same(first[k], alone[k], static_cast<int>(k));
    expect_same(second[k], alone[k], static_cast<int>(k));
    solved += alone[k].status == LemkeStatus::kSolved;
  }
  EXPECT_GT(solved, 0);
}

GTEST_TEST(LemkeMatrix, RejectsANonSquareMatrixAndAWrongSizedRightHandSide) {
  try {
    LemkeMatrix bad(mat({{1, 0}}));
    FAIL() << "a 1x2 matrix was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1x2"), std::string::npos) << e.what();
  }
  const LemkeMatrix B(mat({{2, 1}, {1, 2}}));
  EXPECT_THROW(solve_lcp_lemke(B, vec({1, -1, 1})), InputError);
  const LemkeResult r = solve_lcp_lemke(B, vec({-1, -1}));
  ASSERT_EQ(r.status, LemkeStatus::kSolved);
  EXPECT_EQ(r.z, vec({Rational(1, 3), Rational(1, 3)}));  // 2z + z = 1 in both rows
  EXPECT_EQ(r.w, vec({0, 0}));
}

GTEST_TEST(FilteredLemke, ForcedExactRunsCountNoFilterDecision) {
  reset_filter_stats();
  solve_forced_exact(mat({{2, 1}, {1, 2}}), vec({-1, -1}));
  EXPECT_EQ(filter_stats().at(FilterSite::kLemke).certified + filter_stats().at(FilterSite::kLemke).fallbacks, 0);
}

GTEST_TEST(IsSolution, RejectsEachViolatedCondition) {
  const MatrixQ B = mat({{1}});
  EXPECT_TRUE(is_solution(B, vec({-1}), vec({0}), vec({1})));
  EXPECT_FALSE(is_solution(B, vec({-1}), vec({1}), vec({1})));   // w ≠ Bz + b
  EXPECT_FALSE(is_solution(B, vec({-1}), vec({-1}), vec({0})));  // w < 0
  EXPECT_FALSE(is_solution(B, vec({1}), vec({0}), vec({-1})));   // z < 0
  EXPECT_FALSE(is_solution(B, vec({1}), vec({2}), vec({1})));    // wᵀz ≠ 0
}

GTEST_TEST(IsSolution, AgreesWithTheRationalDefinitionOnRandomComplementaryPairs) {
  // Second method: w == B·z + b evaluated by Eigen in rationals. Each pair is
  // built to satisfy it, then one entry of b is moved by a tiny amount.
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 8;
    MatrixQ B(n, n);
    VectorQ w(n), z(n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) B(i, j) = test::random_rational(rng, -5, 5, 97);
      const bool z_basic = rng() % 2 == 0;
      z[i] = z_basic ? test::random_rational(rng, 0, 4, 1009) : Rational(0);
      w[i] = z_basic ? Rational(0) : test::random_rational(rng, 0, 4, 1013);
    }
    VectorQ b = w - B * z;
    ASSERT_EQ(VectorQ(B * z + b), w);
    EXPECT_TRUE(is_solution(B, b, w, z)) << "trial " << trial;
    const int i = static_cast<int>(rng() % n);
    b[i] += Rational(1, 1000003);
    ASSERT_NE(VectorQ(B * z + b), w);
    EXPECT_FALSE(is_solution(B, b, w, z)) << "trial " << trial;
  }
}

// One LCP polls the calling thread's ControlScope: the filtered run at
// each lifting step of its exact values, the exact run at each pivot.
// Entries of thousands of digits make either take seconds.
GTEST_TEST(Lemke, BothRunsStopInsideACancelledControlScopeNamingTheLcp) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  const TimeSteppingLcp lcp = build_lcp(scene);
  const VectorQ b = lcp.b(vec({-1, -1, -1}));
  const test::CancelledControl cancelled;
  for (const bool exact : {false, true}) {
    const ForceExactScope forced(exact);
    EXPECT_EQ(test::stop_message([&] { solve_lcp_lemke(lcp.B, b); }), "(no stop)") << exact;
    const ControlScope scope(&cancelled.control);
    EXPECT_EQ(test::stop_message([&] { solve_lcp_lemke(lcp.B, b); }).rfind("LCP (Lemke): interrupted after ", 0), 0u)
        << exact;
  }
}
}  // namespace
}  // namespace fixel
