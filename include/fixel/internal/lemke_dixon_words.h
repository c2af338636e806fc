#pragma once
// The machine-word arithmetic of the p-adic lifting (src/lemke_dixon.cpp):
// residues modulo a prime 2^61 < p < 2^62, 128-bit words, and the block
// C triangularised modulo p (src/lemke_dixon_words.cpp). The word helpers
// (low_128, low_bits, block_in_words, the Int128 residues) read their
// operands without a branch on their signs, sizes or zeros: those follow
// no pattern a branch predictor could learn, and a mispredicted branch
// costs more than the arithmetic here (docs/performance_log.md). The GMP-path
// residue and the factoring's skip of zero multipliers still branch.
#include <flint/nmod.h>
#include <gmp.h>

#include <cstdint>
#include <vector>

#include "fixel/rational.h"

namespace fixel::internal {

// Signed and unsigned 128-bit words (a GCC and Clang extension).
__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;

// The word path's bounds. With |C(a, j)| < 2^59, |y_a| < 2^125 and k ≤ 16,
// every residual of the lifting stays a signed 128-bit integer: before the
// division by p, |r − Σ_j C(a, j)·digit_j| < 2^125 + 16·2^59·2^62 = 2^126,
// and after it (p > 2^61) |r| < 2^65.
constexpr int kWordRows = 16;
constexpr mp_limb_t kWordEntry = mp_limb_t(1) << 59;

// |z| modulo 2^128 (its two low limbs).
inline UInt128 low_128(mpz_srcptr z) {
  // A select of pointers, then the loads: a zero has no limb to read.
  static const mp_limb_t zero = 0;
  const int size = z->_mp_size;
  const mp_limb_t low = *(size != 0 ? z->_mp_d : &zero);
  const mp_limb_t high = *(size > 1 || size < -1 ? z->_mp_d + 1 : &zero);
  return (static_cast<UInt128>(high) << 64) | low;
}

// z modulo 2^128, as two's complement.
inline UInt128 low_bits(mpz_srcptr z) {
  const UInt128 negative = z->_mp_size < 0 ? ~UInt128(0) : 0;
  return (low_128(z) ^ negative) - negative;
}

// C (k×k, row-major) and y as words, when every |C(a, j)| < 2^59 and
// |y_a| < 2^125 and k ≤ 16; false otherwise, with the outputs unspecified.
bool block_in_words(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y,
                    std::vector<std::int64_t>& c_words, std::vector<Int128>& y_words);
// y alone as words, when every |y_a| < 2^125 and k ≤ 16 (C's entries known
// to be words already); false otherwise, y_words unspecified.
bool rhs_in_words(int k, const std::vector<const Integer*>& y, std::vector<Int128>& y_words);

// x mod p in [0, p), for |x| < 2^125.
inline mp_limb_t residue(Int128 x, nmod_t mod) {
  const UInt128 negative = static_cast<UInt128>(x >> 127);  // all ones for x < 0
  const UInt128 m = (static_cast<UInt128>(x) ^ negative) - negative;
  mp_limb_t r;
  NMOD_RED2(r, static_cast<mp_limb_t>(m >> 64), static_cast<mp_limb_t>(m), mod);  // high word < 2^61 < p
  const mp_limb_t flip = static_cast<mp_limb_t>(negative) & (mp_limb_t(0) - static_cast<mp_limb_t>(r != 0));
  return r ^ ((r ^ (mod.n - r)) & flip);  // p − r for x < 0 and r ≠ 0
}

// x/p into q when the odd p divides x, for |x| < 2^126: q = x·p⁻¹ mod 2^128
// (`inverse`, inverse_mod_2_128) is x/p exactly when |q| ≤ ⌊2^126/p⌋
// (`bound`): then q·p ≡ x mod 2^128 and |q·p − x| < 2^127, so q·p = x;
// when p ∤ x, |q| is larger. False when p ∤ x. Two products and a
// comparison, where a residue mod p would take a reduction.
inline bool exact_quotient(Int128 x, UInt128 inverse, UInt128 bound, Int128& q) {
  q = static_cast<Int128>(static_cast<UInt128>(x) * inverse);
  const UInt128 negative = static_cast<UInt128>(q >> 127);
  return ((static_cast<UInt128>(q) ^ negative) - negative) <= bound;
}

// x mod p in [0, p), for any integer x.
mp_limb_t residue(const Integer& x, nmod_t mod);

// x mod p in [0, p), for any 128-bit x.
inline mp_limb_t reduce_128(UInt128 x, nmod_t mod) {
  mp_limb_t high = static_cast<mp_limb_t>(x >> 64), r;
  NMOD_RED(high, high, mod);
  NMOD_RED2(r, high, static_cast<mp_limb_t>(x), mod);
  return r;
}

// (a·b + c·e) mod p, for a, b, c, e ≤ p.
inline mp_limb_t mul_add_mod(mp_limb_t a, mp_limb_t b, mp_limb_t c, mp_limb_t e, nmod_t mod) {
  // Both products are below 2^124 (p < 2^62), their sum below 2^125: its
  // high word is below p, so one reduction serves both.
  const UInt128 x = static_cast<UInt128>(a) * b + static_cast<UInt128>(c) * e;
  mp_limb_t r;
  NMOD_RED2(r, static_cast<mp_limb_t>(x >> 64), static_cast<mp_limb_t>(x), mod);
  return r;
}

// Numbers modulo p^s as their s base-p digits, least first: the
// reconstruction's products and sums modulo M = p^s without a division by
// M (src/lemke_dixon.cpp), for s ≤ kPadicDigits lifting steps.
constexpr int kPadicDigits = 4;

// x mod p^s's digits, for x ≥ 0 and 1 ≤ s ≤ kPadicDigits.
void padic_digits(mpz_srcptr x, int s, nmod_t mod, mp_limb_t* digits);

// a·b mod p^s's digits, from a's and b's (each s digits below p).
void padic_product(const mp_limb_t* a, const mp_limb_t* b, int s, nmod_t mod, mp_limb_t* out);

// Σ_j (j + 1)·x_j mod p^s's digits, for k ≤ 2^20 numbers x_j whose digit t
// is digits[t·k + j] (each below p).
void padic_weighted_sum(const mp_limb_t* digits, int k, int s, nmod_t mod, mp_limb_t* out);

// Σ_t digits_t·p^t into `out` (0 ≤ out < p^s), for digits below p.
void from_padic(const mp_limb_t* digits, int s, nmod_t mod, Integer& out);

// Σ_c a_c·u_c into `sum`, in words: each a_c one limb below 2^63, each
// u_c two limbs below 2^127 (the products are below 2^190, and k ≤ 16 of
// them below 2^194, summed in 256 bits). False, with `sum` unspecified,
// when an operand is larger or k > 16: then GMP must do it.
bool dot_in_words(int k, const mpz_srcptr* a, const std::vector<Integer>& u, Integer& sum);

// 1/x modulo 2^128, for odd x.
UInt128 inverse_mod_2_128(UInt128 x);

// num/den in lowest terms into q, for num ≠ 0 and den > 0 of at most two
// limbs each: the odd parts' gcd by GMP's mpn_gcd (or mpn_gcd_1), and both
// exact divisions by it as products with its inverse modulo 2^128, with
// none of mpz_gcd's and mpz_divexact's general-size work. False, q
// untouched, for other operands: then GMP must do it.
bool lowest_terms_in_words(mpz_srcptr num, mpz_srcptr den, mpq_ptr q);

// A k×k integer matrix C triangularised modulo p, for solving C·x ≡ r
// (mod p) again and again: division-free elimination (row r ← U_cc·row r −
// C_rc·row c, the multipliers C_rc kept below the diagonal), the pivots'
// inverses from one modular inversion (Montgomery's batch trick).
class ModularLu {
 public:
  // C modulo p from words (|C(a, j)| < p), or from integers. False if C is
  // singular modulo p; then solve() must not be called.
  bool factor(int k, const std::vector<std::int64_t>& c_words, nmod_t mod);
  bool factor(int k, const std::vector<const Integer*>& c, nmod_t mod);
  // digit = C⁻¹·rhs mod p (rhs, k residues, is overwritten).
  void solve(std::vector<mp_limb_t>& rhs, std::vector<mp_limb_t>& digit) const;

 private:
  bool eliminate();
  std::size_t at(int a, int j) const { return static_cast<std::size_t>(a) * k_ + j; }

  int k_ = 0;
  nmod_t mod_{};
  std::vector<mp_limb_t> lu_, inverse_pivot_;
  std::vector<int> swaps_;
};

}  // namespace fixel::internal
