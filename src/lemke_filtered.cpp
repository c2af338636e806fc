#include "fixel/internal/lemke_filtered.h"

#include <atomic>
#include <boost/container/small_vector.hpp>
#include <limits>
#include <vector>

#include "fixel/error.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/lemke_dixon.h"
#include "fixel/internal/lemke_scaled.h"
#include "fixel/internal/lemke_tie.h"

namespace fixel::internal {

namespace {

std::atomic<long> g_dixon_values{0}, g_factored_values{0}, g_lifting_steps{0}, g_reconstructions{0};
std::atomic<long> g_z0_settled{0}, g_z0_reruns{0};
std::atomic<bool> g_defer_every_z0_comparison{false};

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

// Whether `values` solve the LCP at the complementary basis β: z0 is not
// basic, no variable is basic with its complement, every value is ≥ 0 and
// every equation of the scaled problem holds exactly. With den·x the
// integers of BasicValues and b's column scaled by δ, equation i reads
//   δ·([w_i basic] num + Σ_{z_j basic} A(i, z_j)·num) = den·b_i.
// This checks the elimination that produced the values, row by row, with
// one product per basic z and no gcd.
// The checks of solves_lcp_at_basis before its equations: `basis` is
// complementary without z0, and every value is ≥ 0. row_of gets the row of
// each basic variable (−1 for a nonbasic one).
bool complementary_and_nonnegative(int n, const std::vector<int>& basis, const BasicValues& values,
                                   std::vector<int>& row_of) {
  row_of.assign(2 * n + 1, -1);
  for (int t = 0; t < n; ++t) {
    const int v = basis[t];
    if (v < 0 || v >= 2 * n || row_of[v] >= 0) return false;  // z0 basic, or not a basis
    row_of[v] = t;
  }
  for (int i = 0; i < n; ++i)
    if (row_of[i] >= 0 && row_of[n + i] >= 0) return false;  // w_i and z_i both basic
  for (int t = 0; t < n; ++t)
    if (mpz_sgn(mp(values.num[t])) < 0) return false;
  return true;
}

bool solves_lcp_at_basis(const ScaledProblem& P, const std::vector<int>& basis, const BasicValues& values) {
  const int n = P.n();
  thread_local std::vector<int> row_of;
  if (!complementary_and_nonnegative(n, basis, values, row_of)) return false;
  thread_local Integer sum, rhs;
  for (int i = 0; i < n; ++i) {
    if (row_of[i] >= 0)
      mpz_set(mp(sum), mp(values.num[row_of[i]]));
    else
      mpz_set_ui(mp(sum), 0);
    for (int j = 0; j < n; ++j) {
      const int t = row_of[n + j];
      if (t >= 0) mpz_addmul(mp(sum), mp(P.entry(i, n + j)), mp(values.num[t]));
    }
    mpz_mul(mp(sum), mp(sum), mp(P.rhs_factor()));
    mpz_mul(mp(rhs), mp(values.den), mp(P.entry(i, 2 * n + 1)));
    if (mpz_cmp(mp(sum), mp(rhs)) != 0) return false;
  }
  return true;
}

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
  void assign(const ScaledProblem& P, const std::vector<int>& basis) {
    P_ = &P;
    basis_ = basis;
    n_ = P.n();
    std::vector<bool> w_basic(n_, false);
    K_.clear();
    R_.clear();
    for (int t = 0; t < n_; ++t) {
      if (basis_[t] < n_)
        w_basic[basis_[t]] = true;
      else
        K_.push_back(t);
    }
    for (int i = 0; i < n_; ++i)
      if (!w_basic[i]) R_.push_back(i);
    const int k = static_cast<int>(K_.size());
    if (static_cast<int>(R_.size()) != k) throw InternalError("filtered Lemke: the basis is not a basis");
    grow(U_, static_cast<std::size_t>(n_) * n_);
    grow(multipliers_, static_cast<std::size_t>(n_) * n_);
    grow(previous_, n_);
    grow(y_, n_);
    grow(N_, n_);
    grow(columns_, static_cast<std::size_t>(2 * n_ + 2) * n_);
    have_.assign(2 * n_ + 2, false);
    for (int a = 0; a < k; ++a)
      for (int c = 0; c < k; ++c) mpz_set(mp(u(a, c)), mp(P.entry(R_[a], basis_[K_[c]])));
    eliminate();
  }

