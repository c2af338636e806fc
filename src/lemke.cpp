#include "fixel/lemke.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/lemke_filtered.h"
#include "fixel/internal/lemke_prepared.h"
#include "fixel/progress.h"

namespace fixel {

namespace {

// Integer tableau T = D · A_B⁻¹ [A | q] for A = [I, −L·B, −e], q = L·b,
// where L clears every denominator of B and b (so w' = L·w). Columns:
// 0..n−1 w', n..2n−1 z, 2n z0, 2n+1 the right-hand side. D = |det A_B| > 0.
class Tableau {
 public:
  Tableau(const MatrixQ& B, const VectorQ& b) : n_(static_cast<int>(b.size())) {
    for (int i = 0; i < n_; ++i) {
      scale_ = boost::multiprecision::lcm(scale_, boost::multiprecision::denominator(b[i]));
      for (int j = 0; j < n_; ++j)
        scale_ = boost::multiprecision::lcm(scale_, boost::multiprecision::denominator(B(i, j)));
    }
    T_.assign(n_, std::vector<Integer>(2 * n_ + 2, Integer(0)));
    basis_.resize(n_);
    for (int i = 0; i < n_; ++i) {
      T_[i][i] = 1;
      for (int j = 0; j < n_; ++j) T_[i][n_ + j] = integer(-B(i, j) * Rational(scale_));
      T_[i][z0()] = -1;
      T_[i][rhs()] = integer(b[i] * Rational(scale_));
      basis_[i] = i;
    }
  }

  int z0() const { return 2 * n_; }
  int rhs() const { return 2 * n_ + 1; }
  int basic(int row) const { return basis_[row]; }
  const Integer& at(int row, int col) const { return T_[row][col]; }
  // w_i and z_i are complements.
  int complement(int var) const { return var < n_ ? var + n_ : var - n_; }

  // Fraction-free (Bareiss) pivot: every division is exact.
  void pivot(int r, int s) {
    const Integer p = T_[r][s];
    for (int i = 0; i < n_; ++i) {
      if (i == r) continue;
      const Integer f = T_[i][s];
      for (int j = 0; j < 2 * n_ + 2; ++j) T_[i][j] = (T_[i][j] * p - f * T_[r][j]) / D_;
    }
    D_ = p;
    basis_[r] = s;
    if (D_ < 0) {  // keep D > 0 so that column signs are value signs
      D_ = -D_;
      for (auto& row : T_)
        for (auto& x : row) x = -x;
    }
  }

  // a/b < c/d for b, d > 0, as the sign of a·d − c·b.
  static int compare_ratio(const Integer& a, const Integer& b, const Integer& c, const Integer& d) {
    const Integer diff = a * d - c * b;
    return diff < 0 ? -1 : (diff > 0 ? 1 : 0);
  }

  // Lexicographic minimum ratio test on column s; -1 if no entry is positive
  // (ray). Prefers the z0 row when it ties on the right-hand side, which ends
  // the path with a solution.
  int ratio_test(int s) const {
    int best = -1;
    for (int i = 0; i < n_; ++i) {
      if (T_[i][s] <= 0) continue;
      if (best < 0) {
        best = i;
        continue;
      }
      int c = compare_ratio(T_[i][rhs()], T_[i][s], T_[best][rhs()], T_[best][s]);
      if (c == 0 && (basis_[i] == z0() || basis_[best] == z0())) {
        if (basis_[i] == z0()) best = i;
        continue;
      }
      for (int col = 0; c == 0 && col < n_; ++col) c = compare_ratio(T_[i][col], T_[i][s], T_[best][col], T_[best][s]);
      if (c < 0) best = i;
    }
    return best;
  }

  void extract(VectorQ& w, VectorQ& z) const {
    w = VectorQ::Zero(n_);
    z = VectorQ::Zero(n_);
    for (int i = 0; i < n_; ++i) {
      const int v = basis_[i];
      const Rational value(T_[i][rhs()], D_);
      if (v < n_)
        w[v] = value / Rational(scale_);
      else if (v < 2 * n_)
        z[v - n_] = value;
    }
  }

