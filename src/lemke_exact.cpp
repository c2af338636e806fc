#include "fixel/internal/lemke_exact.h"

#include "fixel/error.h"
#include "fixel/internal/lemke_dixon.h"
#include "fixel/internal/lemke_dixon_words.h"

namespace fixel::internal {

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

bool dixon_basic_values(const ScaledProblem& P, const std::vector<int>& basis, const std::vector<double>& rhs_lo,
                        const std::vector<double>& rhs_hi, BasicValues& out, DixonTrace& trace) {
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
  rhs.resize(k);
  for (int a = 0; a < k; ++a) rhs[a] = &P.entry(rows[a], 2 * n + 1);
  // The block as words from the matrix's copy (no conversion of its
  // integers per solve) when it has one and y fits too: then lifting
  // never reads the integers, and they are not gathered.
  thread_local std::vector<std::int64_t> block_words;
  thread_local std::vector<Int128> rhs_words;
  const bool words = dixon_words_allowed() && P.in_words() && rhs_in_words(k, rhs, rhs_words);
  if (words) {
    block_words.resize(static_cast<std::size_t>(k) * k);
    for (int a = 0; a < k; ++a)
      for (int c = 0; c < k; ++c)
        block_words[static_cast<std::size_t>(a) * k + c] = P.word(rows[a], basis[block_rows[c]]);
    block.clear();
  } else {
    block.resize(static_cast<std::size_t>(k) * k);
    for (int a = 0; a < k; ++a)
      for (int c = 0; c < k; ++c) block[static_cast<std::size_t>(a) * k + c] = &P.entry(rows[a], basis[block_rows[c]]);
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
  if (!dixon_solve(k, block, rhs, u, d, &hint, &trace, words ? &block_words : nullptr)) return false;
  out.num.resize(n);
  for (int c = 0; c < k; ++c) mpz_set(mp(out.num[block_rows[c]]), mp(u[c]));
  thread_local std::vector<mpz_srcptr> row;
  thread_local Integer sum;
  row.resize(k);
  for (int t = 0; t < n; ++t) {
    if (basis[t] >= n) continue;
    // L_i·δ·d·w_i = d·(L_i δ b_i) − Σ_c A(i, β_c)·u_c.
    const int i = basis[t];
    mpz_mul(mp(out.num[t]), mp(d), mp(P.entry(i, 2 * n + 1)));
    for (int c = 0; c < k; ++c) row[c] = mp(P.entry(i, basis[block_rows[c]]));
    if (dixon_words_allowed() && dot_in_words(k, row.data(), u, sum)) {  // the seating LCPs' usual case
      mpz_sub(mp(out.num[t]), mp(out.num[t]), mp(sum));
      continue;
    }
    for (int c = 0; c < k; ++c) {
      if (mpz_sgn(mp(u[c])) == 0) continue;
      const mpz_srcptr a = mp(P.entry(i, basis[block_rows[c]]));
      if (mpz_size(a) > 1)
        mpz_submul(mp(out.num[t]), a, mp(u[c]));
      else if (mpz_sgn(a) > 0)  // one limb (the seating LCPs' entries have at most 52 bits)
        mpz_submul_ui(mp(out.num[t]), mp(u[c]), mpz_getlimbn(a, 0));
      else if (mpz_sgn(a) < 0)
        mpz_addmul_ui(mp(out.num[t]), mp(u[c]), mpz_getlimbn(a, 0));
    }
  }
  mpz_mul(mp(out.den), mp(d), mp(P.rhs_factor()));
  return true;
}

void ExactTableau::assign(const ScaledProblem& P, const std::vector<int>& basis) {
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

const Integer* ExactTableau::column(int col) {
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

int ExactTableau::cross_sign(int i, int j, int col, int s) {
  const Integer* c = column(col);
  const Integer* x = column(s);
  mpz_mul(mp(t_), mp(c[i]), mp(x[j]));
  mpz_mul(mp(t2_), mp(c[j]), mp(x[i]));
  const int cmp = mpz_cmp(mp(t_), mp(t2_));
  return (cmp > 0) - (cmp < 0);
}

void ExactTableau::basic_values(int rhs, BasicValues& out) {
  const Integer* N = column(rhs);
  out.num.resize(n_);
  for (int t = 0; t < n_; ++t) mpz_set(mp(out.num[t]), mp(N[t]));
  mpz_mul(mp(out.den), mp(D_), mp(P_->rhs_factor()));
  out.normalize_sign();
}

bool ExactTableau::basic_values_after_pivot(int r, int col, int rhs, BasicValues& out) {
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

void ExactTableau::grow(std::vector<Integer>& v, std::size_t size) {
  if (v.size() < size) v.resize(size);
}

void ExactTableau::bareiss_step(Integer& x, const Integer& p, const Integer* m, const Integer& y, const Integer& D) {
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

void ExactTableau::eliminate() {
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

}  // namespace fixel::internal
