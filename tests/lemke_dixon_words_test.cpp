#include "fixel/internal/lemke_dixon_words.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "fixel/internal/lemke_dixon.h"
#include "fixel/internal/lemke_scaled.h"

namespace fixel::internal {
namespace {

// Every value below is checked against GMP's own arithmetic on the same
// integers (a second method): mpz_fdiv_r_2exp for the words, mpz_fdiv_r for
// the residues.

// A signed integer of `bits` random bits (so up to that size), or zero.
Integer random_integer(std::mt19937_64& rng, int bits) {
  Integer x = 0;
  for (int left = bits; left > 0; left -= 32) {
    const int chunk = left < 32 ? left : 32;
    x = (x << chunk) + Integer(rng() & ((std::uint64_t{1} << chunk) - 1));
  }
  return (rng() & 1) ? Integer(-x) : x;
}

UInt128 to_word(const Integer& nonnegative_below_2_128) {
  const mpz_srcptr z = mp(nonnegative_below_2_128);
  return (static_cast<UInt128>(mpz_getlimbn(z, 1)) << 64) | mpz_getlimbn(z, 0);
}

Integer from_word(Int128 x) {
  const UInt128 m = x < 0 ? -static_cast<UInt128>(x) : static_cast<UInt128>(x);
  Integer out = (Integer(static_cast<std::uint64_t>(m >> 64)) << 64) + Integer(static_cast<std::uint64_t>(m));
  return x < 0 ? Integer(-out) : out;
}

Integer from_word(UInt128 x) {
  return (Integer(static_cast<std::uint64_t>(x >> 64)) << 64) + Integer(static_cast<std::uint64_t>(x));
}

// x mod n in [0, n), by GMP.
std::uint64_t gmp_mod(const Integer& x, std::uint64_t n) {
  Integer r;
  mpz_fdiv_r(mp(r), mp(x), mp(Integer(n)));
  return mpz_get_ui(mp(r));
}

nmod_t modulus(std::uint64_t p) {
  nmod_t mod;
  nmod_init(&mod, p);
  return mod;
}

// Sizes 0–300 bits, both signs, and the edges of one and two limbs.
std::vector<Integer> sample_integers(std::mt19937_64& rng) {
  std::vector<Integer> out = {Integer(0), Integer(1), Integer(-1)};
  for (const int e : {63, 64, 127, 128, 129}) {
    out.push_back(Integer(1) << e);
    out.push_back((Integer(1) << e) - 1);
    out.push_back(-(Integer(1) << e));
    out.push_back(Integer(1) - (Integer(1) << e));
  }
  for (int trial = 0; trial < 300; ++trial) out.push_back(random_integer(rng, trial % 301));
  return out;
}

GTEST_TEST(DixonWords, LowBitsAreTheIntegerModulo2To128ForEverySignAndSize) {
  std::mt19937_64 rng(3);
  for (const Integer& x : sample_integers(rng)) {
    Integer expected, magnitude;
    mpz_fdiv_r_2exp(mp(expected), mp(x), 128);  // in [0, 2^128)
    EXPECT_EQ(from_word(low_bits(mp(x))), expected) << x;
    mpz_abs(mp(magnitude), mp(x));
    mpz_fdiv_r_2exp(mp(magnitude), mp(magnitude), 128);
    EXPECT_EQ(from_word(low_128(mp(x))), magnitude) << x;
  }
}

GTEST_TEST(DixonWords, ResiduesAgreeWithGmpForEveryPrimeSignAndEdge) {
  std::mt19937_64 rng(5);
  for (const std::uint64_t p : dixon_primes()) {
    const nmod_t mod = modulus(p);
    std::vector<Integer> values = sample_integers(rng);
    for (const int e : {125, 126}) {  // the edges of the two word residues
      values.push_back((Integer(1) << e) - 1);
      values.push_back(Integer(1) - (Integer(1) << e));
    }
    const UInt128 inverse = inverse_mod_2_128(p);
    const UInt128 bound = (UInt128(1) << 126) / p;
    // The largest multiples of p below 2^126 in magnitude, and their
    // neighbours: the edges of exact_quotient's bound.
    const Integer top = Integer(p) * Integer(from_word(bound));
    for (const Integer& m : {top, Integer(top - 1), Integer(top - Integer(p)), Integer(top + 1)}) {
      values.push_back(m);
      values.push_back(-m);
    }
    values.push_back(Integer(p) << 63);  // multiples of p
    values.push_back(-(Integer(p) * Integer(p)));
    for (const Integer& x : values) {
      SCOPED_TRACE(x);
      EXPECT_EQ(residue(x, mod), gmp_mod(x, p));
      const long size = static_cast<long>(mpz_sizeinbase(mp(x), 2));
      if (mpz_sgn(mp(x)) == 0 || size <= 125) {
        const Int128 w = static_cast<Int128>(low_bits(mp(x)));
        ASSERT_EQ(from_word(w), x);
        EXPECT_EQ(residue(w, mod), gmp_mod(x, p));
      }
      if (mpz_sgn(mp(x)) == 0 || size <= 126) {
        // The quotient by p exactly when GMP says p divides x.
        const Int128 w = static_cast<Int128>(low_bits(mp(x)));
        Int128 q = 0;
        const bool divides = mpz_divisible_ui_p(mp(x), p) != 0;
        EXPECT_EQ(exact_quotient(w, inverse, bound, q), divides);
        if (divides) {
          Integer expected;
          mpz_divexact_ui(mp(expected), mp(x), p);
          EXPECT_EQ(from_word(q), expected);
        }
      }
      if (mpz_sgn(mp(x)) >= 0 && (mpz_sgn(mp(x)) == 0 || size <= 128)) {
        EXPECT_EQ(reduce_128(to_word(x), mod), gmp_mod(x, p));
      }
    }
    EXPECT_EQ(reduce_128(~UInt128(0), mod), gmp_mod((Integer(1) << 128) - 1, p));
    // a·b + c·e for residues up to p itself.
    for (int trial = 0; trial < 200; ++trial) {
      std::uint64_t w[4];
      for (std::uint64_t& x : w) x = trial < 16 ? (trial & 1 ? p : p - 1) : rng() % (p + 1);
      const Integer expected = Integer(w[0]) * Integer(w[1]) + Integer(w[2]) * Integer(w[3]);
      EXPECT_EQ(mul_add_mod(w[0], w[1], w[2], w[3], mod), gmp_mod(expected, p)) << "trial " << trial;
    }
  }
}

GTEST_TEST(DixonWords, InvertsOddNumbersModulo2To128) {
  std::vector<std::uint64_t> odd = dixon_primes();
  odd.insert(odd.end(), {1, 3, 0xFFFFFFFFFFFFFFFFull, 0x8000000000000001ull});
  for (const std::uint64_t p : odd) EXPECT_EQ(static_cast<UInt128>(p * inverse_mod_2_128(p)), UInt128(1)) << p;
  // Two-limb odd numbers too (the lowest terms' gcds).
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 200; ++trial) {
    const UInt128 x = ((static_cast<UInt128>(rng()) << 64) | rng()) | 1;
    EXPECT_EQ(static_cast<UInt128>(x * inverse_mod_2_128(x)), UInt128(1)) << "trial " << trial;
  }
  EXPECT_EQ(static_cast<UInt128>(~UInt128(0) * inverse_mod_2_128(~UInt128(0))), UInt128(1));
}

// num/den in lowest terms by GMP's canonicalization (the second method).
Rational canonical(const Integer& num, const Integer& den) {
  Rational q;
  mpz_set(mpq_numref(q.backend().data()), mp(num));
  mpz_set(mpq_denref(q.backend().data()), mp(den));
  mpq_canonicalize(q.backend().data());
  return q;
}

// The result of lowest_terms_in_words for num/den, else nullopt. The
// target starts as 7/3, so a value left over would show.
std::optional<Rational> in_words(const Integer& num, const Integer& den) {
  Rational q(7, 3);
  if (!lowest_terms_in_words(mp(num), mp(den), q.backend().data())) {
    EXPECT_EQ(q, Rational(7, 3)) << "a refusal must leave q untouched";
    return std::nullopt;
  }
  return q;
}

// That lowest_terms_in_words gives num/den's canonical numerator and
// denominator, compared as integers: Rational's == compares values, and
// would pass a result left unreduced.
void expect_lowest_terms(const Integer& num, const Integer& den) {
  const auto q = in_words(num, den);
  ASSERT_TRUE(q.has_value()) << num << "/" << den;
  const Rational expected = canonical(num, den);
  EXPECT_EQ(numerator(*q), numerator(expected)) << num << "/" << den;
  EXPECT_EQ(denominator(*q), denominator(expected)) << num << "/" << den;
}

GTEST_TEST(DixonWords, ReducesToLowestTermsAsGmpDoesForOperandsOfUpToTwoLimbs) {
  const Integer two_128 = Integer(1) << 128;
  // Common factors with up to 120 twos and odd parts of one and two limbs,
  // so that both mpn_gcd_1 and mpn_gcd answer and the twos span both
  // limbs, and numerators of either sign.
  std::mt19937_64 rng(20261128);
  int reduced_by_two_limbs = 0, twos_beyond_a_limb = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int g_bits = 1 + static_cast<int>(rng() % 100);
    Integer g = abs(random_integer(rng, g_bits));
    if (g == 0) g = 1;
    const int shift = std::min(static_cast<int>(rng() % 100), 120 - static_cast<int>(msb(g)));
    g <<= shift;
    const int room = 128 - static_cast<int>(msb(g)) - 1;
    const Integer a = random_integer(rng, 1 + static_cast<int>(rng() % room));
    Integer b = abs(random_integer(rng, 1 + static_cast<int>(rng() % room)));
    if (a == 0 || b == 0) continue;
    const Integer num = a * g, den = b * g;
    ASSERT_LT(abs(num), two_128);
    ASSERT_LT(den, two_128);
    expect_lowest_terms(num, den);
    const Integer common = gcd(num, den);
    if (msb(common) >= 64) ++reduced_by_two_limbs;
    if (lsb(common) >= 64) ++twos_beyond_a_limb;
  }
  EXPECT_GT(reduced_by_two_limbs, 100) << "two-limb gcds must be reached";
  EXPECT_GT(twos_beyond_a_limb, 50) << "common twos of 64 and more must be reached";
  // The edges: 1, powers of two on either side of the limbs' boundary, and
  // the two-limb maximum.
  const Integer max = two_128 - 1;
  const std::vector<Integer> edges = {
      1,   2,      3, Integer(1) << 63, Integer(1) << 64, Integer(3) << 64, (Integer(1) << 64) - 1, Integer(1) << 127,
      max, max - 1};
  for (const Integer& num : edges)
    for (const Integer& den : edges) {
      expect_lowest_terms(num, den);
      expect_lowest_terms(Integer(-num), den);
    }
  // Refusals: three limbs either side, a zero numerator, a denominator ≤ 0.
  EXPECT_EQ(in_words(two_128, 3), std::nullopt);
  EXPECT_EQ(in_words(Integer(-two_128), 3), std::nullopt);
  EXPECT_EQ(in_words(3, two_128), std::nullopt);
  EXPECT_EQ(in_words(0, 3), std::nullopt);
  EXPECT_EQ(in_words(3, 0), std::nullopt);
  EXPECT_EQ(in_words(3, -4), std::nullopt);
}

