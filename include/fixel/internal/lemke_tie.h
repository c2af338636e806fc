#pragma once
// Exact ties of the filtered Lemke run (src/lemke_tie.cpp), proved without
// factoring the basis: a ratio tie is a 2×2 minor of the tableau, which
// vanishes iff one n×n matrix of columns of [A | b] is singular, and the
// seating LCPs' ties are singular through small-integer combinations of
// rows (docs/theory.md §6). A null vector is guessed in doubles and checked
// in integers, so a "tie" is always exact; when the guess fails the caller
// decides on the exact tableau as before.
#include <vector>

#include "fixel/internal/lemke_scaled.h"

namespace fixel::internal {

// x ≈ p/q with 1 ≤ q ≤ 1024 and |x − p/q| ≤ 1e-9·max(1, |x|), the first
// such continued-fraction convergent; false if there is none (or |x| ≥ 2^20).
// Only a guess: the caller checks what it builds from it exactly.
bool small_rational(double x, long long& p, long long& q);

// Approximations of the unscaled [A | b] = [I, −B, −e | b]: `slots` holds
// n rows of n + 2 doubles (−B, then −1, then b); the w columns are exact.
struct ApproxProblem {
  const double* slots = nullptr;
  int n = 0;
  double at(int i, int var) const {
    if (var < n) return var == i ? 1.0 : 0.0;
    return slots[static_cast<std::size_t>(i) * (n + 2) + (var - n)];
  }
};

// Scratch storage reused from call to call (one per thread).
class TieCertifier {
 public:
  // Whether the n×n matrix A_β of the columns β of [A | b] (variables
  // numbered as in ScaledProblem::entry) is singular, proved by a vector
  // y ≠ 0 with yᵀ A_β = 0 exactly. False means "not proved", never
  // "nonsingular".
  bool singular(const std::vector<int>& beta, const ApproxProblem& approx, const ScaledProblem& P);

 private:
  std::vector<char> in_beta_;
  std::vector<int> rows_, vars_, perm_;
  std::vector<double> M_, x_;
  std::vector<long long> num_, den_, y_;
  std::vector<Integer> weight_;
  Integer L_, sum_;
};

}  // namespace fixel::internal
