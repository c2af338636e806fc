#include "fixel/internal/lemke_dixon.h"

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/nmod.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "fixel/internal/lemke_scaled.h"

namespace fixel::internal {

const std::vector<std::uint64_t>& dixon_primes() {
  static const std::vector<std::uint64_t> primes = [] {
    std::vector<std::uint64_t> out;
    // The largest primes below 2^62: then a one-step modulus is a small
    // fmpz for FLINT's reconstruction (no GMP integer behind it).
    for (ulong p = (UWORD(1) << 62) - 1; out.size() < 3; p -= 2)
      if (n_is_prime(p)) out.push_back(p);
    return out;
  }();
  return primes;
}

namespace {

// FLINT's fmpz and fmpq as scoped values (they own memory when large).
struct Fmpz {
  fmpz_t v;
  Fmpz() { fmpz_init(v); }
  ~Fmpz() { fmpz_clear(v); }
  Fmpz(const Fmpz&) = delete;
  Fmpz& operator=(const Fmpz&) = delete;
};
struct Fmpq {
  fmpq_t v;
  Fmpq() { fmpq_init(v); }
  ~Fmpq() { fmpq_clear(v); }
  Fmpq(const Fmpq&) = delete;
  Fmpq& operator=(const Fmpq&) = delete;
};

// Signed and unsigned 128-bit words (a GCC and Clang extension).
__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;

// Storage reused from call to call (one per thread).
struct Workspace {
  std::vector<mp_limb_t> lu, inverse_pivot, digit, rhs;
  std::vector<int> swaps;
  std::vector<Integer> residual, lifted, candidate;
  Integer modulus, half, t, combination, factor;
  // The word path's system and residual (words() below).
  std::vector<std::int64_t> c_words;
  std::vector<Int128> y_words, residual_words;
};

std::atomic<bool> g_words_allowed{true};

// The word path. With |C(a, j)| < 2^59, |y_a| < 2^125 and k ≤ 16, every
// residual stays a signed 128-bit integer: before the division by p,
// |r − Σ_j C(a, j)·digit_j| < 2^125 + 16·2^59·2^62 = 2^126, and after it
// (p > 2^61) |r| < 2^65. So lifting needs no GMP call at all; on the
// seating LCPs every block entry has at most 52 bits and y at most 91.
constexpr int kWordRows = 16;
constexpr mp_limb_t kWordEntry = mp_limb_t(1) << 59;

// |z| modulo 2^128, its two low limbs read without a branch on z's size:
// a select of pointers, then the loads (the sizes of the values read here
// follow no pattern a branch predictor could learn).
UInt128 low_128(mpz_srcptr z) {
  static const mp_limb_t zero = 0;
  const int size = z->_mp_size;
  const mp_limb_t low = *(size != 0 ? z->_mp_d : &zero);
  const mp_limb_t high = *(size > 1 || size < -1 ? z->_mp_d + 1 : &zero);
  return (static_cast<UInt128>(high) << 64) | low;
}

// C and y as words into ws (c_words, y_words); false, with
// nothing promised about ws, when an entry is too large or k > 16.
bool words(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y, Workspace& ws) {
  if (k > kWordRows || !g_words_allowed) return false;
  ws.c_words.resize(c.size());
  mp_limb_t too_large = 0;  // any limb count above 1, or magnitude at or above 2^59
  for (std::size_t e = 0; e < c.size(); ++e) {
    // Without a branch on the entry's sign or zeroness: the blocks' zeros
    // and signs follow no pattern a branch predictor could learn.
    const mpz_srcptr z = mp(*c[e]);
    const int size = z->_mp_size;
    const mp_limb_t m = static_cast<mp_limb_t>(low_128(z));
    too_large |= static_cast<mp_limb_t>(size > 1 || size < -1) | static_cast<mp_limb_t>(m >= kWordEntry);
    const std::int64_t negative = size < 0 ? -1 : 0;  // a mask: size >> 31 (compiles without a branch)
    ws.c_words[e] = (static_cast<std::int64_t>(m) ^ negative) - negative;
  }
  if (too_large != 0) return false;
  ws.y_words.resize(k);
  for (int a = 0; a < k; ++a) {
    const mpz_srcptr z = mp(*y[a]);
    if (mpz_size(z) > 2) return false;
    const UInt128 m = low_128(z);
    too_large |= static_cast<mp_limb_t>(m >> 125 != 0);
    const Int128 negative = z->_mp_size < 0 ? -1 : 0;
    ws.y_words[a] = (static_cast<Int128>(m) ^ negative) - negative;
  }
  return too_large == 0;
}

// x mod p in [0, p) for |x| < 2^125 (so its high word is below p > 2^61).
mp_limb_t residue(Int128 x, nmod_t mod) {
  const UInt128 negative = static_cast<UInt128>(x >> 127);  // all ones for x < 0: masks, no branch
  const UInt128 m = (static_cast<UInt128>(x) ^ negative) - negative;
  mp_limb_t r;
  NMOD_RED2(r, static_cast<mp_limb_t>(m >> 64), static_cast<mp_limb_t>(m), mod);
  const mp_limb_t flip = static_cast<mp_limb_t>(negative) & (mp_limb_t(0) - static_cast<mp_limb_t>(r != 0));
  return r ^ ((r ^ (mod.n - r)) & flip);  // p − r for x < 0 and r ≠ 0
}

// x mod p for |x| < 2^126: the high word, below 2^62 < 2p, is reduced
// first (NMOD_RED2 wants it below p).
mp_limb_t residue_below_2_126(Int128 x, nmod_t mod) {
  const UInt128 m = x < 0 ? -static_cast<UInt128>(x) : static_cast<UInt128>(x);
  mp_limb_t high = static_cast<mp_limb_t>(m >> 64), r;
  if (high >= mod.n) high -= mod.n;
  NMOD_RED2(r, high, static_cast<mp_limb_t>(m), mod);
  return r;  // zero or not, as x mod p: the sign does not matter here
}

// 1/p modulo 2^128 for odd p, by Newton's iteration (each step doubles the
// correct low bits, from 3: p·p ≡ 1 mod 8).
UInt128 inverse_mod_2_128(std::uint64_t p) {
  UInt128 inverse = p;
  for (int i = 0; i < 6; ++i) inverse *= 2 - p * inverse;
  return inverse;
}

Workspace& workspace() {
  thread_local Workspace ws;
  return ws;
}

// x mod p in [0, p), limb by limb with FLINT's preinverted reduction
// (no hardware division).
mp_limb_t residue(const Integer& x, nmod_t mod) {
  const mpz_srcptr z = mp(x);
  mp_limb_t r = 0;
  for (std::size_t i = mpz_size(z); i-- > 0;) NMOD_RED2(r, r, mpz_getlimbn(z, i), mod);
  return mpz_sgn(z) < 0 ? nmod_neg(r, mod) : r;
}

// x mod p for any 128-bit x: the high word reduced first.
mp_limb_t reduce_128(UInt128 x, nmod_t mod) {
  mp_limb_t high = static_cast<mp_limb_t>(x >> 64), r;
  NMOD_RED(high, high, mod);
  NMOD_RED2(r, high, static_cast<mp_limb_t>(x), mod);
  return r;
}

// (a·b + c·e) mod p for residues below p, 2^61 < p < 2^62: the sum of the
// two products is below 2^125, so its high word is below p and one
// reduction serves both.
mp_limb_t mul_add_mod(mp_limb_t a, mp_limb_t b, mp_limb_t c, mp_limb_t e, nmod_t mod) {
  const UInt128 x = static_cast<UInt128>(a) * b + static_cast<UInt128>(c) * e;
  mp_limb_t r;
  NMOD_RED2(r, static_cast<mp_limb_t>(x >> 64), static_cast<mp_limb_t>(x), mod);
  return r;
}

// C modulo p reduced to upper triangular U by division-free elimination
// (row r ← U_cc·row r − C_rc·row c, the multipliers C_rc kept below the
// diagonal), with the pivots' inverses from one inversion (Montgomery's
// batch trick): one n_invmod per factoring instead of k. False if C is
// singular mod p.
bool factor_mod(int k, const std::vector<const Integer*>& c, bool in_words, nmod_t mod, Workspace& ws) {
  const auto at = [k](int a, int j) { return static_cast<std::size_t>(a) * k + j; };
  ws.lu.resize(static_cast<std::size_t>(k) * k);
  ws.inverse_pivot.resize(k);
  ws.swaps.resize(k);
  if (in_words) {
    for (std::size_t e = 0; e < ws.lu.size(); ++e) {  // |C(a, j)| < 2^59 < p
      const std::int64_t x = ws.c_words[e];           // p added to a negative x, by a mask: signs are unpredictable
      ws.lu[e] = static_cast<mp_limb_t>(x) + (static_cast<mp_limb_t>(x >> 63) & mod.n);
    }
  } else {
    for (std::size_t e = 0; e < ws.lu.size(); ++e) ws.lu[e] = residue(*c[e], mod);
  }
  for (int col = 0; col < k; ++col) {
    int p = col;
    while (p < k && ws.lu[at(p, col)] == 0) ++p;
    if (p == k) return false;
    ws.swaps[col] = p;
    if (p != col)
      for (int j = 0; j < k; ++j) std::swap(ws.lu[at(p, j)], ws.lu[at(col, j)]);
    const mp_limb_t pivot = ws.lu[at(col, col)];
    for (int r = col + 1; r < k; ++r) {
      const mp_limb_t f = ws.lu[at(r, col)];
      if (f == 0) continue;  // row r already eliminated: left unscaled
      const mp_limb_t minus_f = mod.n - f;
      for (int j = col + 1; j < k; ++j)
        ws.lu[at(r, j)] = mul_add_mod(pivot, ws.lu[at(r, j)], minus_f, ws.lu[at(col, j)], mod);
    }
  }
  // inverse_pivot[c] = 1/U_cc: prefix products, one inverse, then back.
  mp_limb_t product = 1;
  for (int col = 0; col < k; ++col) {
    ws.inverse_pivot[col] = product;  // U_00 ⋯ U_(c−1)(c−1)
    product = nmod_mul(product, ws.lu[at(col, col)], mod);
  }
  mp_limb_t inverse = n_invmod(product, mod.n);  // a product of nonzero residues mod a prime
  for (int col = k; col-- > 0;) {
    ws.inverse_pivot[col] = nmod_mul(ws.inverse_pivot[col], inverse, mod);
    inverse = nmod_mul(inverse, ws.lu[at(col, col)], mod);
  }
  return true;
}

// digit = C⁻¹ rhs mod p, from factor_mod's factors (rhs is overwritten).
void solve_mod(int k, nmod_t mod, Workspace& ws) {
  const auto at = [k](int a, int j) { return static_cast<std::size_t>(a) * k + j; };
  // The swaps first, then the eliminations: the stored multipliers moved
  // with their rows at every later swap (as in LAPACK's getrs).
  for (int col = 0; col < k; ++col)
    if (ws.swaps[col] != col) std::swap(ws.rhs[col], ws.rhs[ws.swaps[col]]);
  for (int col = 0; col < k; ++col) {
    const mp_limb_t pivot = ws.lu[at(col, col)];
    for (int r = col + 1; r < k; ++r) {
      const mp_limb_t f = ws.lu[at(r, col)];
      if (f != 0) ws.rhs[r] = mul_add_mod(pivot, ws.rhs[r], mod.n - f, ws.rhs[col], mod);
    }
  }
  for (int r = k; r-- > 0;) {
    // Σ_j U_rj·digit_j in 128 bits: at most 15 products below 2^124 each
    // (k ≤ 16 on this path; longer rows are reduced in parts).
    UInt128 sum = 0;
    int terms = 0;
    mp_limb_t reduced = 0;
    for (int j = r + 1; j < k; ++j) {
      sum += static_cast<UInt128>(ws.lu[at(r, j)]) * ws.digit[j];
      if (++terms == 15) {
        reduced = nmod_add(reduced, reduce_128(sum, mod), mod);
        sum = 0;
        terms = 0;
      }
    }
    reduced = nmod_add(reduced, reduce_128(sum, mod), mod);
    ws.digit[r] = nmod_mul(nmod_sub(ws.rhs[r], reduced, mod), ws.inverse_pivot[r], mod);
  }
}

// Whether C·u = d·y exactly (C's entries from c_words when in words).
bool solves(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y, bool in_words,
            const std::vector<Integer>& u, const Integer& d, Workspace& ws) {
  for (int a = 0; a < k; ++a) {
    mpz_mul(mp(ws.t), mp(d), mp(*y[a]));
    for (int j = 0; j < k; ++j) {
      const std::size_t e = static_cast<std::size_t>(a) * k + j;
      if (!in_words) {
        mpz_submul(mp(ws.t), mp(*c[e]), mp(u[j]));
        continue;
      }
      const std::int64_t x = ws.c_words[e];
      if (x > 0)
        mpz_submul_ui(mp(ws.t), mp(u[j]), static_cast<unsigned long>(x));
      else if (x < 0)
        mpz_addmul_ui(mp(ws.t), mp(u[j]), static_cast<unsigned long>(-x));
    }
    if (mpz_sgn(mp(ws.t)) != 0) return false;
  }
  return true;
}

// x modulo 2^128, as two's complement.
UInt128 low_bits(mpz_srcptr z) {
  const UInt128 negative = z->_mp_size < 0 ? ~UInt128(0) : 0;
  return (low_128(z) ^ negative) - negative;
}

// Bits of |x|: |x| < 2^bits (0 for x = 0).
long bits(mpz_srcptr z) { return mpz_sgn(z) == 0 ? 0 : static_cast<long>(mpz_sizeinbase(z, 2)); }

// Whether C·u = d·y, given C·u ≡ d·y (mod M): see dixon_accepts. C's
// entries from c_words when in words.
bool accepts(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y, bool in_words,
             const std::vector<Integer>& u, const Integer& d, const Integer& modulus, Workspace& ws) {
  // r = C·u − d·y is a multiple of M. With M odd, r is then 0 if it is
  // ≡ 0 mod 2^128 (wrapping products of the low words) and |r| < M·2^128,
  // which sizes show: |r| < k·2^(cb+ub) + 2^(db+yb) ≤ 2^(E+1) with
  // E = max(cb + ub + ⌈log2 k⌉, db + yb), and M ≥ 2^(mb−1). When the
  // sizes do not show it, the exact products decide.
  thread_local std::vector<UInt128> u_low;
  u_low.resize(k);
  long cb = 0, ub = 0, yb = 0;
  for (int j = 0; j < k; ++j) {
    u_low[j] = low_bits(mp(u[j]));
    ub = std::max(ub, bits(mp(u[j])));
  }
  if (in_words) {
    std::uint64_t largest = 0;
    for (const std::int64_t x : ws.c_words) largest |= static_cast<std::uint64_t>(x < 0 ? -x : x);
    cb = largest == 0 ? 0 : 64 - __builtin_clzll(largest);  // |x| ≤ largest < 2^cb (an upper bound: or of all)
  } else {
    for (const Integer* x : c) cb = std::max(cb, bits(mp(*x)));
  }
  for (const Integer* x : y) yb = std::max(yb, bits(mp(*x)));
  long log_k = 0;
  while ((1L << log_k) < k) ++log_k;
  const long e = std::max(cb + ub + log_k, bits(mp(d)) + yb);
  if (!mpz_odd_p(mp(modulus)) || e + 2 > bits(mp(modulus)) + 128) return solves(k, c, y, in_words, u, d, ws);
  const UInt128 d_low = low_bits(mp(d));
  for (int a = 0; a < k; ++a) {
    UInt128 r = -(d_low * low_bits(mp(*y[a])));
    const std::size_t row = static_cast<std::size_t>(a) * k;
    if (in_words) {
      for (int j = 0; j < k; ++j) r += static_cast<UInt128>(static_cast<Int128>(ws.c_words[row + j])) * u_low[j];
    } else {
      for (int j = 0; j < k; ++j) r += low_bits(mp(*c[row + j])) * u_low[j];
    }
    if (r != 0) return false;
  }
  return true;
}

}  // namespace

bool dixon_accepts(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y,
                   const std::vector<Integer>& u, const Integer& d, const Integer& modulus) {
  if (k < 0 || c.size() != static_cast<std::size_t>(k) * k || y.size() != static_cast<std::size_t>(k) ||
      u.size() != static_cast<std::size_t>(k))
    return false;
  return accepts(k, c, y, false, u, d, modulus, workspace());
}

namespace {

// Rational reconstruction of a mod M (0 ≤ a < M): its denominator into
// `den`, false if there is none.
bool reconstruct_denominator(const Integer& a, const Workspace& ws, Integer& den) {
  Fmpz residue, modulus;  // FLINT values stay local: none outlives FLINT's per-thread pools
  Fmpq q;
  fmpz_set_mpz(residue.v, mp(a));
  fmpz_set_mpz(modulus.v, mp(ws.modulus));
  if (!fmpq_reconstruct_fmpz(q.v, residue.v, modulus.v)) return false;
  fmpz_get_mpz(mp(den), fmpq_denref(q.v));
  return true;
}

// Whether d² < M/2, as for a denominator that rational reconstruction
// may return: a larger d would let garbage pass the size test below.
bool small_denominator(const Integer& d, Workspace& ws) {
  mpz_mul(mp(ws.t), mp(d), mp(d));
  return mpz_cmp(mp(ws.t), mp(ws.half)) < 0;
}

// The denominator of the reconstruction of a mod M whose value is at most
// `bound` in magnitude, and that value's double: FLINT's search in the box
// |n| ≤ N, d ≤ D with D = 2^e, N = 2^(m−2−e), m the bits of M and e =
// ⌊(m − 3 − b)/2⌋, b the bits of ⌈bound⌉ + 1. Then 2ND = 2^(m−1) < M (M is
// odd), so the answer is unique, and N ≥ bound·D. Such a value is found
// once M > 8(bound + 1)·den², where the balanced search needs
// M > 2·max(num, den)²: about |value| times fewer for large values. Powers
// of two spare the square root. False if there is none.
bool reconstruct_denominator_bounded(const Integer& a, double bound, Workspace& ws, Integer& den, double& value) {
  if (!(bound >= 0 && bound < 0x1p1000)) return false;
  const long m = static_cast<long>(mpz_sizeinbase(mp(ws.modulus), 2));
  const long b = std::ilogb(std::ceil(bound) + 1) + 1;
  const long e = (m - 3 - b) / 2;
  if (m - 3 - b < 0) return false;
  Fmpz residue, modulus, num_bound, den_bound;
  Fmpq q;
  fmpz_one(den_bound.v);
  fmpz_mul_2exp(den_bound.v, den_bound.v, static_cast<ulong>(e));
  fmpz_one(num_bound.v);
  fmpz_mul_2exp(num_bound.v, num_bound.v, static_cast<ulong>(m - 2 - e));
  fmpz_set_mpz(residue.v, mp(a));
  fmpz_set_mpz(modulus.v, mp(ws.modulus));
  if (!fmpq_reconstruct_fmpz_2(q.v, residue.v, modulus.v, num_bound.v, den_bound.v)) return false;
  fmpz_get_mpz(mp(den), fmpq_denref(q.v));
  value = fmpq_get_d(q.v);
  return true;
}

// Whether `value` lies in [lo, hi] up to 2⁻³⁰ of `magnitude` ≥ |lo|, |hi|
// (the doubles' own errors are near 2⁻⁵²): a filter in front of the exact
// check, so its roundings can cost time, never an answer.
bool within(double value, double lo, double hi, double magnitude) {
  const double slack = 0x1p-30 * magnitude;
  return value >= lo - slack && value <= hi + slack;
}

// Whether v/d lies in the hint's enclosure of x_j.
// v/d is taken from both mantissas and exponents, so that it does not
// overflow when v and d are beyond double range themselves.
bool plausible(const Integer& v, const Integer& d, const DixonHint& hint, int j) {
  const double lo = hint.lo[j], hi = hint.hi[j];
  long v_exp = 0, d_exp = 0;
  const double v_mantissa = mpz_get_d_2exp(&v_exp, mp(v)), d_mantissa = mpz_get_d_2exp(&d_exp, mp(d));
  const double value = std::ldexp(v_mantissa / d_mantissa, static_cast<int>(std::clamp(v_exp - d_exp, -4000L, 4000L)));
  return within(value, lo, hi, std::max(std::abs(lo), std::abs(hi)));
}

// With x ≡ lifted (mod M): d from the rational reconstruction of a fixed
// combination of the x_j (usually the lcm of their denominators), then
// each u_j = d·x_j as the symmetric residue mod M. A u_j that fails the
// test below means d lacks a factor of x_j's denominator (or M is still
// too small): x_j·d is reconstructed and d grows by its denominator (at
// most k times). Last, the exact check; the test before it only keeps
// garbage from reaching it. With a hint, the combination's reconstruction
// is bounded by the hint's magnitude and the test is the hint's
// enclosure; without, both are balanced: |u_j|·max(d, 2⁶⁴) < M/2.
bool reconstruct(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y, bool in_words,
                 std::vector<Integer>& u, Integer& d, Workspace& ws, const DixonHint* hint) {
  mpz_set_ui(mp(ws.combination), 0);
  for (int j = 0; j < k; ++j) mpz_addmul_ui(mp(ws.combination), mp(ws.lifted[j]), static_cast<unsigned long>(j + 1));
  mpz_mod(mp(ws.combination), mp(ws.combination), mp(ws.modulus));
  mpz_fdiv_q_2exp(mp(ws.half), mp(ws.modulus), 1);
  double bound = 0, lo = 0, hi = 0;  // bound ≥ |Σ (j + 1) x_j|, [lo, hi] ∋ Σ (j + 1) x_j
  if (hint != nullptr) {
    for (int j = 0; j < k; ++j) {
      bound += (j + 1) * std::max(std::abs(hint->lo[j]), std::abs(hint->hi[j]));
      lo += (j + 1) * hint->lo[j];
      hi += (j + 1) * hint->hi[j];
    }
    if (!(bound < 0x1p1000)) hint = nullptr;  // values beyond doubles (or no enclosure): balanced
  }
  if (hint != nullptr) {
    // A reconstruction outside the combination's enclosure is garbage (M
    // still too small), dropped before any u_j.
    double value = 0;
    if (!reconstruct_denominator_bounded(ws.combination, bound, ws, d, value) || !within(value, lo, hi, bound))
      return false;
  } else if (!reconstruct_denominator(ws.combination, ws, d) || !small_denominator(d, ws)) {
    return false;
  }
  ws.candidate.resize(k);
  for (int grown = 0, j = 0; j < k; ++j) {
    Integer& v = ws.candidate[j];
    mpz_mul(mp(v), mp(ws.lifted[j]), mp(d));
    mpz_mod(mp(v), mp(v), mp(ws.modulus));
    if (mpz_cmp(mp(v), mp(ws.half)) > 0) mpz_sub(mp(v), mp(v), mp(ws.modulus));
    if (hint != nullptr) {
      if (plausible(v, d, *hint, j)) continue;
    } else {
      // The 64-bit floor keeps a random residue from passing when d is
      // small (it then passes with odds below 2⁻⁶³).
      if (mpz_sizeinbase(mp(d), 2) > 64)
        mpz_mul(mp(ws.t), mp(v), mp(d));
      else
        mpz_mul_2exp(mp(ws.t), mp(v), 64);
      mpz_abs(mp(ws.t), mp(ws.t));
      if (mpz_cmp(mp(ws.t), mp(ws.half)) < 0) continue;
    }
    if (grown++ == k) return false;
    if (mpz_sgn(mp(v)) < 0) mpz_add(mp(v), mp(v), mp(ws.modulus));
    const double scale = mpz_get_d(mp(d));
    const double lo_j = hint != nullptr ? hint->lo[j] * scale : 0, hi_j = hint != nullptr ? hint->hi[j] * scale : 0;
    const double bound_j = std::max(std::abs(lo_j), std::abs(hi_j));
    if (hint != nullptr && bound_j < 0x1p1000) {
      // x_j·d's reconstruction, bounded by the hint and inside its
      // enclosure (times d), else M is still too small.
      double value = 0;
      if (!reconstruct_denominator_bounded(v, bound_j, ws, ws.factor, value) || mpz_cmp_ui(mp(ws.factor), 1) == 0 ||
          !within(value, lo_j, hi_j, bound_j))
        return false;
      mpz_mul(mp(d), mp(d), mp(ws.factor));
    } else {
      if (!reconstruct_denominator(v, ws, ws.t) || mpz_cmp_ui(mp(ws.t), 1) == 0) return false;
      mpz_mul(mp(d), mp(d), mp(ws.t));
      if (!small_denominator(d, ws)) return false;
    }
    j = -1;  // d changed: every u_j again
  }
  // C·u ≡ d·y (mod M) holds by construction: C·x̄ ≡ y and u ≡ d·x̄.
  if (!accepts(k, c, y, in_words, ws.candidate, d, ws.modulus, ws)) return false;
  u.resize(k);
  for (int j = 0; j < k; ++j) mpz_swap(mp(u[j]), mp(ws.candidate[j]));
  return true;
}

// Lifting steps after which reconstruction must have succeeded: by
// Cramer's rule x_j = det C_j / det C, and Hadamard's bound H_num ≥ H_den
// (y's column counted in the first) bounds every numerator and
// denominator involved; FLINT's reconstruction looks for both below
// √(M/2), so p^steps > 2·H_num² suffices. Bits are over-estimated from each
// row's longest entry in limbs, so the bound stays a bound (a loose one
// costs nothing unless reconstruction fails).
int step_limit(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y, bool in_words,
               double prime_bits) {
  double num_bits = 0;
  const double half_log_k = 0.5 * std::log2(static_cast<double>(k) + 1);
  for (int a = 0; a < k; ++a) {
    std::size_t row = mpz_size(mp(*y[a]));
    if (in_words)
      row = std::max<std::size_t>(row, 1);  // every entry of C has at most one limb
    else
      for (int j = 0; j < k; ++j) row = std::max(row, mpz_size(mp(*c[static_cast<std::size_t>(a) * k + j])));
    num_bits += 64.0 * static_cast<double>(row) + half_log_k;
  }
  return static_cast<int>(std::ceil((2 * num_bits + 2) / prime_bits)) + 1;
}

}  // namespace

void set_dixon_words_allowed(bool on) { g_words_allowed = on; }

bool dixon_solve(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y,
                 std::vector<Integer>& u, Integer& d, const DixonHint* hint, DixonTrace* trace) {
  if (k < 0 || c.size() != static_cast<std::size_t>(k) * k || y.size() != static_cast<std::size_t>(k)) return false;
  if (hint != nullptr && (hint->lo.size() != static_cast<std::size_t>(k) || hint->hi.size() != hint->lo.size()))
    hint = nullptr;  // not this system's: ignored
  DixonTrace ignored;
  DixonTrace& record = trace != nullptr ? *trace : ignored;
  record = DixonTrace{};
  Workspace& ws = workspace();
  if (k == 0) {
    u.clear();
    mpz_set_ui(mp(d), 1);
    return true;
  }
  const bool in_words = words(k, c, y, ws);
  for (const std::uint64_t prime : dixon_primes()) {
    nmod_t mod;
    nmod_init(&mod, prime);
    if (!factor_mod(k, c, in_words, mod, ws)) continue;  // p divides det C (or C is singular)
    const int limit = step_limit(k, c, y, in_words, std::log2(static_cast<double>(prime)));
    const UInt128 prime_inverse = inverse_mod_2_128(prime);
    ws.residual.resize(k);
    ws.lifted.resize(k);
    ws.digit.resize(k);
    ws.rhs.resize(k);
    ws.residual_words = ws.y_words;
    for (int a = 0; a < k; ++a) {
      if (!in_words) mpz_set(mp(ws.residual[a]), mp(*y[a]));
      mpz_set_ui(mp(ws.lifted[a]), 0);
    }
    mpz_set_ui(mp(ws.modulus), 1);
    record = DixonTrace{};
    record.words = in_words;
    // Invariant: C·lifted + modulus·residual = y, lifted < modulus entrywise.
    // It is checked, not assumed: each division by p is of a number p
    // is seen to divide (a wrong digit would stop the solve), and the
    // acceptance test (accepts) relies on it.
    for (int step = 0; step < limit; ++step) {
      ++record.steps;
      for (int a = 0; a < k; ++a)
        ws.rhs[a] = in_words ? residue(ws.residual_words[a], mod) : residue(ws.residual[a], mod);
      solve_mod(k, mod, ws);
      for (int a = 0; a < k; ++a) {
        mpz_addmul_ui(mp(ws.lifted[a]), mp(ws.modulus), ws.digit[a]);
        const std::size_t row = static_cast<std::size_t>(a) * k;
        if (in_words) {
          // r ← (r − Σ_j C(a, j)·digit_j)/p, exact: times 1/p modulo 2^128.
          Int128 r = ws.residual_words[a];
          for (int j = 0; j < k; ++j) r -= static_cast<Int128>(ws.c_words[row + j]) * static_cast<Int128>(ws.digit[j]);
          if (residue_below_2_126(r, mod) != 0) return false;  // checked: see the invariant
          ws.residual_words[a] = static_cast<Int128>(static_cast<UInt128>(r) * prime_inverse);
          continue;
        }
        for (int j = 0; j < k; ++j)
          if (ws.digit[j] != 0) mpz_submul_ui(mp(ws.residual[a]), mp(*c[row + j]), ws.digit[j]);
        if (mpz_tdiv_q_ui(mp(ws.residual[a]), mp(ws.residual[a]), prime) != 0) return false;
      }
      mpz_mul_ui(mp(ws.modulus), mp(ws.modulus), prime);
      // With a hint, from the first step on (a one-limb reconstruction is
      // cheap); the last step without it, where Hadamard's bound promises
      // the balanced reconstruction success.
      const bool last = step + 1 == limit;
      if (hint == nullptr && step == 0) continue;
      ++record.attempts;
      if (reconstruct(k, c, y, in_words, u, d, ws, last ? nullptr : hint)) return true;
    }
    return false;  // beyond the bound: not expected (p ∤ det C), and the caller solves another way
  }
  return false;
}

}  // namespace fixel::internal