// The pointers block_in_words takes.
std::vector<const Integer*> pointers(const std::vector<Integer>& v) {
  std::vector<const Integer*> out;
  for (const Integer& x : v) out.push_back(&x);
  return out;
}

GTEST_TEST(DixonWords, TakesABlockInWordsExactlyUpToTheBoundsAndNoFurther) {
  const Integer entry_edge = (Integer(1) << 59) - 1, y_edge = (Integer(1) << 125) - 1;
  std::vector<Integer> c = {entry_edge, Integer(-entry_edge), Integer(0), Integer(-7)};
  std::vector<Integer> y = {y_edge, Integer(-y_edge)};
  std::vector<std::int64_t> c_words;
  std::vector<Int128> y_words;
  ASSERT_TRUE(block_in_words(2, pointers(c), pointers(y), c_words, y_words));
  for (std::size_t e = 0; e < c.size(); ++e) EXPECT_EQ(Integer(c_words[e]), c[e]) << "entry " << e;
  for (std::size_t a = 0; a < y.size(); ++a) EXPECT_EQ(from_word(y_words[a]), y[a]) << "row " << a;

  const auto rejected = [&](std::vector<Integer> c2, std::vector<Integer> y2) {
    return !block_in_words(2, pointers(c2), pointers(y2), c_words, y_words);
  };
  EXPECT_TRUE(rejected({Integer(1) << 59, Integer(0), Integer(0), Integer(1)}, y));
  EXPECT_TRUE(rejected({Integer(0), -(Integer(1) << 59), Integer(0), Integer(1)}, y));
  EXPECT_TRUE(rejected({Integer(0), Integer(0), Integer(1) << 64, Integer(1)}, y));  // two limbs
  EXPECT_TRUE(rejected(c, {Integer(1) << 125, Integer(0)}));
  EXPECT_TRUE(rejected(c, {Integer(0), -(Integer(1) << 125)}));
  EXPECT_TRUE(rejected(c, {Integer(0), Integer(1) << 128}));  // three limbs
  std::vector<Integer> big(17 * 17, Integer(1)), big_y(17, Integer(1));
  EXPECT_FALSE(block_in_words(17, pointers(big), pointers(big_y), c_words, y_words));  // k > 16
  EXPECT_FALSE(block_in_words(3, pointers(c), pointers(y), c_words, y_words));         // sizes not k
}

