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
#include <cstdint>
#include <cstring>
#include <thread>
#include <utility>
#include <vector>

#include "fixel/internal/flint_thread.h"
#include "fixel/internal/lemke_dixon_sparse.h"
#include "fixel/internal/lemke_dixon_words.h"
#include "fixel/internal/lemke_scaled.h"
#include "fixel/progress.h"

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

// 1/p modulo 2^128 and ⌊2^126/p⌋ (exact_quotient's), made once for the
// primes above: Newton's steps and a 128-bit division are noticeable
// beside a small system's lifting.
struct PrimeDivision {
  UInt128 inverse = 0, bound = 0;
  explicit PrimeDivision(std::uint64_t p) : inverse(inverse_mod_2_128(p)), bound((UInt128(1) << 126) / p) {}
};
PrimeDivision prime_division(std::uint64_t prime) {
  static const std::vector<PrimeDivision> divisions = [] {
    std::vector<PrimeDivision> out;
    for (const std::uint64_t p : dixon_primes()) out.emplace_back(p);
    return out;
  }();
  const std::vector<std::uint64_t>& primes = dixon_primes();
  for (std::size_t i = 0; i < primes.size(); ++i)
    if (primes[i] == prime) return divisions[i];
  return PrimeDivision(prime);
}

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

// Storage reused from call to call (one per thread). The FLINT values
// live here too rather than per reconstruction: fewer of FLINT's pooled
// integers taken and given back (a value of more than 62 bits holds one).
struct Workspace {
  Fmpz residue, flint_modulus, num_bound, den_bound;
  Fmpq reconstructed;
  ModularLu lu;
  std::vector<mp_limb_t> digit, rhs;
  std::vector<Integer> residual, lifted, candidate;
  Integer modulus, half, t, combination, factor;
  // The lifted x as base-p digits (digit t of x_j at digits[t·k + j]);
  // `lifted` holds the first lifted_steps of them as integers, made only
  // when a modulus of more than kPadicDigits steps needs them.
  nmod_t mod{};
  std::vector<mp_limb_t> digits;
  int lifted_steps = 0;
  Integer lifted_modulus;  // p^lifted_steps
  mp_limb_t d_digits[kPadicDigits] = {}, x_digits[kPadicDigits] = {}, u_digits[kPadicDigits] = {};
  // The word path's system and residual (internal/lemke_dixon_words.h).
  std::vector<std::int64_t> c_words;
  std::vector<Int128> y_words, residual_words;
  // dixon_solve's short rows eliminated, and the smaller system's parts.
  SparseRowReduction sparse;
  std::vector<char> zero_rhs, hint_set;
  std::vector<const Integer*> reduced_y;
  std::vector<Integer> reduced_u;
  DixonHint reduced_hint;
};

std::atomic<bool> g_words_allowed{true};
std::atomic<bool> g_sparse_rows_allowed{true};

