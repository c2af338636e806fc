#include "fixel/internal/lemke_filtered.h"

#include <optional>
#include <vector>

#include "fixel/error.h"
#include "fixel/internal/filtered.h"

namespace fixel::internal {

namespace {

// [A | b] with equation i scaled by L_i > 0, the lcm of the denominators of
// B's row i and b_i: every entry an integer. Scaling an equation changes no
// solution of the systems below.
class ScaledProblem {
 public:
  ScaledProblem(const MatrixQ& B, const VectorQ& b) : n_(static_cast<int>(b.size())) {
    scale_.resize(n_);
    B_.assign(n_, std::vector<Integer>(n_));
    b_.resize(n_);
    for (int i = 0; i < n_; ++i) {
      Integer L = boost::multiprecision::denominator(b[i]);
      for (int j = 0; j < n_; ++j) L = boost::multiprecision::lcm(L, boost::multiprecision::denominator(B(i, j)));
      scale_[i] = L;
      for (int j = 0; j < n_; ++j) B_[i][j] = scaled(B(i, j), L);
      b_[i] = scaled(b[i], L);
    }
  }

  int n() const { return n_; }
  const Integer& scale(int i) const { return scale_[i]; }
  // L_i · (i, var) of [A | b]; var 0..n−1 w, n..2n−1 z, 2n z0, 2n+1 b.
  Integer entry(int i, int var) const {
    if (var < n_) return i == var ? scale_[i] : Integer(0);
    if (var < 2 * n_) return -B_[i][var - n_];
    if (var == 2 * n_) return -scale_[i];
    return b_[i];
  }

 private:
  static Integer scaled(const Rational& x, const Integer& L) {
    return boost::multiprecision::numerator(x) * (L / boost::multiprecision::denominator(x));
  }

  int n_;
  std::vector<Integer> scale_;
  std::vector<std::vector<Integer>> B_;
  std::vector<Integer> b_;
};

// The exact tableau A_β⁻¹ [A | b] at one basis β, A = [I, −B, −e], column by
// column on demand, in integers. Rows whose basic variable is some w_i solve
// trivially, so only the k×k block C of the basic z's (and z0) on the other
// equations is factored, k being at most the pivots made so far (early ties
// are cheap). C is reduced by fraction-free (Bareiss) elimination, whose
// divisions are exact; its last pivot D = ±det C. Entry (t, col) is then
// N_t / σ_t with N_t an integer and σ_t = D (rows of z's) or D·L_i (the row
// of w_i): no gcd until a value is needed.
class ExactTableau {
 public:
  ExactTableau(const ScaledProblem& P, const std::vector<int>& basis)
      : P_(P), basis_(basis), n_(P.n()), columns_(2 * n_ + 2) {
    std::vector<bool> w_basic(n_, false);
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
    U_.assign(k, std::vector<Integer>(k));
    for (int a = 0; a < k; ++a)
      for (int c = 0; c < k; ++c) U_[a][c] = P_.entry(R_[a], basis_[K_[c]]);
    eliminate();
  }

  // Numerators N_t of column `col`; the value of entry t is N_t / σ_t.
  const std::vector<Integer>& column(int col) {
    auto& slot = columns_[col];
    if (slot) return *slot;
    const int k = static_cast<int>(K_.size());
    std::vector<Integer> y(k);
    for (int a = 0; a < k; ++a) y[a] = P_.entry(R_[a], col);
    // The stored elimination steps, then fraction-free back substitution:
    // N_r = (D·y_r − Σ_{j>r} U_rj N_j) / U_rr (exact: D·x is an integer by Cramer).
    for (int c = 0; c < k; ++c) {
      std::swap(y[c], y[swaps_[c]]);
      for (int r = c + 1; r < k; ++r) y[r] = (U_[c][c] * y[r] - multipliers_[r][c] * y[c]) / previous_[c];
    }
    std::vector<Integer> N(k);
    for (int r = k; r-- > 0;) {
      Integer acc = D_ * y[r];
      for (int j = r + 1; j < k; ++j)
        if (U_[r][j] != 0) acc -= U_[r][j] * N[j];
      N[r] = acc / U_[r][r];
    }
    std::vector<Integer> x(n_);
    for (int c = 0; c < k; ++c) x[K_[c]] = N[c];
    for (int t = 0; t < n_; ++t) {
      if (basis_[t] >= n_) continue;
      // w_i = (v_i − A(i, K)·x_K), scaled by L_i·D.
      const int i = basis_[t];
      Integer acc = D_ * P_.entry(i, col);
      for (int c = 0; c < k; ++c)
        if (N[c] != 0) acc -= P_.entry(i, basis_[K_[c]]) * N[c];
      x[t] = acc;
    }
    slot = std::move(x);
    return *slot;
  }

