#pragma once
// The LCP's tableau data scaled to integers, shared by the filtered Lemke
// run (src/lemke_filtered.cpp, its exact side src/lemke_exact.cpp) and its
// tie certificates (src/lemke_tie.cpp).
#include <gmp.h>

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "fixel/rational.h"

namespace fixel::internal {

// In-place GMP on Integer storage: the loops reuse each value's limbs
// instead of allocating a temporary per operation (Integer has no
// expression templates), which was most of their cost.
inline mpz_ptr mp(Integer& x) { return x.backend().data(); }
inline mpz_srcptr mp(const Integer& x) { return x.backend().data(); }

// B's part of the scaled tableau: row i of [−B, −e] times L_i > 0, the lcm
// of the denominators of B's row i. It depends on B alone, so a prepared
// matrix (LemkeMatrix) keeps one for all its solves.
class ScaledMatrix {
 public:
  void assign(const MatrixQ& B) {
    n_ = static_cast<int>(B.rows());
    width_ = n_ + 1;  // the z columns and z0's
    A_.resize(static_cast<std::size_t>(n_) * width_);
    scale_.resize(n_);
    word_factors_.resize(n_);
    words_row_ = -1;
    for (int i = 0; i < n_; ++i) {
      Integer& L = scale_[i];
      if (!scale_row_like_previous(B, i) && !scale_row_in_words(B, i)) {
        mpz_set_ui(mp(L), 1);
        for (int j = 0; j < n_; ++j) {
          mpz_srcptr q = mpq_denref(B(i, j).backend().data());
          if (!mpz_divisible_p(mp(L), q)) mpz_lcm(mp(L), mp(L), q);  // denominators repeat
        }
        for (int j = 0; j < n_; ++j) {
          scaled(at(i, n_ + j), B(i, j), L, factor_);
          mpz_neg(mp(at(i, n_ + j)), mp(at(i, n_ + j)));
        }
      }
      mpz_neg(mp(at(i, 2 * n_)), mp(L));
    }
    keep_words();
  }

  int n() const { return n_; }
  // Whether every entry and every L_i is below kWordBound in magnitude: the
  // word path of the final values' lifting (internal/lemke_dixon_words.h),
  // whose block then comes from word() without a conversion per solve.
  bool in_words() const { return in_words_; }
  // The lifting's bound on a word entry (kWordEntry there, checked equal).
  static constexpr mp_limb_t kWordBound = mp_limb_t(1) << 59;
  // entry(i, var) as a word, for var n..2n, when in_words().
  std::int64_t word(int i, int var) const { return words_[static_cast<std::size_t>(i) * width_ + (var - n_)]; }
  // L_i.
  const Integer& scale(int i) const { return scale_[i]; }
  // L_i · (i, var) for var n..2n−1 (z) and 2n (z0).
  const Integer& entry(int i, int var) const { return A_[static_cast<std::size_t>(i) * width_ + (var - n_)]; }

 private:
  Integer& at(int i, int var) { return A_[static_cast<std::size_t>(i) * width_ + (var - n_)]; }  // var ≥ n

  // Row i scaled with the factors of row i − 1 when that row was scaled in
  // words and B's row i has its denominators, one by one (the seating
  // LCPs' friction rows come in pairs): no division. False, nothing
  // written, otherwise.
  bool scale_row_like_previous(const MatrixQ& B, int i) {
    if (words_row_ != i - 1 || i == 0) return false;
    for (int j = 0; j < n_; ++j)
      if (mpz_cmp(mpq_denref(B(i, j).backend().data()), mpq_denref(B(i - 1, j).backend().data())) != 0) return false;
    mpz_set(mp(scale_[i]), mp(scale_[i - 1]));
    for (int j = 0; j < n_; ++j) {
      mpz_mul_ui(mp(at(i, n_ + j)), mpq_numref(B(i, j).backend().data()), word_factors_[j]);
      mpz_neg(mp(at(i, n_ + j)), mp(at(i, n_ + j)));
    }
    words_row_ = i;
    return true;
  }
  // The common case, B's row i with denominators whose lcm fits in 64 bits:
  // L_i and each factor L_i/den in machine words, one mpz_mul_ui per entry.
  // False (nothing written) when a denominator or the lcm does not fit.
  // Denominators repeat along a row (and zeros have 1), so the last one
  // seen is remembered: a hardware division costs tens of cycles.
  bool scale_row_in_words(const MatrixQ& B, int i) {
    unsigned long L = 1, last = 1;
    for (int j = 0; j < n_; ++j) {
      mpz_srcptr q = mpq_denref(B(i, j).backend().data());
      if (!mpz_fits_ulong_p(q)) return false;
      const unsigned long d = mpz_get_ui(q);
      if (d == 1 || d == last || L % d == 0) {  // L only grows: a divisor stays one
        last = d;
        continue;
      }
      if (__builtin_mul_overflow(L / std::gcd(L, d), d, &L)) return false;
      last = d;
    }
    mpz_set_ui(mp(scale_[i]), L);
    unsigned long d_last = 1, factor = L;  // L / d_last
    for (int j = 0; j < n_; ++j) {
      const auto* q = B(i, j).backend().data();
      const unsigned long d = mpz_get_ui(mpq_denref(q));
      if (d != d_last) {
        d_last = d;
        factor = d == 1 ? L : L / d;
      }
      word_factors_[j] = factor;  // L / den(B(i, j)), for a next row with these denominators
      mpz_mul_ui(mp(at(i, n_ + j)), mpq_numref(q), factor);
      mpz_neg(mp(at(i, n_ + j)), mp(at(i, n_ + j)));
    }
    words_row_ = i;
    return true;
  }