  // Numerators N_t of column `col` (n of them from `data`); the value of
  // entry t is N_t / σ_t.
  const Integer* column(int col) {
    Integer* x = &columns_[static_cast<std::size_t>(col) * n_];
    if (have_[col]) return x;
    const int k = static_cast<int>(K_.size());
    for (int a = 0; a < k; ++a) mpz_set(mp(y_[a]), mp(P_->entry(R_[a], col)));
    // The stored elimination steps, then fraction-free back substitution:
    // N_r = (D·y_r − Σ_{j>r} U_rj N_j) / U_rr (exact: D·x is an integer by Cramer).
    for (int c = 0; c < k; ++c) {
      if (swaps_[c] != c) mpz_swap(mp(y_[c]), mp(y_[swaps_[c]]));
      for (int r = c + 1; r < k; ++r) {
        const bool eliminates = mpz_sgn(mp(multiplier(r, c))) != 0;
        bareiss_step(y_[r], u(c, c), eliminates ? &multiplier(r, c) : nullptr, y_[c], previous_[c]);
      }
    }
    for (int r = k; r-- > 0;) {
      mpz_mul(mp(t_), mp(D_), mp(y_[r]));
      for (int j = r + 1; j < k; ++j)
        if (mpz_sgn(mp(u(r, j))) != 0) mpz_submul(mp(t_), mp(u(r, j)), mp(N_[j]));
      mpz_divexact(mp(N_[r]), mp(t_), mp(u(r, r)));
    }
    for (int c = 0; c < k; ++c) mpz_set(mp(x[K_[c]]), mp(N_[c]));
    for (int t = 0; t < n_; ++t) {
      if (basis_[t] >= n_) continue;
      // w_i = (v_i − A(i, K)·x_K), scaled by L_i·D.
      const int i = basis_[t];
      mpz_mul(mp(x[t]), mp(D_), mp(P_->entry(i, col)));
      for (int c = 0; c < k; ++c)
        if (mpz_sgn(mp(N_[c])) != 0) mpz_submul(mp(x[t]), mp(P_->entry(i, basis_[K_[c]])), mp(N_[c]));
    }
    have_[col] = true;
    return x;
  }

  // Sign of entry (t, col).
  int entry_sign(int t, int col) { return mpz_sgn(mp(column(col)[t])) * mpz_sgn(mp(D_)); }

  // Sign of T(i, col)·T(j, s) − T(j, col)·T(i, s): σ_i σ_j > 0 cancels.
  int cross_sign(int i, int j, int col, int s) {
    const Integer* c = column(col);
    const Integer* x = column(s);
    mpz_mul(mp(t_), mp(c[i]), mp(x[j]));
    mpz_mul(mp(t2_), mp(c[j]), mp(x[i]));
    const int cmp = mpz_cmp(mp(t_), mp(t2_));
    return (cmp > 0) - (cmp < 0);
  }

  bool has_column(int col) const { return have_[col]; }

  // The basic values at this basis: row t holds num_t/den, or
  // num_t/(den·L_i) for the row of w_i (rhs's column computed or not);
  // den = D·δ, b's column being scaled by δ.
  void basic_values(int rhs, BasicValues& out) {
    const Integer* N = column(rhs);
    out.num.resize(n_);
    for (int t = 0; t < n_; ++t) mpz_set(mp(out.num[t]), mp(N[t]));
    mpz_mul(mp(out.den), mp(D_), mp(P_->rhs_factor()));
    out.normalize_sign();
  }

  // The basic values at the basis that pivoting on (r, col) reaches, in the
  // form of basic_values, from this basis's columns `rhs` and `col` (both
  // computed already): with S = column(col), row r becomes N_r/S_r and row
  // t ≠ r (N_t·S_r − N_r·S_t)/(σ_t·S_r), so den = D·S_r·δ. False if S_r = 0.
  // This spares factoring the next basis for the final values.
  bool basic_values_after_pivot(int r, int col, int rhs, BasicValues& out) {
    const Integer* N = column(rhs);
    const Integer* S = column(col);
    if (mpz_sgn(mp(S[r])) == 0) return false;
    out.num.resize(n_);
    for (int t = 0; t < n_; ++t) {
      if (t == r) continue;
      mpz_mul(mp(out.num[t]), mp(N[t]), mp(S[r]));
      mpz_submul(mp(out.num[t]), mp(N[r]), mp(S[t]));
    }
    // Row r: N_r/S_r = num_r/den with den = D·S_r·δ (times L_i when col is w_i).
    mpz_mul(mp(out.num[r]), mp(N[r]), mp(D_));
    if (col < n_) mpz_mul(mp(out.num[r]), mp(out.num[r]), mp(P_->scale(col)));
    mpz_mul(mp(out.den), mp(D_), mp(S[r]));
    mpz_mul(mp(out.den), mp(out.den), mp(P_->rhs_factor()));
    out.normalize_sign();
    return true;
  }