  // Sign of entry (t, col).
  int entry_sign(int t, int col) { return column(col)[t].sign() * D_.sign(); }

  // Sign of T(i, col)·T(j, s) − T(j, col)·T(i, s): σ_i σ_j > 0 cancels.
  int cross_sign(int i, int j, int col, int s) {
    const auto& c = column(col);
    const auto& x = column(s);
    return (c[i] * x[j] - c[j] * x[i]).sign();
  }

  // The exact value of entry (t, col).
  Rational value(int t, int col) {
    const Integer sigma = basis_[t] < n_ ? D_ * P_.scale(basis_[t]) : D_;
    return Rational(column(col)[t], sigma);
  }

 private:
  void eliminate() {
    const int k = static_cast<int>(K_.size());
    swaps_.assign(k, 0);
    previous_.assign(k, Integer(1));
    multipliers_.assign(k, std::vector<Integer>(k));
    Integer previous = 1;
    for (int c = 0; c < k; ++c) {
      int p = c;
      while (p < k && U_[p][c] == 0) ++p;
      if (p == k) throw InternalError("filtered Lemke: the basis is singular");
      std::swap(U_[p], U_[c]);
      swaps_[c] = p;
      previous_[c] = previous;
      for (int r = c + 1; r < k; ++r) {
        multipliers_[r][c] = U_[r][c];
        for (int j = c + 1; j < k; ++j) U_[r][j] = (U_[c][c] * U_[r][j] - U_[r][c] * U_[c][j]) / previous;
        U_[r][c] = 0;
      }
      previous = U_[c][c];
    }
    D_ = previous;
  }

  const ScaledProblem& P_;
  std::vector<int> basis_;
  int n_;
  std::vector<int> R_;  // equations whose w is nonbasic
  std::vector<int> K_;  // tableau rows whose basic variable is a z or z0
  std::vector<std::vector<Integer>> U_, multipliers_;
  std::vector<int> swaps_;
  std::vector<Integer> previous_;
  Integer D_ = 1;
  std::vector<std::optional<std::vector<Integer>>> columns_;
};

// The same tableau in intervals (Gauss–Jordan on [I, −B, −e | b]): every
// entry encloses the exact tableau's. It is the integer tableau of
// src/lemke.cpp up to positive row and column scalings, which change no
// ratio-test decision.
class IntervalTableau {
 public:
  IntervalTableau(const MatrixQ& B, const VectorQ& b) : n_(static_cast<int>(b.size())), w_(2 * n_ + 2) {
    T_.assign(static_cast<std::size_t>(n_) * w_, FI(0));
    basis_.resize(n_);
    for (int i = 0; i < n_; ++i) {
      at(i, i) = FI(1);
      for (int j = 0; j < n_; ++j)
        if (B(i, j) != 0) at(i, n_ + j) = -to_interval(B(i, j));
      at(i, z0()) = FI(-1);
      at(i, rhs()) = to_interval(b[i]);
      basis_[i] = i;
    }
  }

  int z0() const { return 2 * n_; }
  int rhs() const { return 2 * n_ + 1; }
  int basic(int row) const { return basis_[row]; }
  const std::vector<int>& basis() const { return basis_; }
  int complement(int var) const { return var < n_ ? var + n_ : var - n_; }
  FI& at(int i, int j) { return T_[static_cast<std::size_t>(i) * w_ + j]; }
  const FI& at(int i, int j) const { return T_[static_cast<std::size_t>(i) * w_ + j]; }

