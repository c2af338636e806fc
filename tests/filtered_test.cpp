// The semi-static dot-product filter of internal/filtered.h (the pair
// bound's walk): every sign it gives is the exact sign, compared as exact
// values, in every rounding mode; what it cannot vouch for it leaves open.
#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <random>

#include "fixel/internal/filtered.h"

namespace fixel {
namespace {

using internal::FI;
using internal::kUndecided;
using internal::Near3;

Near3 near_of(const VectorQ& v) {
  return internal::near3({internal::to_interval(v[0]), internal::to_interval(v[1]), internal::to_interval(v[2])});
}

VectorQ vec(const Rational& x, const Rational& y, const Rational& z) {
  VectorQ v(3);
  v << x, y, z;
  return v;
}

// A rational of up to 60-bit numerator and denominator, either sign, zero
// now and then.
Rational random_entry(std::mt19937_64& rng) {
  if (rng() % 9 == 0) return Rational(0);
  const Integer num(rng() >> (4 + rng() % 60)), den(1 + (rng() >> (4 + rng() % 60)));
  return Rational(rng() % 2 ? -num : num, den);
}

VectorQ random_vector(std::mt19937_64& rng) { return vec(random_entry(rng), random_entry(rng), random_entry(rng)); }

VectorQ cross(const VectorQ& a, const VectorQ& b) {
  return vec(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

const int kModes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};

// The filter's sign in rounding mode `mode`, the caller's mode restored.
int sign_in_mode(const Near3& a, const Near3& g, int mode) {
  const int old_mode = std::fegetround();
  std::fesetround(mode);
  const int s = internal::static_dot_sign(a, g);
  std::fesetround(old_mode);
  return s;
}

GTEST_TEST(StaticDotSign, EverySignItGivesOnRandomVectorsIsTheExactSignAndMostAreGiven) {
  std::mt19937_64 rng(31);
  int given = 0, trials = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const VectorQ a = random_vector(rng), g = random_vector(rng);
    const int exact = sign(a.dot(g));
    for (const int mode : kModes) {
      const int s = sign_in_mode(near_of(a), near_of(g), mode);
      ++trials;
      if (s == kUndecided) continue;
      ++given;
      ASSERT_EQ(s, exact) << "a " << a.transpose() << " g " << g.transpose() << " mode " << mode;
    }
  }
  EXPECT_GT(given, trials * 9 / 10);
}

// a · (a × h) = 0 exactly, with nonzero products whose rounded sum is
// usually not zero: a filter without its margin gives a sign here. Pushed
// off zero by a relative 2^-k, the sign is given only when it is right.
GTEST_TEST(StaticDotSign, ProductsSummingToZeroOrNearlyAreLeftOpenOrSignedRight) {
  std::mt19937_64 rng(32);
  int open_at_zero = 0, signed_off_zero = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const VectorQ a = random_vector(rng), h = random_vector(rng);
    const VectorQ g0 = cross(a, h);
    if (a.isZero() || g0.isZero()) continue;
    for (const int mode : kModes) {
      const int s = sign_in_mode(near_of(a), near_of(g0), mode);
      ASSERT_TRUE(s == kUndecided || s == 0) << "a " << a.transpose() << " g " << g0.transpose();
      if (s == kUndecided) ++open_at_zero;
    }
    for (const int k : {20, 40, 45, 50, 60, 80}) {
      const VectorQ g = g0 + Rational(Integer(1), Integer(1) << k) * a;  // a · g = 2^-k |a|²
      const int exact = sign(a.dot(g));
      for (const int mode : kModes) {
        const int s = sign_in_mode(near_of(a), near_of(g), mode);
        if (s == kUndecided) continue;
        ASSERT_EQ(s, exact) << "k " << k << " a " << a.transpose() << " g " << g.transpose();
        ++signed_off_zero;
      }
    }
  }
  EXPECT_GT(open_at_zero, 1000);
  EXPECT_GT(signed_off_zero, 1000);  // the 2^-20 shifts, at least
}

GTEST_TEST(StaticDotSign, ExactZerosGiveZeroAndEntriesOutOfItsRangeLeaveTheSignOpen) {
  EXPECT_EQ(internal::static_dot_sign(near_of(vec(0, 0, Rational(1, 3))), near_of(vec(5, Rational(-2, 7), 0))), 0);
  EXPECT_EQ(internal::static_dot_sign(near_of(vec(1, 2, 3)), near_of(vec(0, 0, 0))), 0);
  // 1/3 · 2^-600: its enclosure is below 2^-500, where products may round
  // to subnormals; 2^600 + 1/3 is above 2^500.
  const Rational tiny = Rational(1, 3) / Rational(Integer(1) << 600);
  const Rational huge = Rational(Integer(1) << 600) + Rational(1, 3);
  EXPECT_FALSE(near_of(vec(tiny, 1, 1)).valid);
  EXPECT_FALSE(near_of(vec(1, huge, 1)).valid);
  EXPECT_EQ(internal::static_dot_sign(near_of(vec(tiny, 1, 1)), near_of(vec(1, 1, 1))), kUndecided);
  EXPECT_EQ(internal::static_dot_sign(near_of(vec(1, 1, 1)), near_of(vec(1, huge, 1))), kUndecided);
  // An exact double, even tiny, has no rounding error, but products of
  // such can underflow: below 2^-500 it is refused too.
  EXPECT_FALSE(near_of(vec(Rational(1) / Rational(Integer(1) << 600), 0, 0)).valid);
  // A wide enclosure (more than 2^-50 relative) is refused.
  EXPECT_FALSE(internal::near3({FI(1, 1 + 0x1p-40), FI(1), FI(1)}).valid);
  EXPECT_TRUE(internal::near3({FI(1, 1 + 0x1p-52), FI(-2), FI(0)}).valid);
  EXPECT_FALSE(internal::near3({FI(-0x1p-52, 0x1p-52), FI(1), FI(1)}).valid);  // straddles zero
}

}  // namespace
}  // namespace fixel