 private:
  static void grow(std::vector<Integer>& v, std::size_t size) {
    if (v.size() < size) v.resize(size);
  }
  Integer& u(int a, int c) { return U_[static_cast<std::size_t>(a) * n_ + c]; }
  Integer& multiplier(int a, int c) { return multipliers_[static_cast<std::size_t>(a) * n_ + c]; }

  // x ← (p·x − m·y)/D, exact (Bareiss), with m = nullptr meaning m = 0;
  // the sparse seating blocks make many of these products zero, so they
  // are skipped, and D = 1 (the first step) divides nothing.
  void bareiss_step(Integer& x, const Integer& p, const Integer* m, const Integer& y, const Integer& D) {
    const bool x_zero = mpz_sgn(mp(x)) == 0, my_zero = m == nullptr || mpz_sgn(mp(y)) == 0;
    if (x_zero && my_zero) return;  // stays 0
    if (x_zero) {
      mpz_mul(mp(t_), mp(*m), mp(y));
      mpz_neg(mp(t_), mp(t_));
    } else {
      mpz_mul(mp(t_), mp(p), mp(x));
      if (!my_zero) mpz_submul(mp(t_), mp(*m), mp(y));
    }
    if (mpz_cmp_ui(mp(D), 1) == 0)
      mpz_swap(mp(x), mp(t_));
    else
      mpz_divexact(mp(x), mp(t_), mp(D));
  }

  void eliminate() {
    const int k = static_cast<int>(K_.size());
    swaps_.assign(k, 0);
    mpz_set_ui(mp(D_), 1);  // the previous pivot, 1 before the first
    for (int c = 0; c < k; ++c) {
      int p = c;
      while (p < k && mpz_sgn(mp(u(p, c))) == 0) ++p;
      if (p == k) throw InternalError("filtered Lemke: the basis is singular");
      if (p != c)
        for (int j = 0; j < k; ++j) mpz_swap(mp(u(p, j)), mp(u(c, j)));
      swaps_[c] = p;
      mpz_set(mp(previous_[c]), mp(D_));
      for (int r = c + 1; r < k; ++r) {
        mpz_set(mp(multiplier(r, c)), mp(u(r, c)));
        const bool eliminates = mpz_sgn(mp(u(r, c))) != 0;
        for (int j = c + 1; j < k; ++j) bareiss_step(u(r, j), u(c, c), eliminates ? &u(r, c) : nullptr, u(c, j), D_);
        mpz_set_ui(mp(u(r, c)), 0);
      }
      mpz_set(mp(D_), mp(u(c, c)));
    }
  }

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
bool dixon_basic_values(const ScaledProblem& P, const std::vector<int>& basis, const std::vector<double>& rhs_lo,
                        const std::vector<double>& rhs_hi, BasicValues& out) {
  const int n = P.n();
  thread_local std::vector<int> rows, block_rows;
  thread_local std::vector<const Integer*> block, rhs;
  thread_local std::vector<Integer> u;
  thread_local Integer d;
  thread_local std::vector<char> w_basic;
  w_basic.assign(n, 0);
  block_rows.clear();  // tableau rows whose basic variable is a z
  for (int t = 0; t < n; ++t) {
    if (basis[t] >= 2 * n) return false;  // z0 basic: not a final basis
    if (basis[t] < n)
      w_basic[basis[t]] = 1;
    else
      block_rows.push_back(t);
  }
  rows.clear();  // equations whose w is not basic
  for (int i = 0; i < n; ++i)
    if (!w_basic[i]) rows.push_back(i);
  const int k = static_cast<int>(block_rows.size());
  if (static_cast<int>(rows.size()) != k) return false;
  block.resize(static_cast<std::size_t>(k) * k);
  rhs.resize(k);
  for (int a = 0; a < k; ++a) {
    for (int c = 0; c < k; ++c) block[static_cast<std::size_t>(a) * k + c] = &P.entry(rows[a], basis[block_rows[c]]);
    rhs[a] = &P.entry(rows[a], 2 * n + 1);
  }
  // The block's unknowns are δ times the basic z's.
  thread_local DixonHint hint;
  const double delta = mpz_get_d(mp(P.rhs_factor()));
  hint.lo.resize(k);
  hint.hi.resize(k);
  for (int c = 0; c < k; ++c) {
    hint.lo[c] = rhs_lo[block_rows[c]] * delta;
    hint.hi[c] = rhs_hi[block_rows[c]] * delta;
  }
  DixonTrace trace;
  const bool solved = dixon_solve(k, block, rhs, u, d, &hint, &trace);
  g_lifting_steps += trace.steps;
  g_reconstructions += trace.attempts;
  if (!solved) return false;
  out.num.resize(n);
  for (int c = 0; c < k; ++c) mpz_set(mp(out.num[block_rows[c]]), mp(u[c]));
  for (int t = 0; t < n; ++t) {
    if (basis[t] >= n) continue;
    // L_i·δ·d·w_i = d·(L_i δ b_i) − Σ_c A(i, β_c)·u_c.
    const int i = basis[t];
    mpz_mul(mp(out.num[t]), mp(d), mp(P.entry(i, 2 * n + 1)));
    for (int c = 0; c < k; ++c)
      if (mpz_sgn(mp(u[c])) != 0) mpz_submul(mp(out.num[t]), mp(P.entry(i, basis[block_rows[c]])), mp(u[c]));
  }
  mpz_mul(mp(out.den), mp(d), mp(P.rhs_factor()));
  return true;
}

// The exact side's storage, kept per thread so that GMP limbs are reused.
struct ExactWorkspace {
  ScaledProblem problem;
  ExactTableau tableau;
  BasicValues final_values;
  TieCertifier ties;
  std::vector<int> tie_basis;
};

ExactWorkspace& exact_workspace() {
  thread_local ExactWorkspace workspace;
  return workspace;
}

// The same tableau in intervals (Gauss–Jordan on [I, −B, −e | b]): every
// entry encloses the exact tableau's. It is the integer tableau of
// src/lemke.cpp up to positive row and column scalings, which change no
// ratio-test decision. Only the n + 1 nonbasic columns and b are stored: a
// basic variable's column is a unit vector, and the leaving variable's
// column takes over the entering one's storage. Needs a Protect scope.
class IntervalTableau {
 public:
  IntervalTableau(const MatrixQ& B, const VectorQ& b) : n_(static_cast<int>(b.size())), width_(n_ + 2) {
    T_.assign(static_cast<std::size_t>(n_) * width_, FI(0));
    basis_.resize(n_);
    slot_.assign(2 * n_ + 2, -1);
    stamp_.assign(width_, 0);
    forget_pivots();
    // Slots: z_j at j, z0 at n, b at n + 1; the w's are basic.
    for (int j = 0; j <= n_; ++j) slot_[n_ + j] = j;
    slot_[rhs()] = n_ + 1;
    for (int i = 0; i < n_; ++i) {
      for (int j = 0; j < n_; ++j)
        if (mpq_sgn(B(i, j).backend().data()) != 0) at_slot(i, j) = -enclosure(B(i, j));  // no Rational(0) temporary
      at_slot(i, n_) = FI(-1);
      at_slot(i, n_ + 1) = enclosure(b[i]);
      basis_[i] = i;
    }
    initial_.resize(T_.size());
    for (std::size_t k = 0; k < T_.size(); ++k) initial_[k] = T_[k].inf();  // width_ = n + 2: ApproxProblem's layout
  }