  // words_ from A_, and in_words_.
  void keep_words() {
    words_.resize(A_.size());
    in_words_ = true;
    for (std::size_t e = 0; e < A_.size() && in_words_; ++e) in_words_ = word_of(mp(A_[e]), words_[e]);
    for (int i = 0; i < n_ && in_words_; ++i) {
      std::int64_t ignored = 0;
      in_words_ = word_of(mp(scale_[i]), ignored);
    }
  }
  // z as a word when |z| < kWordBound.
  static bool word_of(mpz_srcptr z, std::int64_t& out) {
    if (mpz_size(z) > 1 || mpz_getlimbn(z, 0) >= kWordBound) return false;
    const auto magnitude = static_cast<std::int64_t>(mpz_getlimbn(z, 0));
    out = mpz_sgn(z) < 0 ? -magnitude : magnitude;
    return true;
  }
  static void scaled(Integer& out, const Rational& x, const Integer& L, Integer& factor) {
    const auto* q = x.backend().data();
    mpz_divexact(mp(factor), mp(L), mpq_denref(q));
    mpz_mul(mp(out), mpq_numref(q), mp(factor));
  }

  int n_ = 0, width_ = 0;
  std::vector<Integer> A_;
  std::vector<Integer> scale_;
  Integer factor_;
  std::vector<unsigned long> word_factors_;  // of row words_row_, the last row scaled in words (−1: none)
  int words_row_ = -1;
  std::vector<std::int64_t> words_;  // A_ as words, when in_words_
  bool in_words_ = false;
};

// [A | b] = [I, −B, −e | b] with equation i scaled by L_i > 0, the lcm of
// the denominators of B's row i, and the b column also by δ > 0, the lcm of
// the denominators of the L_i·b_i: every entry an integer. Scaling an
// equation changes no solution of the systems the runs solve, and scaling
// the b column by δ scales every basic value by δ. b's denominators are
// kept out of the L_i on purpose: on the seating LCPs they are 25–30 bits
// larger than B's on the friction rows, and the same few bits for every
// row, so one δ is much smaller than their share of every L_i.
//
// B's part is its own ScaledMatrix, or a prepared one it points to, which
// must then outlive every use of this problem until the next assign.
class ScaledProblem {
 public:
  ScaledProblem() = default;
  ScaledProblem(const ScaledProblem&) = delete;  // matrix_ may point into *this
  ScaledProblem& operator=(const ScaledProblem&) = delete;

  void assign(const MatrixQ& B, const VectorQ& b) {
    own_.assign(B);
    matrix_ = &own_;
    assign_rhs(b);
  }
  // B's part prepared already (the same B as a ScaledMatrix::assign(B)).
  void assign(const ScaledMatrix& prepared, const VectorQ& b) {
    matrix_ = &prepared;
    assign_rhs(b);
  }

  int n() const { return n_; }
  // L_i.
  const Integer& scale(int i) const { return matrix_->scale(i); }
  // δ, the b column's own factor.
  const Integer& rhs_factor() const { return delta_; }
  // L_i · (i, var) of [A | b], times δ for var = b; var 0..n−1 w, n..2n−1 z,
  // 2n z0, 2n+1 b.
  const Integer& entry(int i, int var) const {
    if (var < n_) return var == i ? matrix_->scale(i) : zero_;
    if (var == 2 * n_ + 1) return rhs_[i];
    return matrix_->entry(i, var);
  }
  // Whether entry(i, var) is below 2^59 for every var ≤ 2n (not b's) and
  // every i: then word(i, var) gives it.
  bool in_words() const { return matrix_->in_words(); }
  std::int64_t word(int i, int var) const {
    if (var < n_) return var == i ? static_cast<std::int64_t>(mpz_getlimbn(mp(matrix_->scale(i)), 0)) : 0;
    return matrix_->word(i, var);
  }