 private:
  static Integer integer(const Rational& x) { return boost::multiprecision::numerator(x); }

  int n_;
  Integer scale_ = 1;
  Integer D_ = 1;
  std::vector<std::vector<Integer>> T_;
  std::vector<int> basis_;
};

}  // namespace

std::string to_string(LemkeStatus status) {
  switch (status) {
    case LemkeStatus::kSolved:
      return "solved";
    case LemkeStatus::kRayTermination:
      return "ray termination";
    case LemkeStatus::kPivotLimit:
      return "pivot limit";
  }
  return "unknown";
}

bool is_solution(const MatrixQ& B, const VectorQ& b, const VectorQ& w, const VectorQ& z) {
  const auto n = b.size();
  if (B.rows() != n || B.cols() != n || w.size() != n || z.size() != n) return false;
  for (int i = 0; i < n; ++i)
    if (w[i] < 0 || z[i] < 0 || (w[i] != 0 && z[i] != 0)) return false;  // w ≥ 0, z ≥ 0, wᵀz = 0
  // Row by row in integers: with d the lcm of z's denominators (n_j = d·z_j)
  // and L the lcm of the row's denominators of B, row i holds iff
  // Σ_j (L·B_ij)·n_j = L·d·(w_i − b_i). This avoids a gcd per term; the
  // values are reused from row to row, so the check allocates little.
  Integer d = 1, L, factor, sum, term;
  // lcm(L, q) only when q does not divide L already (denominators repeat).
  const auto raise_to_multiple = [](Integer& L, mpz_srcptr q) {
    if (!mpz_divisible_p(L.backend().data(), q)) mpz_lcm(L.backend().data(), L.backend().data(), q);
  };
  for (int j = 0; j < n; ++j) raise_to_multiple(d, mpq_denref(z[j].backend().data()));
  std::vector<Integer> scaled_z(n);
  for (int j = 0; j < n; ++j) {
    const auto* q = z[j].backend().data();
    mpz_divexact(factor.backend().data(), d.backend().data(), mpq_denref(q));
    mpz_mul(scaled_z[j].backend().data(), mpq_numref(q), factor.backend().data());
  }
  Rational rhs;
  for (int i = 0; i < n; ++i) {
    mpz_set_ui(L.backend().data(), 1);
    for (int j = 0; j < n; ++j)
      if (z[j] != 0) raise_to_multiple(L, mpq_denref(B(i, j).backend().data()));
    mpz_set_ui(sum.backend().data(), 0);
    for (int j = 0; j < n; ++j) {
      if (z[j] == 0) continue;
      const auto* q = B(i, j).backend().data();
      if (mpz_sgn(mpq_numref(q)) == 0) continue;
      mpz_divexact(factor.backend().data(), L.backend().data(), mpq_denref(q));
      mpz_mul(term.backend().data(), mpq_numref(q), factor.backend().data());
      mpz_addmul(sum.backend().data(), term.backend().data(), scaled_z[j].backend().data());
    }
    // L·d·(w_i − b_i) = L·d·p/q (lowest terms) must be the integer `sum`:
    // q must divide L·d.
    mpq_sub(rhs.backend().data(), w[i].backend().data(), b[i].backend().data());
    const auto* r = rhs.backend().data();
    mpz_mul(factor.backend().data(), L.backend().data(), d.backend().data());
    if (!mpz_divisible_p(factor.backend().data(), mpq_denref(r))) return false;
    mpz_divexact(factor.backend().data(), factor.backend().data(), mpq_denref(r));
    mpz_mul(factor.backend().data(), factor.backend().data(), mpq_numref(r));
    if (mpz_cmp(factor.backend().data(), sum.backend().data()) != 0) return false;
  }
  return true;
}

LemkeResult solve_lcp_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots) {
  LemkeResult result;
  solve_lcp_lemke(B, b, result, max_pivots);
  return result;
}