  // Doubles near the first tableau's entries, for guesses only.
  ApproxProblem approx() const { return {initial_.data(), n_}; }

  int z0() const { return 2 * n_; }
  int rhs() const { return 2 * n_ + 1; }
  int basic(int row) const { return basis_[row]; }
  const std::vector<int>& basis() const { return basis_; }
  int complement(int var) const { return var < n_ ? var + n_ : var - n_; }

  // Entry (i, var): a unit-vector entry for a basic variable.
  FI at(int i, int var) {
    const int k = slot_[var];
    if (k < 0) return FI(basis_[i] == var ? 1 : 0);
    bring_up_to_date(k);
    return at_slot(i, k);
  }

  // Pivot on (r, s), s nonbasic; needs a pivot interval that excludes zero.
  // The leaving variable's column, e_r before, becomes (−T(i, s)/p)_i with
  // 1/p in row r, and is stored in s's slot. The other columns are updated
  // when they are next read (bring_up_to_date) or at the flush after 2n
  // pivots: the path reads b's column and the entering one, and others only
  // for a lexicographic tie-break.
  void pivot(int r, int s) {
    const int ks = slot_[s];
    bring_up_to_date(ks);
    const int leaving = basis_[r];
    eta_.resize(static_cast<std::size_t>(pivots_ + 1) * n_);
    eta_support_start_.push_back(static_cast<int>(eta_support_.size()));
    for (int i = 0; i < n_; ++i) {
      const FI f = at_slot(i, ks);
      eta_[static_cast<std::size_t>(pivots_) * n_ + i] = f;
      if (i != r && !(f.inf() == 0 && f.sup() == 0)) eta_support_.push_back(i);
    }
    eta_row_.push_back(r);
    const FI inverse = FI(1) / at_slot(r, ks);
    eta_inverse_.push_back(inverse);
    at_slot(r, ks) = inverse;
    for (int i = 0; i < n_; ++i) {
      if (i == r) continue;
      const FI f = at_slot(i, ks);
      if (f.inf() == 0 && f.sup() == 0) continue;  // an exact zero stays exact
      at_slot(i, ks) = -f * inverse;
    }
    stamp_[ks] = ++pivots_;
    basis_[r] = s;
    slot_[leaving] = ks;
    slot_[s] = -1;
    if (pivots_ >= 2 * n_) flush();  // bounds the pivots kept, and the work, by the eager update's
  }