  // Needs a Protect scope and a pivot interval that excludes zero.
  void pivot(int r, int s) {
    const FI p = at(r, s);
    for (int j = 0; j < w_; ++j) at(r, j) /= p;
    at(r, s) = FI(1);
    for (int i = 0; i < n_; ++i) {
      if (i == r) continue;
      const FI f = at(i, s);
      if (f.inf() == 0 && f.sup() == 0) continue;  // an exact zero stays exact
      for (int j = 0; j < w_; ++j) {
        const FI& x = at(r, j);
        if (x.inf() == 0 && x.sup() == 0) continue;
        at(i, j) -= f * x;
      }
      at(i, s) = FI(0);
    }
    basis_[r] = s;
  }

 private:
  int n_, w_;
  std::vector<FI> T_;
  std::vector<int> basis_;
};

// One filtered run: each decision of the exact run (src/lemke.cpp) is taken
// from the intervals when they certify it, else from the exact tableau at the
// current basis (built lazily, dropped at each pivot). So the pivots, and the
// final basis, are the exact run's.
class FilteredRun {
 public:
  FilteredRun(const MatrixQ& B, const VectorQ& b) : B_(B), b_(b), n_(static_cast<int>(b.size())), T_(B, b) {}
  ~FilteredRun() { record_filter(FilterSite::kLemke, certified_, exact_); }

  bool run(int max_pivots, LemkeResult& result) {
    Protect guard;
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
      const int leaving = T_.basic(r);
      if (!pivot(r, entering)) return false;
      ++pivots;
      if (leaving == T_.z0()) break;
      entering = T_.complement(leaving);
    }
    result = LemkeResult{};
    result.status = status;
    result.pivots = pivots;
    if (status == LemkeStatus::kSolved) {
      ExactTableau& E = exact();
      result.w = VectorQ::Zero(n_);
      result.z = VectorQ::Zero(n_);
      for (int t = 0; t < n_; ++t) {
        const int v = T_.basic(t);
        if (v < n_)
          result.w[v] = E.value(t, T_.rhs());
        else if (v < 2 * n_)
          result.z[v - n_] = E.value(t, T_.rhs());
      }
    }
    return true;
  }

 private:
  ExactTableau& exact() {
    if (!scaled_) scaled_.emplace(B_, b_);
    if (!exact_tableau_) exact_tableau_.emplace(*scaled_, T_.basis());
    return *exact_tableau_;
  }

  bool pivot(int r, int s) {
    if (certain_sign(T_.at(r, s)) == kUndecided) return false;  // the division would lose everything
    T_.pivot(r, s);
    exact_tableau_.reset();
    return true;
  }

  // Sign of tableau entry (i, col).
  int entry_sign(int i, int col) {
    const int s = certain_sign(T_.at(i, col));
    if (s != kUndecided) return ++certified_, s;
    ++exact_;
    return exact().entry_sign(i, col);
  }

  // Sign of T(i, col)·T(j, s) − T(j, col)·T(i, s): the ratio T(i, col)/T(i, s)
  // against T(j, col)/T(j, s) when both T(·, s) > 0.
  int compare_ratio(int i, int j, int col, int s) {
    const int c = certain_sign(T_.at(i, col) * T_.at(j, s) - T_.at(j, col) * T_.at(i, s));
    if (c != kUndecided) return ++certified_, c;
    ++exact_;
    return exact().cross_sign(i, j, col, s);
  }

  // The lexicographic minimum ratio test of Tableau::ratio_test in
  // src/lemke.cpp, decision by decision.
  int ratio_test(int s) {
    int best = -1;
    for (int i = 0; i < n_; ++i) {
      if (entry_sign(i, s) <= 0) continue;
      if (best < 0) {
        best = i;
        continue;
      }
      int c = compare_ratio(i, best, T_.rhs(), s);
      if (c == 0 && (T_.basic(i) == T_.z0() || T_.basic(best) == T_.z0())) {
        if (T_.basic(i) == T_.z0()) best = i;
        continue;
      }
      for (int col = 0; c == 0 && col < n_; ++col) c = compare_ratio(i, best, col, s);
      if (c < 0) best = i;
    }
    return best;
  }

  const MatrixQ& B_;
  const VectorQ& b_;
  int n_;
  IntervalTableau T_;
  std::optional<ScaledProblem> scaled_;
  std::optional<ExactTableau> exact_tableau_;
  long certified_ = 0, exact_ = 0;
};

}  // namespace

bool filtered_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result) {
  FilteredRun run(B, b);
  return run.run(max_pivots, result);
}

}  // namespace fixel::internal