namespace {

// Both overloads: `prepared` is B's cached parts, or null.
void solve(const MatrixQ& B, const internal::PreparedLemkeMatrix* prepared, const VectorQ& b, LemkeResult& result,
           int max_pivots) {
  const int n = static_cast<int>(b.size());
  if (B.rows() != n || B.cols() != n)
    throw InputError("B", std::to_string(B.rows()) + "x" + std::to_string(B.cols()),
                     "must be square of the size of b (" + std::to_string(n) + ")");
  if (max_pivots <= 0) max_pivots = 100 * (n + 1);
  result.status = LemkeStatus::kRayTermination;
  result.pivots = 0;
  // z = 0 already solves it when b ≥ 0 (signs read in place: no temporary).
  if (std::all_of(b.begin(), b.end(), [](const Rational& x) { return mpq_sgn(x.backend().data()) >= 0; })) {
    result.status = LemkeStatus::kSolved;
    result.w = b;
    result.z.resize(n);
    result.z.setZero();
    return;
  }

  const internal::ExactTask task("LCP (Lemke)");
  if (!force_exact()) {
    if (internal::filtered_lemke(B, b, max_pivots, result, prepared)) return;
    internal::record_filter(FilterSite::kLemke, 0, 1);  // a pivot interval held zero: the whole run is exact
  }

  Tableau T(B, b);
  // z0 enters; the row with the most negative q leaves. Ties go to the
  // larger index, the lexicographic minimum of (q_i, e_i).
  int r = 0;
  for (int i = 1; i < n; ++i)
    if (T.at(i, T.rhs()) <= T.at(r, T.rhs())) r = i;
  int entering = T.complement(T.basic(r));
  T.pivot(r, T.z0());
  result.pivots = 1;

  while (true) {
    internal::poll_exact_step();
    if (result.pivots >= max_pivots) {
      result.status = LemkeStatus::kPivotLimit;
      result.w.resize(0);
      result.z.resize(0);
      return;
    }
    r = T.ratio_test(entering);
    if (r < 0) {
      result.status = LemkeStatus::kRayTermination;
      result.w.resize(0);
      result.z.resize(0);
      return;
    }
    const int leaving = T.basic(r);
    T.pivot(r, entering);
    ++result.pivots;
    if (leaving == T.z0()) break;
    entering = T.complement(leaving);
  }
  T.extract(result.w, result.z);
  // Never report a wrong "solved": the checker is independent of the tableau.
  if (!is_solution(B, b, result.w, result.z))
    throw InternalError("solve_lcp_lemke: the final basis fails the independent is_solution check");
  result.status = LemkeStatus::kSolved;
}

}  // namespace

void solve_lcp_lemke(const MatrixQ& B, const VectorQ& b, LemkeResult& result, int max_pivots) {
  solve(B, nullptr, b, result, max_pivots);
}

LemkeMatrix::LemkeMatrix(MatrixQ B) {
  if (B.rows() != B.cols())
    throw InputError("B", std::to_string(B.rows()) + "x" + std::to_string(B.cols()), "must be square");
  auto prepared = std::make_shared<internal::PreparedLemkeMatrix>();
  prepared->B = std::move(B);
  {
    internal::Protect guard;
    prepared->intervals.assign(prepared->B);
  }
  prepared->scaled.assign(prepared->B);
  prepared_ = std::move(prepared);
}

const MatrixQ& LemkeMatrix::matrix() const { return prepared_->B; }

int LemkeMatrix::size() const { return static_cast<int>(prepared_->B.rows()); }

void solve_lcp_lemke(const LemkeMatrix& B, const VectorQ& b, LemkeResult& result, int max_pivots) {
  solve(B.prepared_->B, B.prepared_.get(), b, result, max_pivots);
}

LemkeResult solve_lcp_lemke(const LemkeMatrix& B, const VectorQ& b, int max_pivots) {
  LemkeResult result;
  solve_lcp_lemke(B, b, result, max_pivots);
  return result;
}

}  // namespace fixel