GTEST_TEST(DixonWords, SumsProductsInWordsAsGmpDoesUpToTheBoundsAndRefusesBeyond) {
  // Σ a_c·u_c against GMP's sum: random sizes and signs, then the largest
  // operands accepted (|a| = 2^63 − 1, |u| = 2^127 − 1, k = 16, every
  // product of one sign, so the sum nears 2^194), and one past each bound.
  std::mt19937_64 rng(21);
  const Integer a_edge = (Integer(1) << 63) - 1, u_edge = (Integer(1) << 127) - 1;
  auto gmp_dot = [](const std::vector<Integer>& a, const std::vector<Integer>& u) {
    Integer sum = 0;
    for (std::size_t c = 0; c < a.size(); ++c) sum += a[c] * u[c];
    return sum;
  };
  for (int trial = 0; trial < 400; ++trial) {
    const int k = 1 + trial % 16;
    std::vector<Integer> a(k), u(k);
    for (int c = 0; c < k; ++c) {
      a[c] = trial < 8 ? Integer(trial % 2 ? a_edge : Integer(-a_edge))
                       : random_integer(rng, 1 + static_cast<int>(rng() % 63));
      u[c] = trial < 8 ? Integer(trial % 4 < 2 ? u_edge : Integer(-u_edge))
                       : random_integer(rng, 1 + static_cast<int>(rng() % 127));
    }
    std::vector<mpz_srcptr> row;
    for (const Integer& x : a) row.push_back(mp(x));
    Integer sum = 12345;  // overwritten
    ASSERT_TRUE(dot_in_words(k, row.data(), u, sum)) << "trial " << trial;
    EXPECT_EQ(sum, gmp_dot(a, u)) << "trial " << trial;
  }
  std::vector<Integer> a = {Integer(3), Integer(-5)}, u = {Integer(7), Integer(11)};
  std::vector<mpz_srcptr> row = {mp(a[0]), mp(a[1])};
  Integer sum;
  ASSERT_TRUE(dot_in_words(2, row.data(), u, sum));
  EXPECT_EQ(sum, Integer(3 * 7 - 5 * 11));
  const Integer a_past = Integer(1) << 63, u_past = Integer(1) << 127;
  row[1] = mp(a_past);
  EXPECT_FALSE(dot_in_words(2, row.data(), u, sum));  // |a| = 2^63
  row[1] = mp(a[1]);
  std::vector<Integer> u_large = {Integer(7), Integer(-u_past)};
  EXPECT_FALSE(dot_in_words(2, row.data(), u_large, sum));  // |u| = 2^127
  std::vector<Integer> many(17, Integer(1));
  std::vector<mpz_srcptr> long_row(17, mp(many[0]));
  EXPECT_FALSE(dot_in_words(17, long_row.data(), many, sum));  // k > 16
}

