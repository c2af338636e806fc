#pragma once
// The LCP's tableau data scaled to integers, shared by the filtered Lemke
// run (src/lemke_filtered.cpp) and its tie certificates (src/lemke_tie.cpp).
#include <gmp.h>

#include <cstddef>
#include <vector>

#include "fixel/rational.h"

namespace fixel::internal {

// In-place GMP on Integer storage: the loops reuse each value's limbs
// instead of allocating a temporary per operation (Integer has no
// expression templates), which was most of their cost.
inline mpz_ptr mp(Integer& x) { return x.backend().data(); }
inline mpz_srcptr mp(const Integer& x) { return x.backend().data(); }

// [A | b] = [I, −B, −e | b] with equation i scaled by L_i > 0, the lcm of
// the denominators of B's row i and b_i: every entry an integer. Scaling an
// equation changes no solution of the systems the runs solve.
class ScaledProblem {
 public:
  void assign(const MatrixQ& B, const VectorQ& b) {
    n_ = static_cast<int>(b.size());
    width_ = 2 * n_ + 2;
    A_.resize(static_cast<std::size_t>(n_) * width_);
    scale_.resize(n_);
    Integer factor;
    for (int i = 0; i < n_; ++i) {
      Integer& L = scale_[i];
      mpz_set(mp(L), mpq_denref(b[i].backend().data()));
      for (int j = 0; j < n_; ++j) {
        mpz_srcptr q = mpq_denref(B(i, j).backend().data());
        if (!mpz_divisible_p(mp(L), q)) mpz_lcm(mp(L), mp(L), q);  // denominators repeat
      }
      for (int var = 0; var < n_; ++var) mpz_set_ui(mp(at(i, var)), 0);
      mpz_set(mp(at(i, i)), mp(L));
      for (int j = 0; j < n_; ++j) {
        scaled(at(i, n_ + j), B(i, j), L, factor);
        mpz_neg(mp(at(i, n_ + j)), mp(at(i, n_ + j)));
      }
      mpz_neg(mp(at(i, 2 * n_)), mp(L));
      scaled(at(i, 2 * n_ + 1), b[i], L, factor);
    }
  }

  int n() const { return n_; }
  const Integer& scale(int i) const { return scale_[i]; }
  // L_i · (i, var) of [A | b]; var 0..n−1 w, n..2n−1 z, 2n z0, 2n+1 b.
  const Integer& entry(int i, int var) const { return A_[static_cast<std::size_t>(i) * width_ + var]; }

 private:
  Integer& at(int i, int var) { return A_[static_cast<std::size_t>(i) * width_ + var]; }
  static void scaled(Integer& out, const Rational& x, const Integer& L, Integer& factor) {
    const auto* q = x.backend().data();
    mpz_divexact(mp(factor), mp(L), mpq_denref(q));
    mpz_mul(mp(out), mpq_numref(q), mp(factor));
  }

  int n_ = 0, width_ = 0;
  std::vector<Integer> A_;
  std::vector<Integer> scale_;
};

}  // namespace fixel::internal