Workspace& workspace() {
  free_flint_caches_at_thread_exit();  // first, so FLINT's caches go after ws
  thread_local Workspace ws;
  return ws;
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
bool reconstruct_denominator(const Integer& a, Workspace& ws, Integer& den) {
  fmpz_set_mpz(ws.residue.v, mp(a));
  fmpz_set_mpz(ws.flint_modulus.v, mp(ws.modulus));
  if (!fmpq_reconstruct_fmpz(ws.reconstructed.v, ws.residue.v, ws.flint_modulus.v)) return false;
  fmpz_get_mpz(mp(den), fmpq_denref(ws.reconstructed.v));
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
  fmpz_one_2exp(ws.den_bound.v, static_cast<ulong>(e));  // a small fmpz (no allocation) below 2^62
  fmpz_one_2exp(ws.num_bound.v, static_cast<ulong>(m - 2 - e));
  fmpz_set_mpz(ws.residue.v, mp(a));
  fmpz_set_mpz(ws.flint_modulus.v, mp(ws.modulus));
  fmpq* const q = ws.reconstructed.v;
  if (!fmpq_reconstruct_fmpz_2(q, ws.residue.v, ws.flint_modulus.v, ws.num_bound.v, ws.den_bound.v)) return false;
  fmpz_get_mpz(mp(den), fmpq_denref(q));
  // Only the filter below reads the value: one division of the doubles when
  // both parts are small fmpz (the usual case), else from both mantissas.
  const fmpz* n = fmpq_numref(q);
  const fmpz* d = fmpq_denref(q);
  if (!COEFF_IS_MPZ(*n) && !COEFF_IS_MPZ(*d)) {
    value = static_cast<double>(*n) / static_cast<double>(*d);
  } else {
    slong n_exp = 0, d_exp = 0;
    const double n_mantissa = fmpz_get_d_2exp(&n_exp, n), d_mantissa = fmpz_get_d_2exp(&d_exp, d);
    value = std::ldexp(n_mantissa / d_mantissa, static_cast<int>(std::clamp<slong>(n_exp - d_exp, -4000, 4000)));
  }
  return true;
}

// z as mantissa·2^exponent, |mantissa| in [1/2, 1] (0 for z = 0), from its
// top 64 bits: for the filters below only (mpz_get_d_2exp's work and
// libm's ldexp were a tenth of the reconstruction's time).
double mantissa_2exp(mpz_srcptr z, long& exponent) {
  const int size = z->_mp_size < 0 ? -z->_mp_size : z->_mp_size;
  if (size == 0) {
    exponent = 0;
    return 0;
  }
  const mp_limb_t top = z->_mp_d[size - 1];
  const int zeros = __builtin_clzl(top);
  mp_limb_t bits = top << zeros;
  if (zeros != 0 && size > 1) bits |= z->_mp_d[size - 2] >> (64 - zeros);
  exponent = 64L * size - zeros;
  const double mantissa = static_cast<double>(bits) * 0x1p-64;
  return z->_mp_size < 0 ? -mantissa : mantissa;
}

// x·2^e: a product with 2^e when that is a normal double, else ldexp.
double times_2exp(double x, long e) {
  if (e >= -1000 && e <= 1000) {
    const std::uint64_t bits = static_cast<std::uint64_t>(1023 + e) << 52;
    double power = 0;
    std::memcpy(&power, &bits, sizeof power);
    return x * power;
  }
  return std::ldexp(x, static_cast<int>(std::clamp(e, -4000L, 4000L)));
}

// Whether `value` lies in [lo, hi] up to 2⁻³⁰ of `magnitude` ≥ |lo|, |hi|
// (the doubles' own errors are near 2⁻⁵²): a filter in front of the exact
// check, so its roundings can cost time, never an answer.
bool within(double value, double lo, double hi, double magnitude) {
  const double slack = 0x1p-30 * magnitude;
  return value >= lo - slack && value <= hi + slack;
}

// A denominator d as mantissa·2^exponent, converted once for all the x_j.
struct Scaled {
  double mantissa = 1;
  long exponent = 0;
  explicit Scaled(const Integer& d) { mantissa = mantissa_2exp(mp(d), exponent); }
};

// Whether v/d lies in the hint's enclosure of x_j.
// v/d is taken from both mantissas and exponents, so that it does not
// overflow when v and d are beyond double range themselves.
bool plausible(const Integer& v, const Scaled& d, const DixonHint& hint, int j) {
  const double lo = hint.lo[j], hi = hint.hi[j];
  long v_exp = 0;
  const double v_mantissa = mantissa_2exp(mp(v), v_exp);
  const double value = times_2exp(v_mantissa / d.mantissa, v_exp - d.exponent);
  return within(value, lo, hi, std::max(std::abs(lo), std::abs(hi)));
}

// The least f in 2..kSmallFactor with f·d·x_j an integer, judged by the
// hint, else 0: v ≡ d·x_j (mod M), 0 ≤ v < M, and f·v's symmetric residue
// over f·d must lie in x_j's enclosure. A factor that d lacks is usually
// small (on the bench's LCPs mostly 2, 3, 4, 5 or 8: the combination's numerator
// is divisible by a prime p of its denominator about once in p), and a
// trial is one addition mod M, far cheaper than a reconstruction. Like
// the reconstruction it goes before, it only proposes: the exact check
// decides.
constexpr int kSmallFactor = 16;
int small_missing_factor(const Integer& v, const Scaled& d, const DixonHint& hint, int j, Workspace& ws) {
  mpz_set(mp(ws.t), mp(v));  // f·v mod M
  for (int f = 2; f <= kSmallFactor; ++f) {
    mpz_add(mp(ws.t), mp(ws.t), mp(v));
    if (mpz_cmp(mp(ws.t), mp(ws.modulus)) >= 0) mpz_sub(mp(ws.t), mp(ws.t), mp(ws.modulus));
    if (mpz_cmp(mp(ws.t), mp(ws.half)) > 0)
      mpz_sub(mp(ws.factor), mp(ws.t), mp(ws.modulus));
    else
      mpz_set(mp(ws.factor), mp(ws.t));
    Scaled scaled = d;
    scaled.mantissa *= f;
    if (plausible(ws.factor, scaled, hint, j)) return f;
  }
  return 0;
}

// ws.lifted as integers from the first `steps` digits (the digits not
// folded in yet are added, as the lifting once did step by step).
void fold_lifted_digits(int k, int steps, Workspace& ws) {
  for (; ws.lifted_steps < steps; ++ws.lifted_steps) {
    const mp_limb_t* row = &ws.digits[static_cast<std::size_t>(ws.lifted_steps) * k];
    for (int j = 0; j < k; ++j) mpz_addmul_ui(mp(ws.lifted[j]), mp(ws.lifted_modulus), row[j]);
    mpz_mul_ui(mp(ws.lifted_modulus), mp(ws.lifted_modulus), ws.mod.n);
  }
}

// d·x_j's residue mod M = p^steps in [0, M) into v: from the digits when
// steps ≤ kPadicDigits (ws.d_digits holding d's), else from the integers.
void residue_of_product(int j, int k, int steps, const Integer& d, Workspace& ws, Integer& v) {
  if (steps > kPadicDigits) {
    mpz_mul(mp(v), mp(ws.lifted[j]), mp(d));
    mpz_mod(mp(v), mp(v), mp(ws.modulus));
    return;
  }
  for (int t = 0; t < steps; ++t) ws.x_digits[t] = ws.digits[static_cast<std::size_t>(t) * k + j];
  padic_product(ws.x_digits, ws.d_digits, steps, ws.mod, ws.u_digits);
  from_padic(ws.u_digits, steps, ws.mod, v);
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
bool reconstruct(int k, int steps, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y,
                 bool in_words, std::vector<Integer>& u, Integer& d, Workspace& ws, const DixonHint* hint,
                 DixonTrace& record) {
  const bool padic = steps <= kPadicDigits;
  if (padic) {
    padic_weighted_sum(ws.digits.data(), k, steps, ws.mod, ws.u_digits);
    from_padic(ws.u_digits, steps, ws.mod, ws.combination);
  } else {
    fold_lifted_digits(k, steps, ws);
    mpz_set_ui(mp(ws.combination), 0);
    for (int j = 0; j < k; ++j) mpz_addmul_ui(mp(ws.combination), mp(ws.lifted[j]), static_cast<unsigned long>(j + 1));
    mpz_mod(mp(ws.combination), mp(ws.combination), mp(ws.modulus));
  }
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
  Scaled d_scaled(d);
  if (padic) padic_digits(mp(d), steps, ws.mod, ws.d_digits);
  int by_trial = 0, by_reconstruction = 0;  // into the trace if this attempt answers
  for (int grown = 0, j = 0; j < k; ++j) {
    Integer& v = ws.candidate[j];
    residue_of_product(j, k, steps, d, ws, v);
    if (mpz_cmp(mp(v), mp(ws.half)) > 0) mpz_sub(mp(v), mp(v), mp(ws.modulus));
    if (hint != nullptr) {
      if (plausible(v, d_scaled, *hint, j)) continue;
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
      // A small factor by trial; else x_j·d's reconstruction, bounded by
      // the hint and inside its enclosure (times d), else M is still too
      // small.
      double value = 0;
      if (const int f = small_missing_factor(v, d_scaled, *hint, j, ws); f != 0) {
        mpz_mul_ui(mp(d), mp(d), static_cast<unsigned long>(f));
        ++by_trial;
      } else {
        ++by_reconstruction;
        if (!reconstruct_denominator_bounded(v, bound_j, ws, ws.factor, value) || mpz_cmp_ui(mp(ws.factor), 1) == 0 ||
            !within(value, lo_j, hi_j, bound_j))
          return false;
        mpz_mul(mp(d), mp(d), mp(ws.factor));
      }
    } else {
      ++by_reconstruction;
      if (!reconstruct_denominator(v, ws, ws.t) || mpz_cmp_ui(mp(ws.t), 1) == 0) return false;
      mpz_mul(mp(d), mp(d), mp(ws.t));
      if (!small_denominator(d, ws)) return false;
    }
    d_scaled = Scaled(d);
    if (padic) padic_digits(mp(d), steps, ws.mod, ws.d_digits);
    j = -1;  // d changed: every u_j again
  }
  // C·u ≡ d·y (mod M) holds by construction: C·x̄ ≡ y and u ≡ d·x̄.
  if (!accepts(k, c, y, in_words, ws.candidate, d, ws.modulus, ws)) return false;
  u.resize(k);
  for (int j = 0; j < k; ++j) mpz_swap(mp(u[j]), mp(ws.candidate[j]));
  record.factors_by_trial += by_trial;
  record.factors_by_reconstruction += by_reconstruction;
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
bool dixon_words_allowed() { return g_words_allowed; }

namespace {

// dixon_solve on the system as given (no short rows eliminated).
bool solve_block(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y,
                 std::vector<Integer>& u, Integer& d, const DixonHint* hint, DixonTrace* trace,
                 const std::vector<std::int64_t>* c_words) {
  const auto entries = static_cast<std::size_t>(k) * k;
  // c may be empty when c_words is given: then y must fit words too (the
  // integers of C are never read on the word path).
  const bool words_given = c_words != nullptr && c_words->size() == entries && k <= kWordRows;
  if (k < 0 || y.size() != static_cast<std::size_t>(k) || !(c.size() == entries || (c.empty() && words_given)))
    return false;
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
  bool in_words = false;
  if (words_given) {
    ws.c_words = *c_words;
    in_words = g_words_allowed && rhs_in_words(k, y, ws.y_words);
  } else {
    in_words = g_words_allowed && block_in_words(k, c, y, ws.c_words, ws.y_words);
  }
  if (!in_words && c.empty()) return false;  // the GMP path needs C's integers
  for (const std::uint64_t prime : dixon_primes()) {
    nmod_t mod;
    nmod_init(&mod, prime);
    if (!(in_words ? ws.lu.factor(k, ws.c_words, mod) : ws.lu.factor(k, c, mod)))
      continue;  // p divides det C (or C is singular)
    const int limit = step_limit(k, c, y, in_words, std::log2(static_cast<double>(prime)));
    const PrimeDivision division = prime_division(prime);
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
    ws.mod = mod;
    ws.digits.clear();
    ws.lifted_steps = 0;
    mpz_set_ui(mp(ws.lifted_modulus), 1);
    record = DixonTrace{};
    record.words = in_words;
    // Invariant: C·x̄ + modulus·residual = y, x̄ = Σ_t digit_t·p^t below
    // modulus entrywise (the digits kept in ws.digits).
    // It is checked, not assumed: each division by p is of a number p
    // is seen to divide (a wrong digit would stop the solve), and the
    // acceptance test (accepts) relies on it.
    for (int step = 0; step < limit; ++step) {
      poll_exact_step();  // entries of thousands of digits make the limit large
      ++record.steps;
      for (int a = 0; a < k; ++a)
        ws.rhs[a] = in_words ? residue(ws.residual_words[a], mod) : residue(ws.residual[a], mod);
      ws.lu.solve(ws.rhs, ws.digit);
      ws.digits.insert(ws.digits.end(), ws.digit.begin(), ws.digit.end());  // x's digit `step`
      for (int a = 0; a < k; ++a) {
        const std::size_t row = static_cast<std::size_t>(a) * k;
        if (in_words) {
          // r ← (r − Σ_j C(a, j)·digit_j)/p, exact: times 1/p modulo 2^128.
          Int128 r = ws.residual_words[a];
          for (int j = 0; j < k; ++j) r -= static_cast<Int128>(ws.c_words[row + j]) * static_cast<Int128>(ws.digit[j]);
          if (!exact_quotient(r, division.inverse, division.bound, ws.residual_words[a]))
            return false;  // checked: see the invariant
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
      // With a hint, none after the second step either: a two-limb
      // reconstruction costs more than a lifting step, and on the seating
      // LCPs it rarely succeeded where one limb failed (11% of the bench's
      // solves when every step tried, 57% needing three steps, 2% four;
      // docs/theory.md §6). This costs time only: every later step tries.
      if (hint != nullptr && step == 1 && !last) continue;
      ++record.attempts;
      if (reconstruct(k, step + 1, c, y, in_words, u, d, ws, last ? nullptr : hint, record)) return true;
    }
    return false;  // beyond the bound: not expected (p ∤ det C), and the caller solves another way
  }
  return false;
}

}  // namespace

void set_dixon_sparse_rows_allowed(bool on) { g_sparse_rows_allowed = on; }

bool dixon_solve(int k, const std::vector<const Integer*>& c, const std::vector<const Integer*>& y,
                 std::vector<Integer>& u, Integer& d, const DixonHint* hint, DixonTrace* trace,
                 const std::vector<std::int64_t>* c_words) {
  // The short rows first (internal/lemke_dixon_sparse.h), when C comes as
  // words: x from the smaller system's t, x_j = multiplier_j·t_(unknown_j).
  const bool words_given = c_words != nullptr && k > 0 && k <= kWordRows &&
                           c_words->size() == static_cast<std::size_t>(k) * k &&
                           y.size() == static_cast<std::size_t>(k);
  if (!words_given || !g_sparse_rows_allowed || !g_words_allowed)
    return solve_block(k, c, y, u, d, hint, trace, c_words);
  Workspace& ws = workspace();
  ws.zero_rhs.resize(k);
  for (int a = 0; a < k; ++a) ws.zero_rhs[a] = static_cast<char>(mpz_sgn(mp(*y[a])) == 0);
  SparseRowReduction& r = ws.sparse;
  if (!r.reduce(k, *c_words, ws.zero_rhs)) return solve_block(k, c, y, u, d, hint, trace, c_words);
  ws.reduced_y.resize(r.reduced);
  for (int a = 0; a < r.reduced; ++a) ws.reduced_y[a] = y[r.rows[a]];
  const DixonHint* reduced_hint = nullptr;
  if (hint != nullptr && hint->lo.size() == static_cast<std::size_t>(k) && hint->hi.size() == hint->lo.size()) {
    // t from the first x_j that is a multiple of it: x_j/m (only a hint).
    ws.reduced_hint.lo.assign(r.reduced, 0);
    ws.reduced_hint.hi.assign(r.reduced, 0);
    ws.hint_set.assign(r.reduced, 0);
    for (int j = 0; j < k; ++j) {
      const int t = r.unknown[j];
      if (t < 0 || ws.hint_set[t]) continue;
      const double m = static_cast<double>(r.multiplier[j]);
      const double lo = hint->lo[j] / m, hi = hint->hi[j] / m;
      ws.reduced_hint.lo[t] = m > 0 ? lo : hi;
      ws.reduced_hint.hi[t] = m > 0 ? hi : lo;
      ws.hint_set[t] = 1;
    }
    reduced_hint = &ws.reduced_hint;
  }
  const std::vector<const Integer*> no_integers;
  if (!solve_block(r.reduced, no_integers, ws.reduced_y, ws.reduced_u, d, reduced_hint, trace, &r.c_words))
    return solve_block(k, c, y, u, d, hint, trace, c_words);  // e.g. y beyond words: C whole, with GMP if need be
  u.resize(k);
  for (int j = 0; j < k; ++j) {
    if (r.unknown[j] < 0)
      mpz_set_ui(mp(u[j]), 0);
    else
      mpz_mul_si(mp(u[j]), mp(ws.reduced_u[r.unknown[j]]), static_cast<long>(r.multiplier[j]));
  }
  if (trace != nullptr) {
    trace->unknowns_eliminated = k - r.reduced;
    trace->words = true;  // the word path, also when nothing was left to lift
  }
  return true;
}

}  // namespace fixel::internal
