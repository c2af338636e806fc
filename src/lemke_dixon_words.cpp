#include "fixel/internal/lemke_dixon_words.h"

#include <flint/ulong_extras.h>

#include <utility>

#include "fixel/internal/lemke_scaled.h"

namespace fixel::internal {

bool block_in_words(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y,
                    std::vector<std::int64_t>& c_words, std::vector<Int128>& y_words) {
  if (k > kWordRows || c.size() != static_cast<std::size_t>(k) * k || y.size() != static_cast<std::size_t>(k))
    return false;
  c_words.resize(c.size());
  mp_limb_t too_large = 0;  // any limb count above 1, or magnitude at or above 2^59
  for (std::size_t e = 0; e < c.size(); ++e) {
    const mpz_srcptr z = mp(*c[e]);
    const int size = z->_mp_size;
    const mp_limb_t m = static_cast<mp_limb_t>(low_128(z));
    too_large |= static_cast<mp_limb_t>(size > 1 || size < -1) | static_cast<mp_limb_t>(m >= kWordEntry);
    const std::int64_t negative = size < 0 ? -1 : 0;  // a mask
    c_words[e] = (static_cast<std::int64_t>(m) ^ negative) - negative;
  }
  if (too_large != 0) return false;
  y_words.resize(k);
  for (int a = 0; a < k; ++a) {
    const mpz_srcptr z = mp(*y[a]);
    if (mpz_size(z) > 2) return false;
    const UInt128 m = low_128(z);
    too_large |= static_cast<mp_limb_t>(m >> 125 != 0);
    const Int128 negative = z->_mp_size < 0 ? -1 : 0;
    y_words[a] = (static_cast<Int128>(m) ^ negative) - negative;
  }
  return too_large == 0;
}

mp_limb_t residue(const Integer& x, nmod_t mod) {
  // Limb by limb with FLINT's preinverted reduction (no hardware division).
  const mpz_srcptr z = mp(x);
  mp_limb_t r = 0;
  for (std::size_t i = mpz_size(z); i-- > 0;) NMOD_RED2(r, r, mpz_getlimbn(z, i), mod);
  return mpz_sgn(z) < 0 ? nmod_neg(r, mod) : r;
}

UInt128 inverse_mod_2_128(std::uint64_t p) {
  // Newton's iteration: each step doubles the correct low bits, from 3
  // (p·p ≡ 1 mod 8 for odd p).
  UInt128 inverse = p;
  for (int i = 0; i < 6; ++i) inverse *= 2 - p * inverse;
  return inverse;
}

bool ModularLu::factor(int k, const std::vector<std::int64_t>& c_words, nmod_t mod) {
  k_ = k;
  mod_ = mod;
  lu_.resize(static_cast<std::size_t>(k) * k);
  for (std::size_t e = 0; e < lu_.size(); ++e) {
    const std::int64_t x = c_words[e];  // |x| < p: p added to a negative x, by a mask
    lu_[e] = static_cast<mp_limb_t>(x) + (static_cast<mp_limb_t>(x >> 63) & mod.n);
  }
  return eliminate();
}

bool ModularLu::factor(int k, const std::vector<const Integer*>& c, nmod_t mod) {
  k_ = k;
  mod_ = mod;
  lu_.resize(static_cast<std::size_t>(k) * k);
  for (std::size_t e = 0; e < lu_.size(); ++e) lu_[e] = residue(*c[e], mod);
  return eliminate();
}

bool ModularLu::eliminate() {
  const int k = k_;
  inverse_pivot_.resize(k);
  swaps_.resize(k);
  for (int col = 0; col < k; ++col) {
    int p = col;
    while (p < k && lu_[at(p, col)] == 0) ++p;
    if (p == k) return false;
    swaps_[col] = p;
    if (p != col)
      for (int j = 0; j < k; ++j) std::swap(lu_[at(p, j)], lu_[at(col, j)]);
    const mp_limb_t pivot = lu_[at(col, col)];
    for (int r = col + 1; r < k; ++r) {
      const mp_limb_t f = lu_[at(r, col)];
      if (f == 0) continue;  // row r already eliminated: left unscaled
      const mp_limb_t minus_f = mod_.n - f;
      for (int j = col + 1; j < k; ++j)
        lu_[at(r, j)] = mul_add_mod(pivot, lu_[at(r, j)], minus_f, lu_[at(col, j)], mod_);
    }
  }
  // inverse_pivot[c] = 1/U_cc: prefix products, one inverse, then back.
  mp_limb_t product = 1;
  for (int col = 0; col < k; ++col) {
    inverse_pivot_[col] = product;  // U_00 ⋯ U_(c−1)(c−1)
    product = nmod_mul(product, lu_[at(col, col)], mod_);
  }
  mp_limb_t inverse = n_invmod(product, mod_.n);  // a product of nonzero residues mod a prime
  for (int col = k; col-- > 0;) {
    inverse_pivot_[col] = nmod_mul(inverse_pivot_[col], inverse, mod_);
    inverse = nmod_mul(inverse, lu_[at(col, col)], mod_);
  }
  return true;
}

void ModularLu::solve(std::vector<mp_limb_t>& rhs, std::vector<mp_limb_t>& digit) const {
  const int k = k_;
  digit.resize(k);
  // The swaps first, then the eliminations: the stored multipliers moved
  // with their rows at every later swap (as in LAPACK's getrs).
  for (int col = 0; col < k; ++col)
    if (swaps_[col] != col) std::swap(rhs[col], rhs[swaps_[col]]);
  for (int col = 0; col < k; ++col) {
    const mp_limb_t pivot = lu_[at(col, col)];
    for (int r = col + 1; r < k; ++r) {
      const mp_limb_t f = lu_[at(r, col)];
      if (f != 0) rhs[r] = mul_add_mod(pivot, rhs[r], mod_.n - f, rhs[col], mod_);
    }
  }
  for (int r = k; r-- > 0;) {
    // Σ_j U_rj·digit_j in 128 bits: at most 15 products below 2^124 at a
    // time, then reduced.
    UInt128 sum = 0;
    int terms = 0;
    mp_limb_t reduced = 0;
    for (int j = r + 1; j < k; ++j) {
      sum += static_cast<UInt128>(lu_[at(r, j)]) * digit[j];
      if (++terms == 15) {
        reduced = nmod_add(reduced, reduce_128(sum, mod_), mod_);
        sum = 0;
        terms = 0;
      }
    }
    reduced = nmod_add(reduced, reduce_128(sum, mod_), mod_);
    digit[r] = nmod_mul(nmod_sub(rhs[r], reduced, mod_), inverse_pivot_[r], mod_);
  }
}

}  // namespace fixel::internal