 private:
  FI& at_slot(int i, int k) { return T_[static_cast<std::size_t>(i) * width_ + k]; }

  void forget_pivots() {
    eta_.clear();
    eta_row_.clear();
    eta_inverse_.clear();
    eta_support_.clear();
    eta_support_start_.clear();
  }

  // Applies the pivots made since slot k was last read, in order, with the
  // operations of a Gauss–Jordan step on that column (row r times the
  // pivot's reciprocal, the interval the pivot column got, then row i less
  // T(i, s)·(new row r) for the rows where T(i, s) is not an exact zero),
  // so its enclosures are bit for bit those of an eager update.
  void bring_up_to_date(int k) {
    for (int t = stamp_[k]; t < pivots_; ++t) {
      const FI* f = &eta_[static_cast<std::size_t>(t) * n_];
      const int r = eta_row_[t];
      const FI x = at_slot(r, k) * eta_inverse_[t];
      at_slot(r, k) = x;
      if (x.inf() == 0 && x.sup() == 0) continue;
      const int end = t + 1 < pivots_ ? eta_support_start_[t + 1] : static_cast<int>(eta_support_.size());
      for (int e = eta_support_start_[t]; e < end; ++e) {
        const int i = eta_support_[e];
        at_slot(i, k) -= f[i] * x;
      }
    }
    stamp_[k] = pivots_;
  }

  // Brings every column up to date and forgets the pivots.
  void flush() {
    for (int k = 0; k < width_; ++k) bring_up_to_date(k);
    forget_pivots();
    pivots_ = 0;
    stamp_.assign(width_, 0);
  }

  // q in an interval: when numerator and denominator are exact doubles, one
  // interval division (outward rounded), else the shared conversion.
  static FI enclosure(const Rational& q) {
    const auto* m = q.backend().data();
    const mpz_srcptr num = mpq_numref(m), den = mpq_denref(m);
    constexpr mp_limb_t kExact = mp_limb_t(1) << 53;
    if (mpz_size(num) <= 1 && mpz_size(den) == 1 && mpz_getlimbn(num, 0) < kExact && mpz_getlimbn(den, 0) < kExact) {
      const double n = static_cast<double>(mpz_getlimbn(num, 0));
      const FI quotient = FI(n) / FI(static_cast<double>(mpz_getlimbn(den, 0)));
      return mpz_sgn(num) < 0 ? -quotient : quotient;
    }
    return to_interval(q);
  }

  // The vectors' storage, reused from run to run (one per thread; a run
  // does not nest another).
  struct Storage {
    std::vector<FI> T, eta, eta_inverse;
    std::vector<double> initial;
    std::vector<int> basis, slot, stamp, eta_row, eta_support, eta_support_start;
  };
  static Storage& storage() {
    thread_local Storage s;
    return s;
  }

  int n_, width_;
  Storage& storage_ = storage();
  std::vector<FI>& T_ = storage_.T;                      // row-major, width_ slots per row
  std::vector<double>& initial_ = storage_.initial;      // the first tableau's slots, approximately
  std::vector<int>& basis_ = storage_.basis;             // basic variable of each row
  std::vector<int>& slot_ = storage_.slot;               // storage slot of each nonbasic variable (and b), else −1
  std::vector<int>& stamp_ = storage_.stamp;             // per slot: how many pivots its column has seen
  std::vector<FI>& eta_ = storage_.eta;                  // per pivot: the entering column before it (n entries)
  std::vector<int>& eta_row_ = storage_.eta_row;         // per pivot: its row
  std::vector<FI>& eta_inverse_ = storage_.eta_inverse;  // per pivot: 1/p, p its pivot
  // Per pivot t, from eta_support_start_[t]: the rows i ≠ r whose T(i, s)
  // is not an exact zero, the only rows its update changes.
  std::vector<int>& eta_support_ = storage_.eta_support;
  std::vector<int>& eta_support_start_ = storage_.eta_support_start;
  int pivots_ = 0;
};

// One filtered run: each decision of the exact run (src/lemke.cpp) is taken
// from the intervals when they certify it, else from the exact tableau at the
// current basis (built lazily, dropped at each pivot). So the pivots, and the
// final basis, are the exact run's.
//
// One decision may be settled later instead: the z0 row against another row
// in a ratio test when the intervals cannot order their ratios. The z0 row
// wins ties, so "the z0 row wins" is right iff no candidate's ratio is
// below the z0 row's, iff every basic value after pivoting on it is ≥ 0;
// and that pivot is the last. So with `settle_z0_by_values` the run takes
// the z0 row, finds the final values exactly as always, and their exact
// signs settle the decision (docs/theory.md §6). A negative value means it
// was wrong: settlement_failed() says so and the caller runs again
// without settling (the decision is then proved or made exactly).
class FilteredRun {
 public:
  FilteredRun(const MatrixQ& B, const VectorQ& b, bool settle_z0_by_values = false)
      : B_(B), b_(b), n_(static_cast<int>(b.size())), T_(B, b), settle_z0_(settle_z0_by_values) {}
  ~FilteredRun() {
    record_filter(FilterSite::kLemke, certified_, exact_);
    record_filter(FilterSite::kLemkeTie, ties_proved_, ties_unproved_);
  }

