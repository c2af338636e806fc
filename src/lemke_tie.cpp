#include "fixel/internal/lemke_tie.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fixel::internal {

bool small_rational(double x, long long& p, long long& q) {
  if (!(std::abs(x) < 0x1p20)) return false;
  long long p0 = 0, q0 = 1, p1 = 1, q1 = 0;
  double y = x;
  for (int step = 0; step < 24; ++step) {  // q grows at least like Fibonacci: 1024 within 16 steps
    const double a = std::floor(y);
    if (step > 0 && a > 1024) return false;  // q would pass 1024 (and the cast below stays in range)
    const auto ai = static_cast<long long>(a);
    const long long p2 = ai * p1 + p0, q2 = ai * q1 + q0;
    if (q2 > 1024) return false;
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
    if (std::abs(x - static_cast<double>(p1) / static_cast<double>(q1)) <= 1e-9 * std::max(1.0, std::abs(x))) {
      p = p1, q = q1;
      return true;
    }
    const double frac = y - a;
    if (!(frac > 0)) return false;
    y = 1 / frac;
  }
  return false;
}

bool TieCertifier::singular(const std::vector<int>& beta, const ApproxProblem& approx, const ScaledProblem& P) {
  const int n = P.n();
  // A_β with the unit columns of its basic w's removed: rows R (equations
  // whose w is not in β) by the other columns, singular iff A_β is.
  in_beta_.assign(2 * n + 2, 0);
  for (const int v : beta) {
    if (v < 0 || v >= 2 * n + 2 || in_beta_[v]) return false;  // a repeated column: not this certificate's case
    in_beta_[v] = 1;
  }
  rows_.clear();
  vars_.clear();
  for (int r = 0; r < n; ++r)
    if (!in_beta_[r]) rows_.push_back(r);
  for (const int v : beta)
    if (v >= n) vars_.push_back(v);
  const int k = static_cast<int>(vars_.size());
  if (k == 0 || static_cast<int>(rows_.size()) != k) return false;

  // Half of the seating LCPs' ties: an equation in R that is zero on every
  // column of β (y a unit vector), found without the elimination below.
  for (const int r : rows_) {
    bool zero = true;
    for (int c = 0; c < k && zero; ++c) zero = approx.at(r, vars_[c]) == 0.0;
    if (!zero) continue;
    for (int c = 0; c < k && zero; ++c) zero = mpz_sgn(mp(P.entry(r, vars_[c]))) == 0;
    if (zero) return true;
  }

  // The guess: Gaussian elimination with full pivoting on Mᵀ in doubles
  // (row c of Mᵀ is column vars[c]), stopping at the first pivot below
  // 1e-9 of the largest entry; y solves Mᵀ y = 0 with the first free
  // unknown at 1.
  const auto idx = [k](int r, int c) { return static_cast<std::size_t>(r) * k + c; };
  M_.resize(static_cast<std::size_t>(k) * k);
  double largest = 0;
  for (int c = 0; c < k; ++c)
    for (int a = 0; a < k; ++a) {
      M_[idx(c, a)] = approx.at(rows_[a], vars_[c]);
      largest = std::max(largest, std::abs(M_[idx(c, a)]));
    }
  if (!(largest > 0)) return false;
  perm_.resize(k);
  std::iota(perm_.begin(), perm_.end(), 0);
  // The full pivot search of each step is fused into the previous step's
  // update (the same row-major order, so the same pivot): the first one
  // is a scan of the whole matrix.
  // The search keeps the best magnitude in a register and updates it
  // without branches (data-dependent branches mispredict here); the same
  // first strict maximum in row-major order, so the same pivot.
  int pr = 0, pc = 0;
  double best = -1;
  const auto consider = [&](int r, int c) {
    const double a = std::abs(M_[idx(r, c)]);
    const bool better = a > best;
    best = better ? a : best;
    pr = better ? r : pr;
    pc = better ? c : pc;
  };
  for (int r = 0; r < k; ++r)
    for (int c = 0; c < k; ++c) consider(r, c);
  int rank = 0;
  for (; rank < k; ++rank) {
    if (!(best > 1e-9 * largest)) break;
    for (int c = 0; c < k; ++c) std::swap(M_[idx(rank, c)], M_[idx(pr, c)]);
    for (int r = 0; r < k; ++r) std::swap(M_[idx(r, rank)], M_[idx(r, pc)]);
    std::swap(perm_[rank], perm_[pc]);
    pr = pc = rank + 1;
    best = -1;
    const double pivot = M_[idx(rank, rank)];
    for (int r = rank + 1; r < k; ++r) {
      const double f = M_[idx(r, rank)] / pivot;
      M_[idx(r, rank)] -= f * pivot;
      for (int c = rank + 1; c < k; ++c) {
        M_[idx(r, c)] -= f * M_[idx(rank, c)];
        consider(r, c);
      }
    }
  }
  if (rank == k) return false;
  x_.assign(k, 0.0);
  x_[rank] = 1;
  for (int a = rank; a-- > 0;) {
    double sum = 0;
    for (int c = a + 1; c <= rank; ++c) sum += M_[idx(a, c)] * x_[c];
    x_[a] = -sum / M_[idx(a, a)];
  }
  // Small rationals, then integers over their lcm (kept small).
  num_.resize(k);
  den_.resize(k);
  long long lcm = 1;
  for (int a = 0; a < k; ++a) {
    if (!small_rational(x_[a], num_[a], den_[a])) return false;
    lcm = std::lcm(lcm, den_[a]);
    if (lcm > (1LL << 20)) return false;
  }
  y_.assign(k, 0);
  for (int a = 0; a < k; ++a) y_[perm_[a]] = num_[a] * (lcm / den_[a]);  // |p| ≤ 2^20·1024, so |y| < 2^51

  // The proof, in integers: with (i, var) = entry(i, var)/L_i and L the lcm
  // of the L_i on y's support, Σ_a y_a (L/L_{r_a}) entry(r_a, var) = 0 for
  // every var in β.
  mpz_set_ui(mp(L_), 1);
  for (int a = 0; a < k; ++a)
    if (y_[a] != 0) mpz_lcm(mp(L_), mp(L_), mp(P.scale(rows_[a])));
  if (weight_.size() < static_cast<std::size_t>(k)) weight_.resize(k);
  for (int a = 0; a < k; ++a) {
    if (y_[a] == 0) continue;
    mpz_divexact(mp(weight_[a]), mp(L_), mp(P.scale(rows_[a])));
    mpz_mul_si(mp(weight_[a]), mp(weight_[a]), static_cast<long>(y_[a]));
  }
  for (int c = 0; c < k; ++c) {
    mpz_set_ui(mp(sum_), 0);
    for (int a = 0; a < k; ++a)
      if (y_[a] != 0) mpz_addmul(mp(sum_), mp(weight_[a]), mp(P.entry(rows_[a], vars_[c])));
    if (mpz_sgn(mp(sum_)) != 0) return false;
  }
  return true;
}

}  // namespace fixel::internal