// x from its base-p digits and p^s, by GMP.
Integer from_digits_by_gmp(const std::vector<mp_limb_t>& digits, std::uint64_t p) {
  Integer x = 0;
  for (std::size_t t = digits.size(); t-- > 0;) x = x * Integer(p) + Integer(digits[t]);
  return x;
}

GTEST_TEST(DixonWords, ComputesModuloPowersOfPInBasePDigitsAsGmpDoes) {
  // Digits, products, weighted sums and the way back, for s = 1..4, against
  // GMP's arithmetic modulo p^s: random values, and digits of p − 1 (the
  // largest columns and carries) and 0 (leading zeros).
  std::mt19937_64 rng(22);
  for (const std::uint64_t p : dixon_primes())
    for (int s = 1; s <= kPadicDigits; ++s) {
      const nmod_t mod = modulus(p);
      Integer M = 1;
      for (int t = 0; t < s; ++t) M *= Integer(p);
      auto random_digits = [&](int kind) {
        std::vector<mp_limb_t> d(s);
        for (mp_limb_t& x : d) x = kind == 0 ? p - 1 : kind == 1 ? 0 : rng() % p;
        if (kind == 3) d.back() = 0;  // a leading zero
        return d;
      };
      for (int trial = 0; trial < 200; ++trial) {
        SCOPED_TRACE("s " + std::to_string(s) + ", trial " + std::to_string(trial));
        // padic_digits of any x ≥ 0, up to 300 bits.
        Integer x = random_integer(rng, trial % 301);
        if (x < 0) x = -x;
        std::vector<mp_limb_t> digits(s);
        padic_digits(mp(x), s, mod, digits.data());
        for (const mp_limb_t t : digits) EXPECT_LT(t, p);
        EXPECT_EQ(from_digits_by_gmp(digits, p), Integer(x % M));
        Integer back;
        from_padic(digits.data(), s, mod, back);
        EXPECT_EQ(back, Integer(x % M));
        // padic_product.
        const std::vector<mp_limb_t> a = random_digits(trial % 4), b = random_digits((trial / 4) % 4);
        std::vector<mp_limb_t> product(s);
        padic_product(a.data(), b.data(), s, mod, product.data());
        for (const mp_limb_t t : product) EXPECT_LT(t, p);
        EXPECT_EQ(from_digits_by_gmp(product, p), Integer(from_digits_by_gmp(a, p) * from_digits_by_gmp(b, p) % M));
        // padic_weighted_sum, k up to 16 and once 1000.
        const int k = trial == 0 ? 1000 : 1 + trial % 16;
        std::vector<mp_limb_t> columns(static_cast<std::size_t>(s) * k);  // digit t of x_j at [t·k + j]
        for (mp_limb_t& t : columns) t = trial % 3 == 0 ? p - 1 : rng() % p;
        Integer expected = 0;
        for (int j = 0; j < k; ++j) {
          std::vector<mp_limb_t> xj(s);
          for (int t = 0; t < s; ++t) xj[t] = columns[static_cast<std::size_t>(t) * k + j];
          expected += Integer(j + 1) * from_digits_by_gmp(xj, p);
        }
        std::vector<mp_limb_t> sum(s);
        padic_weighted_sum(columns.data(), k, s, mod, sum.data());
        EXPECT_EQ(from_digits_by_gmp(sum, p), Integer(expected % M));
      }
    }
  Integer zero;
  const mp_limb_t zeros[kPadicDigits] = {0, 0, 0, 0};
  from_padic(zeros, kPadicDigits, modulus(dixon_primes()[0]), zero);
  EXPECT_EQ(zero, 0);
}