  // Whether the last run's values showed a z0-row decision wrong: `result`
  // is then not set, and the run must be repeated without settling.
  bool settlement_failed() const { return settlement_failed_; }

  // With `values` false (filtered_lemke_path) the run stops at the final
  // basis: no exact values, w and z left empty.
  bool run(int max_pivots, LemkeResult& result, bool values = true) {
    // z0 enters; the row with the most negative b leaves, ties to the larger index.
    int r = 0;
    for (int i = 1; i < n_; ++i) {
      int c = certain_sign(T_.at(i, T_.rhs()) - T_.at(r, T_.rhs()));
      if (c == kUndecided) {
        c = fixel::sign(b_[i] - b_[r]);
        ++exact_;
      } else {
        ++certified_;
      }
      if (c <= 0) r = i;
    }
    int entering = T_.complement(T_.basic(r));
    if (!pivot(r, T_.z0())) return false;
    int pivots = 1;
    LemkeStatus status = LemkeStatus::kSolved;
    while (true) {
      if (pivots >= max_pivots) {
        status = LemkeStatus::kPivotLimit;
        break;
      }
      r = ratio_test(entering);
      if (r < 0) {
        status = LemkeStatus::kRayTermination;
        break;
      }
      final_settles_ = z0_taken_unordered_;  // then r is the z0 row: the last pivot
      const int leaving = T_.basic(r);
      // The last pivot: when this basis's exact columns are at hand (the z0
      // row usually wins a tie), the final values follow from them.
      if (leaving == T_.z0() && tableau_current_) {
        ExactTableau& E = exact_workspace().tableau;
        if (E.has_column(T_.rhs()) && E.has_column(entering))
          final_ready_ = E.basic_values_after_pivot(r, entering, T_.rhs(), final_);
      }
      if (!pivot(r, entering)) return false;
      ++pivots;
      if (leaving == T_.z0()) break;
      entering = T_.complement(leaving);
    }
    if (status == LemkeStatus::kSolved && values) {
      // Dixon's values first (their equations hold by construction, so only
      // signs and basis are checked); the factored block when lifting
      // declines, with the full check.
      bool equations_hold = false;
      if (!final_ready_) {
        thread_local std::vector<double> rhs_lo, rhs_hi;
        rhs_lo.resize(n_);
        rhs_hi.resize(n_);
        for (int t = 0; t < n_; ++t) {
          const FI x = T_.at(t, T_.rhs());
          rhs_lo[t] = x.inf();
          rhs_hi[t] = x.sup();
        }
        equations_hold = dixon_basic_values(problem(), T_.basis(), rhs_lo, rhs_hi, final_);
        ++(equations_hold ? g_dixon_values : g_factored_values);
        if (!equations_hold) exact().basic_values(T_.rhs(), final_);
      }
      thread_local std::vector<int> row_of;
      const bool solves = equations_hold ? complementary_and_nonnegative(n_, T_.basis(), final_, row_of)
                                         : solves_lcp_at_basis(exact_workspace().problem, T_.basis(), final_);
      if (final_settles_) ++(solves ? g_z0_settled : g_z0_reruns);
      if (!solves) {
        if (final_settles_) {  // a negative value: the z0 row should not have won
          settlement_failed_ = true;
          return true;
        }
        // Never report a wrong "solved" (the exact path uses is_solution).
        throw InternalError("solve_lcp_lemke: the filtered run's final values fail the exact check of the equations");
      }
    }
    result = LemkeResult{};
    result.status = status;
    result.pivots = pivots;
    if (status == LemkeStatus::kSolved && values) {
      result.w.resize(n_);
      result.z.resize(n_);
      for (int t = 0; t < n_; ++t) {
        const int v = T_.basic(t);
        auto* q = (v < n_ ? result.w[v] : result.z[v - n_]).backend().data();
        mpz_set(mpq_numref(q), mp(final_.num[t]));
        mpz_set(mpq_denref(q), mp(final_.den));
        if (v < n_) mpz_mul(mpq_denref(q), mpq_denref(q), mp(exact_workspace().problem.scale(v)));
        mpq_canonicalize(q);
      }
    }
    return true;
  }

