#pragma once
// The filtered Lemke run's exact side (src/lemke_exact.cpp): the final
// basic values and their checks, and the tableau at one basis in integers
// for the decisions the intervals leave open (docs/theory.md §6).
#include <gmp.h>

#include <cstddef>
#include <vector>

#include "fixel/internal/lemke_dixon.h"
#include "fixel/internal/lemke_scaled.h"
#include "fixel/rational.h"

namespace fixel::internal {

// Exact basic values at a basis β: row t holds num_t/den, or
// num_t/(den·L_i) when its basic variable is w_i; den > 0.
struct BasicValues {
  std::vector<Integer> num;
  Integer den;

  void normalize_sign() {
    if (mpz_sgn(mp(den)) >= 0) return;
    mpz_neg(mp(den), mp(den));
    for (auto& x : num) mpz_neg(mp(x), mp(x));
  }
};

// Whether `basis` is complementary without z0 and every value is ≥ 0 (the
// checks of solves_lcp_at_basis before its equations); row_of gets the row
// of each basic variable (−1 for a nonbasic one).
bool complementary_and_nonnegative(int n, const std::vector<int>& basis, const BasicValues& values,
                                   std::vector<int>& row_of);

// Whether `values` solve the LCP at the complementary basis β: z0 is not
// basic, no variable is basic with its complement, every value is ≥ 0 and
// every equation of the scaled problem holds exactly. With den·x the
// integers of BasicValues and b's column scaled by δ, equation i reads
//   δ·([w_i basic] num + Σ_{z_j basic} A(i, z_j)·num) = den·b_i.
// This checks the elimination that produced the values, row by row, with
// one product per basic z and no gcd.
bool solves_lcp_at_basis(const ScaledProblem& P, const std::vector<int>& basis, const BasicValues& values);

// The same check from B and b, exposed for tests: whether the basic values
// x_t = num_t/den (num_t/(den·L_i) when basis[t] is w_i, with L_i the lcm
// of the denominators of B's row i) solve LCP(B, b) at the complementary
// basis `basis` (0..n−1 w, n..2n−1 z, 2n z0), exactly.
bool solves_lcp_at_basis(const MatrixQ& B, const VectorQ& b, const std::vector<int>& basis,
                         const std::vector<Integer>& num, const Integer& den);

// The basic values at the complementary basis β (z0 not basic), in the
// form of ExactTableau::basic_values, with the basis block solved by
// dixon_solve: its common denominator is about the values' own (3–79 bits
// on the bench's seating LCPs) instead of D·δ (130–420 bits), so every
// later step works on smaller integers. False when dixon_solve declines.
// The values it returns satisfy every equation exactly, by construction:
// the block's rows because dixon_solve accepts only u with C·u = d·y in
// integers, each basic w's row because that row defines its value. So
// only the signs and the basis are left to check (the caller's).
// [rhs_lo_t, rhs_hi_t] encloses the basic value of tableau row t (the
// interval tableau's b column): dixon_solve's hint, once scaled by δ.
// `trace` gets what the lifting did.
bool dixon_basic_values(const ScaledProblem& P, const std::vector<int>& basis, const std::vector<double>& rhs_lo,
                        const std::vector<double>& rhs_hi, BasicValues& out, DixonTrace& trace);

// The exact tableau A_β⁻¹ [A | b] at one basis β, A = [I, −B, −e], column by
// column on demand, in integers. Rows whose basic variable is some w_i solve
// trivially, so only the k×k block C of the basic z's (and z0) on the other
// equations is factored, k being at most the pivots made so far (early ties
// are cheap). C is reduced by fraction-free (Bareiss) elimination, whose
// divisions are exact; its last pivot D = ±det C. Entry (t, col) is then
// N_t / σ_t with N_t an integer and σ_t = D (rows of z's) or D·L_i (the row
// of w_i): no gcd until a value is needed. Its storage is reused from basis
// to basis and from run to run.
class ExactTableau {
 public:
  // Factors the block at `basis` (P must outlive the columns' use).
  void assign(const ScaledProblem& P, const std::vector<int>& basis);

  // Numerators N_t of column `col` (n of them from `data`); the value of
  // entry t is N_t / σ_t.
  const Integer* column(int col);

  // Sign of entry (t, col).
  int entry_sign(int t, int col) { return mpz_sgn(mp(column(col)[t])) * mpz_sgn(mp(D_)); }

  // Sign of T(i, col)·T(j, s) − T(j, col)·T(i, s): σ_i σ_j > 0 cancels.
  int cross_sign(int i, int j, int col, int s);

  bool has_column(int col) const { return have_[col]; }

  // The basic values at this basis: row t holds num_t/den, or
  // num_t/(den·L_i) for the row of w_i (rhs's column computed or not);
  // den = D·δ, b's column being scaled by δ.
  void basic_values(int rhs, BasicValues& out);

  // The basic values at the basis that pivoting on (r, col) reaches, in the
  // form of basic_values, from this basis's columns `rhs` and `col` (both
  // computed already): with S = column(col), row r becomes N_r/S_r and row
  // t ≠ r (N_t·S_r − N_r·S_t)/(σ_t·S_r), so den = D·S_r·δ. False if S_r = 0.
  // This spares factoring the next basis for the final values.
  bool basic_values_after_pivot(int r, int col, int rhs, BasicValues& out);

 private:
  static void grow(std::vector<Integer>& v, std::size_t size);
  Integer& u(int a, int c) { return U_[static_cast<std::size_t>(a) * n_ + c]; }
  Integer& multiplier(int a, int c) { return multipliers_[static_cast<std::size_t>(a) * n_ + c]; }

  // x ← (p·x − m·y)/D, exact (Bareiss), with m = nullptr meaning m = 0;
  // the sparse seating blocks make many of these products zero, so they
  // are skipped, and D = 1 (the first step) divides nothing.
  void bareiss_step(Integer& x, const Integer& p, const Integer* m, const Integer& y, const Integer& D);

  void eliminate();

  const ScaledProblem* P_ = nullptr;
  std::vector<int> basis_;
  int n_ = 0;
  std::vector<int> R_;                    // equations whose w is nonbasic
  std::vector<int> K_;                    // tableau rows whose basic variable is a z or z0
  std::vector<Integer> U_, multipliers_;  // k×k, stride n
  std::vector<int> swaps_;
  std::vector<Integer> previous_, y_, N_;
  Integer D_, t_, t2_;
  std::vector<Integer> columns_;  // column col at [col·n, col·n + n)
  std::vector<bool> have_;
};

}  // namespace fixel::internal
