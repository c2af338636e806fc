#include "fixel/lemke.h"

#include <stdexcept>
#include <vector>

#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/filtered.h"

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

using internal::certain_sign;
using internal::FI;
using internal::kUndecided;

// The same lexicographic Lemke path on an interval tableau (Gauss-Jordan on
// [I, −B, −e | b]: the exact tableau up to positive row and column scalings,
// which change no ratio-test decision). Every sign and every ratio
// comparison must be certified by the intervals; the first that is not makes
// the whole run undecided (false), and the caller runs the exact tableau.
// When every decision is certified, the pivots are those of the exact run,
// so the final basis is the exact run's basis.
class IntervalTableau {
 public:
  IntervalTableau(const MatrixQ& B, const VectorQ& b) : n_(static_cast<int>(b.size())), w_(2 * n_ + 2) {
    T_.assign(static_cast<std::size_t>(n_) * w_, FI(0));
    basis_.resize(n_);
    for (int i = 0; i < n_; ++i) {
      at(i, i) = FI(1);
      for (int j = 0; j < n_; ++j)
        if (B(i, j) != 0) at(i, n_ + j) = -internal::to_interval(B(i, j));
      at(i, z0()) = FI(-1);
      at(i, rhs()) = internal::to_interval(b[i]);
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

  // Needs a Protect scope. The pivot's sign is certified by the caller.
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

  // The exact ratio test of Tableau::ratio_test, decision by decision;
  // sets `undecided` when an interval cannot certify one.
  int ratio_test(int s, bool& undecided) const {
    int best = -1;
    for (int i = 0; i < n_; ++i) {
      const int si = certain_sign(at(i, s));
      if (si == kUndecided) return undecided = true, -1;
      if (si <= 0) continue;
      if (best < 0) {
        best = i;
        continue;
      }
      int c = compare_ratio(at(i, rhs()), at(i, s), at(best, rhs()), at(best, s));
      if (c == kUndecided) return undecided = true, -1;
      if (c == 0 && (basis_[i] == z0() || basis_[best] == z0())) {
        if (basis_[i] == z0()) best = i;
        continue;
      }
      for (int col = 0; c == 0 && col < n_; ++col) {
        c = compare_ratio(at(i, col), at(i, s), at(best, col), at(best, s));
        if (c == kUndecided) return undecided = true, -1;
      }
      if (c < 0) best = i;
    }
    return best;
  }

 private:
  static int compare_ratio(const FI& a, const FI& b, const FI& c, const FI& d) { return certain_sign(a * d - c * b); }

  int n_, w_;
  std::vector<FI> T_;
  std::vector<int> basis_;
};

// Exact w, z of a complementary basis: z_Z solves B_ZZ z_Z = −b_Z for the
// basic z's, w = B z + b. Plain rational elimination (the basis is
// nonsingular: it is the exact run's final basis).
void solve_basis(const MatrixQ& B, const VectorQ& b, const std::vector<int>& basis, VectorQ& w, VectorQ& z) {
  const int n = static_cast<int>(b.size());
  std::vector<int> Z;
  for (int v : basis)
    if (v >= n && v < 2 * n) Z.push_back(v - n);
  const int k = static_cast<int>(Z.size());
  std::vector<std::vector<Rational>> A(k, std::vector<Rational>(k + 1));
  for (int r = 0; r < k; ++r) {
    for (int c = 0; c < k; ++c) A[r][c] = B(Z[r], Z[c]);
    A[r][k] = -b[Z[r]];
  }
  for (int c = 0; c < k; ++c) {
    int p = c;
    while (p < k && A[p][c] == 0) ++p;
    if (p == k) throw InternalError("solve_lcp_lemke: the certified final basis is singular");
    std::swap(A[p], A[c]);
    for (int r = c + 1; r < k; ++r) {
      if (A[r][c] == 0) continue;
      const Rational f = A[r][c] / A[c][c];
      for (int j = c; j <= k; ++j)
        if (A[c][j] != 0) A[r][j] -= f * A[c][j];
    }
  }
  z = VectorQ::Zero(n);
  for (int r = k; r-- > 0;) {
    Rational acc = A[r][k];
    for (int j = r + 1; j < k; ++j)
      if (A[r][j] != 0) acc -= A[r][j] * z[Z[j]];
    z[Z[r]] = acc / A[r][r];
  }
  w = b;
  for (int i = 0; i < n; ++i)
    for (int j : Z)
      if (B(i, j) != 0 && z[j] != 0) w[i] += B(i, j) * z[j];
}

// The filtered run: true when every decision was certified (result set),
// false when the exact run must decide.
bool filtered_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result) {
  const int n = static_cast<int>(b.size());
  IntervalTableau T(B, b);
  {
    internal::Protect guard;
    int r = 0;
    for (int i = 1; i < n; ++i) {
      const int c = certain_sign(T.at(i, T.rhs()) - T.at(r, T.rhs()));
      if (c == kUndecided) return false;
      if (c <= 0) r = i;
    }
    int entering = T.complement(T.basic(r));
    T.pivot(r, T.z0());
    result.pivots = 1;
    while (true) {
      if (result.pivots >= max_pivots) {
        result.status = LemkeStatus::kPivotLimit;
        return true;
      }
      bool undecided = false;
      r = T.ratio_test(entering, undecided);
      if (undecided) return false;
      if (r < 0) {
        result.status = LemkeStatus::kRayTermination;
        return true;
      }
      const int leaving = T.basic(r);
      T.pivot(r, entering);
      ++result.pivots;
      if (leaving == T.z0()) break;
      entering = T.complement(leaving);
    }
  }
  solve_basis(B, b, T.basis(), result.w, result.z);
  result.status = LemkeStatus::kSolved;
  return true;
}

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
  for (int i = 0; i < n; ++i) {
    Rational acc = b[i];
    for (int j = 0; j < n; ++j)
      if (z[j] != 0 && B(i, j) != 0) acc += B(i, j) * z[j];
    if (acc != w[i]) return false;
  }
  return true;
}

LemkeResult solve_lcp_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots) {
  const int n = static_cast<int>(b.size());
  if (B.rows() != n || B.cols() != n)
    throw InputError("B", std::to_string(B.rows()) + "x" + std::to_string(B.cols()),
                     "must be square of the size of b (" + std::to_string(n) + ")");
  if (max_pivots <= 0) max_pivots = 100 * (n + 1);
  LemkeResult result;
  if ((b.array() >= Rational(0)).all()) {  // z = 0 already solves it
    result.status = LemkeStatus::kSolved;
    result.w = b;
    result.z = VectorQ::Zero(n);
    return result;
  }

  if (!force_exact()) {
    LemkeResult filtered;
    const bool certified = filtered_lemke(B, b, max_pivots, filtered);
    internal::record_filter(FilterSite::kLemke, certified);
    if (certified) {
      if (filtered.status == LemkeStatus::kSolved && !is_solution(B, b, filtered.w, filtered.z))
        throw InternalError("solve_lcp_lemke: the certified final basis fails the independent is_solution check");
      return filtered;
    }
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
    if (result.pivots >= max_pivots) {
      result.status = LemkeStatus::kPivotLimit;
      return result;
    }
    r = T.ratio_test(entering);
    if (r < 0) {
      result.status = LemkeStatus::kRayTermination;
      return result;
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
  return result;
}

}  // namespace fixel