  // The basic variable of each tableau row.
  const std::vector<int>& basis() const { return T_.basis(); }

 private:
  ExactTableau& exact() {
    ExactWorkspace& ws = exact_workspace();
    if (!tableau_current_) {
      ws.tableau.assign(problem(), T_.basis());
      tableau_current_ = true;
    }
    return ws.tableau;
  }

  bool pivot(int r, int s) {
    if (certain_sign(T_.at(r, s)) == kUndecided) return false;  // the division would lose everything
    T_.pivot(r, s);
    tableau_current_ = false;
    return true;
  }

  // Sign of T(i, col)·T(j, s) − T(j, col)·T(i, s): the ratio T(i, col)/T(i, s)
  // against T(j, col)/T(j, s) when both T(·, s) > 0.
  int compare_ratio(int i, int j, int col, int s) {
    const int c = certain_sign(T_.at(i, col) * T_.at(j, s) - T_.at(j, col) * T_.at(i, s));
    if (c != kUndecided) return ++certified_, c;
    if (certified_tie(i, j, col, s)) return ++certified_, 0;  // no fallback ran
    ++exact_;
    return exact().cross_sign(i, j, col, s);
  }

  const ScaledProblem& problem() {
    ExactWorkspace& ws = exact_workspace();
    if (!scaled_) {
      ws.problem.assign(B_, b_);
      scaled_ = true;
    }
    return ws.problem;
  }

  // Whether T(i, col)·T(j, s) − T(j, col)·T(i, s) = 0, proved exactly
  // (internal/lemke_tie.h): that 2×2 minor of the tableau is
  // det A_β' / det A_β, β' being β with row i's basic variable replaced by
  // col and row j's by s.
  bool certified_tie(int i, int j, int col, int s) {
    ExactWorkspace& ws = exact_workspace();
    ws.tie_basis = T_.basis();
    ws.tie_basis[i] = col;
    ws.tie_basis[j] = s;
    const bool proved = ws.ties.singular(ws.tie_basis, T_.approx(), problem());
    ++(proved ? ties_proved_ : ties_unproved_);
    return proved;
  }

  // The lexicographic minimum ratio test of Tableau::ratio_test in
  // src/lemke.cpp, decision by decision. Its answer is the minimum of a
  // total order on the candidate rows (ratio, then the z0 row, then the
  // lexicographic columns), so the rows may be visited in any order: rows
  // whose entry sign the intervals leave open go last, and one that
  // certainly loses to the best so far, whatever that sign is, needs no
  // exact sign (docs/theory.md §6).
  //
  // With settling on, an unordered comparison of the z0 row with another
  // row is taken as a z0 win (z0_taken_unordered_). That holds only if the
  // z0 row is still best at the end; otherwise the test runs again with
  // every decision made.
  int ratio_test(int s) {
    z0_taken_unordered_ = false;
    const int best = ratio_test_once(s, settle_z0_);
    if (!z0_taken_unordered_ || T_.basic(best) == T_.z0()) return best;
    z0_taken_unordered_ = false;
    return ratio_test_once(s, false);
  }

  //
  // Rows with a certainly positive entry first, each with an enclosure of
  // its ratio; a row whose ratio is certainly above another's (its
  // enclosure starts above the least upper end) cannot be the minimum, so
  // it is dropped before any pairwise comparison: ties among rows that
  // lose anyway are never proved.
  int ratio_test_once(int s, bool settle_z0) {
    int best = -1;
    boost::container::small_vector<int, 16> open, positive;
    boost::container::small_vector<FI, 16> ratio;
    double least_upper = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n_; ++i) {
      const FI entry = T_.at(i, s);
      const int sign = certain_sign(entry);
      if (sign == kUndecided) {
        open.push_back(i);
        continue;
      }
      ++certified_;
      if (sign <= 0) continue;
      positive.push_back(i);
      ratio.push_back(T_.at(i, T_.rhs()) / entry);
      least_upper = std::min(least_upper, ratio.back().sup());
    }
    for (std::size_t a = 0; a < positive.size(); ++a) {
      const bool kept_for_tests = g_defer_every_z0_comparison && T_.basic(positive[a]) == T_.z0();
      if (ratio[a].inf() > least_upper && !kept_for_tests) {
        ++certified_;
        continue;
      }
      consider(positive[a], best, s, settle_z0);
    }
    for (const int i : open) {
      if (best >= 0 && certainly_loses(i, best, s)) {
        ++certified_;
        continue;
      }
      ++exact_;
      if (exact().entry_sign(i, s) > 0) consider(i, best, s, settle_z0);
    }
    return best;
  }

