#include "fixel/internal/lemke_dixon_words.h"

#include <flint/ulong_extras.h>

#include <cstdint>
#include <utility>

#include "fixel/internal/lemke_scaled.h"

namespace fixel::internal {

// A prepared matrix's words are handed to the lifting unchecked: both must
// mean the same bound.
static_assert(ScaledMatrix::kWordBound == kWordEntry, "the word copy's bound is the lifting's");

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
  return rhs_in_words(k, y, y_words);
}

bool rhs_in_words(int k, const std::vector<const Integer*>& y, std::vector<Int128>& y_words) {
  if (k > kWordRows || y.size() != static_cast<std::size_t>(k)) return false;
  mp_limb_t too_large = 0;
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

bool dot_in_words(int k, const mpz_srcptr* a, const std::vector<Integer>& u, Integer& sum) {
  if (k > kWordRows || u.size() < static_cast<std::size_t>(k)) return false;
  std::uint64_t limb[4] = {0, 0, 0, 0};  // the sum, two's complement mod 2^256
  mp_limb_t too_large = 0;
  for (int c = 0; c < k; ++c) {
    const mpz_srcptr x = a[c], y = mp(u[c]);
    too_large |= static_cast<mp_limb_t>(x->_mp_size > 1 || x->_mp_size < -1) |
                 static_cast<mp_limb_t>(y->_mp_size > 2 || y->_mp_size < -2);
    const std::uint64_t a_abs = static_cast<std::uint64_t>(low_128(x));
    const UInt128 u_abs = low_128(y);
    too_large |= static_cast<mp_limb_t>(a_abs >> 63) | static_cast<mp_limb_t>(u_abs >> 127);
    // |a·u| in three limbs, then added or (by the mask) subtracted.
    const UInt128 low = static_cast<UInt128>(a_abs) * static_cast<std::uint64_t>(u_abs);
    const UInt128 high = static_cast<UInt128>(a_abs) * static_cast<std::uint64_t>(u_abs >> 64);
    const UInt128 middle = (low >> 64) + static_cast<std::uint64_t>(high);
    const std::uint64_t product[4] = {static_cast<std::uint64_t>(low), static_cast<std::uint64_t>(middle),
                                      static_cast<std::uint64_t>(high >> 64) + static_cast<std::uint64_t>(middle >> 64),
                                      0};
    const std::uint64_t negative = (x->_mp_size < 0) != (y->_mp_size < 0) ? ~std::uint64_t(0) : 0;
    UInt128 carry = negative & 1;  // −m = ~m + 1
    for (int l = 0; l < 4; ++l) {
      carry += static_cast<UInt128>(limb[l]) + (product[l] ^ negative);
      limb[l] = static_cast<std::uint64_t>(carry);
      carry >>= 64;
    }
  }
  if (too_large != 0) return false;
  const std::uint64_t negative = (limb[3] >> 63) != 0 ? ~std::uint64_t(0) : 0;
  UInt128 carry = negative & 1;
  mp_limb_t* out = mpz_limbs_write(mp(sum), 4);
  int size = 0;
  for (int l = 0; l < 4; ++l) {
    carry += limb[l] ^ negative;
    out[l] = static_cast<mp_limb_t>(carry);
    carry >>= 64;
    if (out[l] != 0) size = l + 1;
  }
  mpz_limbs_finish(mp(sum), negative != 0 ? -size : size);
  return true;
}

namespace {

// q = ⌊c/p⌋ and r = c mod p, for c < p·2^64 (its high word below p, so q is
// one word): FLINT's preinverted division on the normalised divisor.
inline void divide_by_p(UInt128 c, nmod_t mod, mp_limb_t& q, mp_limb_t& r) {
  const auto high = static_cast<mp_limb_t>(c >> 64), low = static_cast<mp_limb_t>(c);
  const mp_limb_t shifted_high = (high << mod.norm) + r_shift(low, FLINT_BITS - mod.norm);
  udiv_qrnnd_preinv(q, r, shifted_high, low << mod.norm, mod.n << mod.norm, mod.ninv);
  r >>= mod.norm;
}

}  // namespace

void padic_digits(mpz_srcptr x, int s, nmod_t mod, mp_limb_t* digits) {
  thread_local Integer rest;
  mpz_set(mp(rest), x);
  for (int t = 0; t < s; ++t) digits[t] = mpz_fdiv_q_ui(mp(rest), mp(rest), mod.n);
}

void padic_product(const mp_limb_t* a, const mp_limb_t* b, int s, nmod_t mod, mp_limb_t* out) {
  // Column t of the schoolbook product plus the carry is below
  // (t + 1)·p² + t·p < 2^126 (p < 2^62, t ≤ 3): a 128-bit word, and for
  // t ≤ 2 its high word is below 3p/4 + 1 < p. The last column's carry
  // falls outside p^s: only its residue is kept.
  UInt128 carry = 0;
  for (int t = 0; t < s; ++t) {
    UInt128 column = carry;
    for (int i = 0; i <= t; ++i) column += static_cast<UInt128>(a[i]) * b[t - i];
    if (t + 1 == s) {
      out[t] = reduce_128(column, mod);
      break;
    }
    mp_limb_t q = 0;
    divide_by_p(column, mod, q, out[t]);
    carry = q;
  }
}

void padic_weighted_sum(const mp_limb_t* digits, int k, int s, nmod_t mod, mp_limb_t* out) {
  // Column t is below k(k + 1)/2·p + carry < 2^40·p: its high word < p.
  UInt128 carry = 0;
  for (int t = 0; t < s; ++t) {
    UInt128 column = carry;
    const mp_limb_t* row = digits + static_cast<std::size_t>(t) * k;
    for (int j = 0; j < k; ++j) column += static_cast<UInt128>(row[j]) * static_cast<mp_limb_t>(j + 1);
    mp_limb_t q = 0;
    divide_by_p(column, mod, q, out[t]);
    carry = q;
  }
}

void from_padic(const mp_limb_t* digits, int s, nmod_t mod, Integer& out) {
  // Horner's rule on limbs: below p^s < 2^(62s), so s + 1 limbs suffice.
  mp_limb_t value[kPadicDigits + 1] = {digits[s - 1]};
  mp_size_t size = 1;
  for (int t = s - 2; t >= 0; --t) {
    const mp_limb_t high = mpn_mul_1(value, value, size, mod.n);
    if (high != 0) value[size++] = high;
    if (mpn_add_1(value, value, size, digits[t]) != 0) value[size++] = 1;
  }
  while (size > 0 && value[size - 1] == 0) --size;
  mp_limb_t* limbs = mpz_limbs_write(mp(out), size > 0 ? size : 1);
  for (mp_size_t l = 0; l < size; ++l) limbs[l] = value[l];
  mpz_limbs_finish(mp(out), size);
}

UInt128 inverse_mod_2_128(UInt128 x) {
  // Newton's iteration: each step doubles the correct low bits. From 5
  // ((3x) xor 2 is 1/x mod 32 for odd x), four steps in 64-bit words give
  // 1/x mod 2^64 (80 bits), and one in 128 bits the rest.
  const auto low = static_cast<std::uint64_t>(x);
  std::uint64_t inverse = (3 * low) ^ 2;
  for (int i = 0; i < 4; ++i) inverse *= 2 - low * inverse;
  const UInt128 wide = inverse;
  return wide * (2 - x * wide);
}

namespace {

int trailing_zeros(UInt128 x) {  // x ≠ 0
  const auto low = static_cast<mp_limb_t>(x);
  return low != 0 ? __builtin_ctzl(low) : 64 + __builtin_ctzl(static_cast<mp_limb_t>(x >> 64));
}

// x ≠ 0 into z's limbs, with the sign `negative`.
void set_word(mpz_ptr z, UInt128 x, bool negative) {
  const auto high = static_cast<mp_limb_t>(x >> 64);
  const int size = high != 0 ? 2 : 1;
  mp_limb_t* limbs = mpz_limbs_write(z, size);
  limbs[0] = static_cast<mp_limb_t>(x);
  if (high != 0) limbs[1] = high;
  mpz_limbs_finish(z, negative ? -size : size);
}

}  // namespace

bool lowest_terms_in_words(mpz_srcptr num, mpz_srcptr den, mpq_ptr q) {
  const int num_size = num->_mp_size, den_size = den->_mp_size;
  if (num_size == 0 || num_size > 2 || num_size < -2 || den_size <= 0 || den_size > 2) return false;
  const UInt128 a = low_128(num), b = low_128(den);
  // gcd(a, b) = 2^min(s, t)·gcd(a/2^s, b/2^t), the latter of odd numbers
  // (mpn_gcd wants an odd operand, and the longer one first).
  const int a_twos = trailing_zeros(a), b_twos = trailing_zeros(b);
  const int twos = a_twos < b_twos ? a_twos : b_twos;
  const UInt128 a_odd = a >> a_twos, b_odd = b >> b_twos;
  mp_limb_t x[2] = {static_cast<mp_limb_t>(a_odd), static_cast<mp_limb_t>(a_odd >> 64)};
  mp_limb_t y[2] = {static_cast<mp_limb_t>(b_odd), static_cast<mp_limb_t>(b_odd >> 64)};
  const mp_size_t x_size = x[1] != 0 ? 2 : 1, y_size = y[1] != 0 ? 2 : 1;
  UInt128 g_odd = 0;
  if (y_size == 1) {
    g_odd = mpn_gcd_1(x, x_size, y[0]);
  } else if (x_size == 1) {
    g_odd = mpn_gcd_1(y, y_size, x[0]);
  } else {
    mp_limb_t g[2] = {0, 0};
    const mp_size_t g_size = mpn_gcd(g, x, 2, y, 2);  // destroys x and y
    g_odd = g_size == 2 ? (static_cast<UInt128>(g[1]) << 64) | g[0] : g[0];
  }
  // a/g and b/g: exact, so the product with 1/g_odd modulo 2^128 is the
  // quotient itself (it is below 2^128).
  UInt128 a_reduced = a >> twos, b_reduced = b >> twos;
  if (g_odd != 1) {
    const UInt128 inverse = inverse_mod_2_128(g_odd);
    a_reduced *= inverse;
    b_reduced *= inverse;
  }
  set_word(mpq_numref(q), a_reduced, num_size < 0);
  set_word(mpq_denref(q), b_reduced, false);
  return true;
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