 private:
  void assign_rhs(const VectorQ& b) {
    n_ = static_cast<int>(b.size());
    rhs_.resize(n_);
    if (assign_rhs_in_words(b)) return;
    Integer& factor = factor_;
    mpz_set_ui(mp(delta_), 1);
    for (int i = 0; i < n_; ++i) {
      // δ: the denominator of L_i·b_i is den(b_i)/gcd(den(b_i), L_i); a
      // row with the L and den(b) of the previous one adds nothing (the
      // seating LCPs' friction rows come in such pairs, and b_i = 0 has 1).
      mpz_srcptr d = mpq_denref(b[i].backend().data());
      if (mpz_cmp_ui(d, 1) == 0 || (i > 0 && same_rhs_scaling(b, i))) continue;
      mpz_gcd(mp(factor), d, mp(scale(i)));
      mpz_divexact(mp(factor), d, mp(factor));
      if (!mpz_divisible_p(mp(delta_), mp(factor))) mpz_lcm(mp(delta_), mp(delta_), mp(factor));
    }
    for (int i = 0; i < n_; ++i) {
      // L_i·δ·b_i = num(b_i)·(L_i·δ/den(b_i)), the division exact; the
      // factor of the previous row when L and den(b) are its.
      const auto* q = b[i].backend().data();
      if (mpq_sgn(q) == 0) {
        mpz_set_ui(mp(rhs_[i]), 0);
        continue;
      }
      if (i == 0 || !same_rhs_scaling(b, i) || mpq_sgn(b[i - 1].backend().data()) == 0) {
        mpz_mul(mp(factor), mp(scale(i)), mp(delta_));
        mpz_divexact(mp(factor), mp(factor), mpq_denref(q));
      }
      mpz_mul(mp(rhs_[i]), mpq_numref(q), mp(factor));
    }
  }

  // The common case, every L_i in one limb, den(b_i) in two and δ below
  // 2^64: the same δ and L_i·δ·b_i as the general path, with word gcds
  // and divisions (GMP's calls here cost about 7% of a solve's time). False, δ and the rhs unset, when a number does
  // not fit.
  bool assign_rhs_in_words(const VectorQ& b) {
    static_assert(sizeof(unsigned long) == sizeof(mp_limb_t), "one limb is one unsigned long");
    __extension__ typedef unsigned __int128 Word2;
    word_factors_.resize(n_);
    own_denominators_.resize(n_);
    unsigned long delta = 1;
    Word2 last_den = 0;
    unsigned long last_L = 0;
    for (int i = 0; i < n_; ++i) {
      mpz_srcptr d = mpq_denref(b[i].backend().data());
      if (mpz_size(d) > 2 || mpz_size(mp(scale(i))) > 1) return false;
      const Word2 den = (static_cast<Word2>(mpz_getlimbn(d, 1)) << 64) | mpz_getlimbn(d, 0);
      const unsigned long L = mpz_get_ui(mp(scale(i)));
      // A row with the previous row's den and L (friction rows come in
      // pairs) repeats its numbers.
      if (i > 0 && den == last_den && L == last_L) {
        word_factors_[i] = word_factors_[i - 1];
        own_denominators_[i] = own_denominators_[i - 1];
        continue;
      }
      last_den = den;
      last_L = L;
      // L_i·b_i's denominator den/g and L_i/g, g = gcd(den, L_i): the
      // factor L_i·δ/den is (L_i/g)·(δ/(den/g)), kept until δ is known.
      const unsigned long g = den == 1 ? 1 : std::gcd(static_cast<unsigned long>(den % L), L);
      const Word2 own = den / g;
      if (own >> 64 != 0) return false;
      word_factors_[i] = L / g;
      own_denominators_[i] = static_cast<unsigned long>(own);
      if (own == 1 || delta % own_denominators_[i] == 0) continue;
      if (__builtin_mul_overflow(delta / std::gcd(delta, own_denominators_[i]), own_denominators_[i], &delta))
        return false;
    }
    mpz_set_ui(mp(delta_), delta);
    for (int i = 0; i < n_; ++i) {
      const auto* q = b[i].backend().data();
      unsigned long factor = 0;
      if (__builtin_mul_overflow(word_factors_[i], delta / own_denominators_[i], &factor)) {
        mpz_mul_ui(mp(rhs_[i]), mpq_numref(q), word_factors_[i]);
        mpz_mul_ui(mp(rhs_[i]), mp(rhs_[i]), delta / own_denominators_[i]);
      } else {
        mpz_mul_ui(mp(rhs_[i]), mpq_numref(q), factor);
      }
    }
    return true;
  }

  // Whether row i has the L and den(b) of row i − 1.
  bool same_rhs_scaling(const VectorQ& b, int i) const {
    return mpz_cmp(mp(scale(i)), mp(scale(i - 1))) == 0 &&
           mpz_cmp(mpq_denref(b[i].backend().data()), mpq_denref(b[i - 1].backend().data())) == 0;
  }

  int n_ = 0;
  ScaledMatrix own_;
  const ScaledMatrix* matrix_ = &own_;
  std::vector<Integer> rhs_;  // L_i·δ·b_i
  // The word path's L_i/g_i and den(b_i)/g_i, g_i = gcd(den(b_i), L_i).
  std::vector<unsigned long> word_factors_, own_denominators_;
  Integer delta_;
  Integer zero_;
  Integer factor_;
};

}  // namespace fixel::internal