  // Row i (entry T(i, s) > 0) against the best row so far.
  void consider(int i, int& best, int s, bool settle_z0) {
    if (best < 0) {
      best = i;
      return;
    }
    const bool z0_row = T_.basic(i) == T_.z0() || T_.basic(best) == T_.z0();
    if (z0_row && settle_z0) {
      const int c = g_defer_every_z0_comparison
                        ? kUndecided
                        : certain_sign(T_.at(i, T_.rhs()) * T_.at(best, s) - T_.at(best, T_.rhs()) * T_.at(i, s));
      if (c == kUndecided) {  // the z0 row taken to win; its final values settle it
        z0_taken_unordered_ = true;
        if (T_.basic(i) == T_.z0()) best = i;
        return;
      }
      ++certified_;
      if (c < 0) best = i;
      if (c == 0 && T_.basic(i) == T_.z0()) best = i;  // a certified tie (exact zeros): the z0 row wins
      return;
    }
    int c = compare_ratio(i, best, T_.rhs(), s);
    if (c == 0 && (T_.basic(i) == T_.z0() || T_.basic(best) == T_.z0())) {
      if (T_.basic(i) == T_.z0()) best = i;
      return;
    }
    for (int col = 0; c == 0 && col < n_; ++col) c = compare_ratio(i, best, col, s);
    if (c < 0) best = i;
  }

  // Whether row i, were T(i, s) positive, would have a ratio strictly above
  // the best row's: T(i, rhs)·T(best, s) − T(best, rhs)·t > 0 for every t in
  // (0, sup T(i, s)]. Then row i cannot win, nor tie, whatever its sign.
  bool certainly_loses(int i, int best, int s) {
    const double hi = T_.at(i, s).sup();
    if (!(hi > 0)) return false;
    const FI d = T_.at(i, T_.rhs()) * T_.at(best, s) - T_.at(best, T_.rhs()) * FI(0, hi);
    return d.inf() > 0;
  }

  const MatrixQ& B_;
  const VectorQ& b_;
  int n_;
  Protect guard_;  // the interval tableau's whole life
  IntervalTableau T_;
  bool scaled_ = false, tableau_current_ = false;
  bool final_ready_ = false;  // final_ holds the final basis's values
  bool settle_z0_;            // take unordered z0-row comparisons, settle them by the final values
  bool z0_taken_unordered_ = false, final_settles_ = false, settlement_failed_ = false;
  BasicValues& final_ = exact_workspace().final_values;
  long certified_ = 0, exact_ = 0;
  long ties_proved_ = 0, ties_unproved_ = 0;
};

}  // namespace

bool filtered_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result) {
  {
    // One run at a time: the runs share per-thread storage.
    FilteredRun run(B, b, true);
    if (!run.run(max_pivots, result)) return false;
    if (!run.settlement_failed()) return true;
  }
  FilteredRun run(B, b, false);
  return run.run(max_pivots, result);
}

void set_lemke_leave_every_z0_comparison_unordered(bool on) { g_defer_every_z0_comparison = on; }

bool filtered_lemke_path(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result,
                         std::vector<int>& basis) {
  FilteredRun run(B, b);
  if (!run.run(max_pivots, result, false)) return false;
  basis = run.basis();
  return true;
}

FinalValueCounts final_value_counts() {
  return {g_dixon_values.load(),    g_factored_values.load(), g_lifting_steps.load(),
          g_reconstructions.load(), g_z0_settled.load(),      g_z0_reruns.load()};
}

void reset_final_value_counts() {
  g_dixon_values = 0;
  g_factored_values = 0;
  g_lifting_steps = 0;
  g_reconstructions = 0;
  g_z0_settled = 0;
  g_z0_reruns = 0;
}

bool solves_lcp_at_basis(const MatrixQ& B, const VectorQ& b, const std::vector<int>& basis,
                         const std::vector<Integer>& num, const Integer& den) {
  const auto n = static_cast<std::size_t>(b.size());
  if (static_cast<std::size_t>(B.rows()) != n || static_cast<std::size_t>(B.cols()) != n || basis.size() != n ||
      num.size() != n || mpz_sgn(mp(den)) <= 0)
    return false;
  ScaledProblem P;
  P.assign(B, b);
  BasicValues values{num, den};
  return solves_lcp_at_basis(P, basis, values);
}

}  // namespace fixel::internal