// C·digit ≡ rhs (mod p), by GMP.
void expect_solves_mod_p(int k, const std::vector<Integer>& c, const std::vector<std::uint64_t>& rhs,
                         const std::vector<mp_limb_t>& digit, std::uint64_t p) {
  for (int a = 0; a < k; ++a) {
    Integer sum = 0;
    for (int j = 0; j < k; ++j) sum += c[static_cast<std::size_t>(a) * k + j] * Integer(digit[j]);
    EXPECT_EQ(gmp_mod(sum, p), rhs[a]) << "row " << a;
  }
}

GTEST_TEST(DixonWords, FactorsModuloPAndSolvesEveryRightHandSide) {
  std::mt19937_64 rng(13);
  const std::uint64_t p = dixon_primes()[0];
  const nmod_t mod = modulus(p);
  int solved = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const int k = 1 + trial % 20;  // past 16: rows of more than 15 products
    const bool small = trial % 2 == 0;
    std::vector<Integer> c;
    for (int e = 0; e < k * k; ++e)
      c.push_back(rng() % 4 == 0 ? Integer(0) : random_integer(rng, small ? 58 : 130));  // zeros need swaps
    ModularLu from_integers;
    if (!from_integers.factor(k, pointers(c), mod)) continue;  // singular mod p: rare
    std::vector<std::uint64_t> rhs(k);
    for (std::uint64_t& x : rhs) x = rng() % p;
    std::vector<mp_limb_t> work(rhs.begin(), rhs.end()), digit;
    from_integers.solve(work, digit);
    SCOPED_TRACE(trial);
    expect_solves_mod_p(k, c, rhs, digit, p);
    ++solved;
    std::vector<std::int64_t> c_words;
    std::vector<Int128> y_words;
    std::vector<Integer> y(k, Integer(1));
    if (small && block_in_words(k, pointers(c), pointers(y), c_words, y_words)) {
      ModularLu from_words;
      ASSERT_TRUE(from_words.factor(k, c_words, mod));
      std::vector<mp_limb_t> work_words(rhs.begin(), rhs.end()), digit_words;
      from_words.solve(work_words, digit_words);
      EXPECT_EQ(digit_words, digit);
    }
  }
  EXPECT_GT(solved, 110);
}

