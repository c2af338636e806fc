#pragma once
// The filtered Lemke run's final values (src/lemke_dixon.cpp): the basis
// block solved by p-adic lifting (Dixon) and rational reconstruction, whose
// work grows with the size of the answer rather than with det C. On the
// bench's seating LCPs the values' denominators are 1–95 bits while the
// factored block's common denominator D·δ is 130–420 bits
// (docs/theory.md §6).
#include <cstdint>
#include <vector>

#include "fixel/rational.h"

namespace fixel::internal {

// The primes p the lifting works modulo, in the order tried (the next one
// when C is singular modulo the last); exposed for tests.
const std::vector<std::uint64_t>& dixon_primes();

// Enclosures lo_j ≤ x_j ≤ hi_j of the solution, in doubles, when the caller
// has them (the filtered run's interval tableau does). Only a hint: it
// decides when reconstruction is tried and which candidates reach the
// exact check, never what is returned. A wrong hint can make dixon_solve
// decline, never answer wrongly.
struct DixonHint {
  std::vector<double> lo, hi;
};

// What one dixon_solve did, for tests and benchmarks.
struct DixonTrace {
  int steps = 0;       // lifting steps made with the prime that answered
  int attempts = 0;    // reconstructions tried (each a rational reconstruction or more)
  bool words = false;  // whether the lifting ran in machine words (small entries) rather than GMP
  // Factors the combination's denominator d lacked, for some x_j, in the
  // attempt that answered: found by trial of 2..16 against the hint, or by
  // a reconstruction of d·x_j.
  int factors_by_trial = 0, factors_by_reconstruction = 0;
  // Unknowns that short rows fixed before lifting (internal/lemke_dixon_sparse.h).
  int unknowns_eliminated = 0;
};

// Test switch: with `on` false, dixon_solve lifts with GMP even when the
// system's entries are small enough for machine words (the default path),
// and dixon_basic_values sums the w numerators with GMP too.
void set_dixon_words_allowed(bool on);
bool dixon_words_allowed();

// Test and benchmark switch: with `on` false, dixon_solve lifts the whole
// system even when it has rows with y_a = 0 and one or two nonzero entries,
// which it otherwise eliminates first (internal/lemke_dixon_sparse.h).
void set_dixon_sparse_rows_allowed(bool on);

// The acceptance test of dixon_solve, exposed for tests: whether
// C·u = d·y, for u and d of which C·u ≡ d·y (mod modulus) is known.
// With an odd modulus M it checks C·u − d·y ≡ 0 mod 2^128 in machine
// words, which with that congruence and |C·u − d·y| < M·2^128 (shown from
// the operands' sizes) proves equality; when the sizes do not show it,
// the exact products decide (docs/theory.md §6). Without the congruence
// its answer means nothing.
bool dixon_accepts(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y,
                   const std::vector<Integer>& u, const Integer& d, const Integer& modulus);

// Solves C x = y for the k×k integer matrix C (c[a·k + j] = C(a, j)) and
// the integer vector y, as x = u/d with one common denominator d > 0.
// True only when C·u = d·y holds exactly (proved before returning: on
// C′·u′ = d·y′ when short rows were eliminated first, which gives it for C,
// docs/theory.md §6 step 0). False
// when C is singular, or singular modulo every prime tried, or no
// reconstruction passed that check within the lifting steps that
// Hadamard's bound says suffice: the caller then solves another way.
// The pointers must stay valid during the call. `hint` (k enclosures, or
// null) lets reconstruction start earlier: after the first step, then
// from the third on (docs/theory.md §6). `c_words`, when given, is C
// as words already (row-major, each |C(a, j)| < 2^59, equal to c's): a
// prepared matrix's block (ScaledProblem::word), not converted again.
// With it c may be empty; then false also when y is beyond words
// (rhs_in_words) or words are switched off, as the GMP path needs c.
bool dixon_solve(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y,
                 std::vector<Integer>& u, Integer& d, const DixonHint* hint = nullptr, DixonTrace* trace = nullptr,
                 const std::vector<std::int64_t>* c_words = nullptr);

}  // namespace fixel::internal
