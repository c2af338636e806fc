#include "fixel/internal/lemke_filtered.h"

#include <optional>
#include <vector>

#include "fixel/error.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/internal/filtered.h"

namespace fixel::internal {

namespace {

int sign(const Rational& x) { return x < 0 ? -1 : (x > 0 ? 1 : 0); }

// The exact tableau A_β⁻¹ [A | b] at one basis β, A = [I, −B, −e], column by
// column on demand. Rows whose basic variable is some w_i solve trivially, so
// only a k×k block needs an LU factorisation, k being the number of basic z's
// (and z0): at most the pivots made so far, so early ties are cheap. The
// block's LU is exact (Eigen's full-pivot LU on rationals, threshold 0).
class ExactTableau {
 public:
  ExactTableau(const MatrixQ& B, const VectorQ& b, const std::vector<int>& basis)
      : B_(B), b_(b), basis_(basis), n_(static_cast<int>(b.size())), columns_(2 * n_ + 2) {
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
    MatrixQ C(k, k);
    for (int a = 0; a < k; ++a)
      for (int c = 0; c < k; ++c) C(a, c) = entry(R_[a], basis_[K_[c]]);
    lu_ = exact_lu(C);
    if (!lu_.isInvertible()) throw InternalError("filtered Lemke: the basis is singular");
  }

  // Column `col` (0..n−1 w, n..2n−1 z, 2n z0, 2n+1 the right-hand side).
  const VectorQ& column(int col) {
    auto& slot = columns_[col];
    if (slot) return *slot;
    const int k = static_cast<int>(K_.size());
    VectorQ v(k);
    for (int a = 0; a < k; ++a) v[a] = entry(R_[a], col);
    const VectorQ y = lu_.solve(v);
    VectorQ x(n_);
    for (int c = 0; c < k; ++c) x[K_[c]] = y[c];
    for (int t = 0; t < n_; ++t) {
      if (basis_[t] >= n_) continue;
      const int i = basis_[t];
      Rational acc = entry(i, col);
      for (int c = 0; c < k; ++c)
        if (y[c] != 0) acc -= entry(i, basis_[K_[c]]) * y[c];
      x[t] = acc;
    }
    slot = std::move(x);
    return *slot;
  }

 private:
  // Entry (i, var) of [A | b].
  Rational entry(int i, int var) const {
    if (var < n_) return Rational(i == var ? 1 : 0);
    if (var < 2 * n_) return -B_(i, var - n_);
    if (var == 2 * n_) return Rational(-1);
    return b_[i];
  }

  const MatrixQ& B_;
  const VectorQ& b_;
  std::vector<int> basis_;
  int n_;
  std::vector<int> R_;  // equations whose w is nonbasic
  std::vector<int> K_;  // tableau rows whose basic variable is a z or z0
  Eigen::FullPivLU<MatrixQ> lu_;
  std::vector<std::optional<VectorQ>> columns_;
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
        c = sign(b_[i] - b_[r]);
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
      const VectorQ& x = exact().column(T_.rhs());
      result.w = VectorQ::Zero(n_);
      result.z = VectorQ::Zero(n_);
      for (int t = 0; t < n_; ++t) {
        const int v = T_.basic(t);
        if (v < n_)
          result.w[v] = x[t];
        else if (v < 2 * n_)
          result.z[v - n_] = x[t];
      }
    }
    return true;
  }

 private:
  ExactTableau& exact() {
    if (!exact_tableau_) exact_tableau_.emplace(B_, b_, T_.basis());
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
    return sign(exact().column(col)[i]);
  }

  // Sign of T(i, col)·T(j, s) − T(j, col)·T(i, s): the ratio T(i, col)/T(i, s)
  // against T(j, col)/T(j, s) when both T(·, s) > 0.
  int compare_ratio(int i, int j, int col, int s) {
    const int c = certain_sign(T_.at(i, col) * T_.at(j, s) - T_.at(j, col) * T_.at(i, s));
    if (c != kUndecided) return ++certified_, c;
    ++exact_;
    ExactTableau& E = exact();
    const VectorQ& xc = E.column(col);
    const VectorQ& xs = E.column(s);
    return sign(xc[i] * xs[j] - xc[j] * xs[i]);
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
  std::optional<ExactTableau> exact_tableau_;
  long certified_ = 0, exact_ = 0;
};

}  // namespace

bool filtered_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result) {
  FilteredRun run(B, b);
  return run.run(max_pivots, result);
}

}  // namespace fixel::internal