GTEST_TEST(DixonWords, SumsLongRowsOfLargestProductsWithoutOverflow) {
  // C upper triangular with every entry −1 ≡ p − 1 and the solution
  // digit_j = p − 1: row 0's back substitution sums 19 products of
  // (p − 1)² ≈ 2^124, past 2^128, so it must reduce in parts.
  const std::uint64_t p = dixon_primes()[0];
  const int k = 20;
  std::vector<Integer> c(k * k, Integer(0));
  for (int a = 0; a < k; ++a)
    for (int j = a; j < k; ++j) c[static_cast<std::size_t>(a) * k + j] = Integer(-1);
  std::vector<std::uint64_t> rhs(k);
  for (int a = 0; a < k; ++a) rhs[a] = gmp_mod(Integer(k - a) * Integer(p - 1) * Integer(-1), p);
  ModularLu lu;
  ASSERT_TRUE(lu.factor(k, pointers(c), modulus(p)));
  std::vector<mp_limb_t> work(rhs.begin(), rhs.end()), digit;
  lu.solve(work, digit);
  EXPECT_EQ(digit, std::vector<mp_limb_t>(k, p - 1));
  expect_solves_mod_p(k, c, rhs, digit, p);
}

GTEST_TEST(DixonWords, RefusesABlockSingularModuloP) {
  const std::uint64_t p = dixon_primes()[0];
  ModularLu lu;
  const std::vector<Integer> multiple = {Integer(p), Integer(0), Integer(0), Integer(1)};  // det = p
  EXPECT_FALSE(lu.factor(2, pointers(multiple), modulus(p)));
  const std::vector<std::int64_t> rank_one = {2, -4, -3, 6};
  EXPECT_FALSE(lu.factor(2, rank_one, modulus(p)));
  EXPECT_TRUE(lu.factor(2, pointers(multiple), modulus(dixon_primes()[1])));
}

}  // namespace
}  // namespace fixel::internal
