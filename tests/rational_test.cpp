#include "fixel/rational.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "fixel/error.h"

namespace fixel {
namespace {

GTEST_TEST(ParseRational, ReadsDecimalsExactly) {
  EXPECT_EQ(parse_rational("0.1"), Rational(1, 10));
  EXPECT_EQ(parse_rational("-0.05"), Rational(-1, 20));
  EXPECT_EQ(parse_rational(".5"), Rational(1, 2));
  EXPECT_EQ(parse_rational("3."), Rational(3));
  EXPECT_EQ(parse_rational("+2"), Rational(2));
}

GTEST_TEST(ParseRational, ReadsFractionsInLowestTerms) {
  EXPECT_EQ(parse_rational("-3/7"), Rational(-3, 7));
  EXPECT_EQ(parse_rational("6/4"), Rational(3, 2));
  EXPECT_EQ(to_string(parse_rational("6/4")), "3/2");
}

GTEST_TEST(ParseRational, LeadingZerosAreDecimalNotOctal) {
  EXPECT_EQ(parse_rational("010"), Rational(10));
  EXPECT_EQ(parse_rational("0.8911"), Rational(8911, 10000));
  EXPECT_EQ(parse_rational("007/010"), Rational(7, 10));
  EXPECT_EQ(parse_rational("0e5"), Rational(0));
  EXPECT_EQ(parse_rational("-0"), Rational(0));
}

GTEST_TEST(ParseRational, AcceptsExponents) {
  EXPECT_EQ(parse_rational("1e-3"), Rational(1, 1000));
  EXPECT_EQ(parse_rational("2.5E2"), Rational(250));
  EXPECT_EQ(parse_rational("-1.25e+1"), Rational(-25, 2));
  EXPECT_EQ(parse_rational("1e-30"), Rational(Integer(1), boost::multiprecision::pow(Integer(10), 30)));
}

GTEST_TEST(ParseRational, ReadsDigitsBeyondDoublePrecisionExactly) {
  // 0.1000000000000000000001 is not a double; the difference must survive.
  EXPECT_NE(parse_rational("0.1000000000000000000001"), Rational(1, 10));
  EXPECT_EQ(parse_rational("0.1000000000000000000001") - Rational(1, 10), parse_rational("1e-22"));
}

GTEST_TEST(ParseRational, RejectsMalformedTextNamingTheField) {
  for (const char* bad :
       {"", "abc", "1/0", "1/-2", "--1", "1e", "1.2.3", " 1", "1 ", "0x10", "nan", "inf", ".", "e5", "1/2/3"}) {
    try {
      parse_rational(bad, "fixels[0].mu");
      ADD_FAILURE() << "accepted \"" << bad << "\"";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.field(), "fixels[0].mu");
      EXPECT_NE(std::string(e.what()).find("fixels[0].mu"), std::string::npos);
    }
  }
}

GTEST_TEST(ParseRational, RejectsHugeExponentsInsteadOfExhaustingMemory) {
  EXPECT_THROW(parse_rational("1e999999999"), ParseError);
  EXPECT_EQ(parse_rational("1e10000"), Rational(boost::multiprecision::pow(Integer(10), 10000)));
}

GTEST_TEST(ParseRationalList, SplitsOnCommasAndNamesTheBadEntry) {
  const auto v = parse_rational_list("-1,1/2,0.25");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[1], Rational(1, 2));
  try {
    parse_rational_list("1,x", "--impulse");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.field(), "--impulse[1]");
  }
}

GTEST_TEST(ToString, PrintsIntegersWithoutDenominator) {
  EXPECT_EQ(to_string(Rational(-4)), "-4");
  EXPECT_EQ(to_string(Rational(0)), "0");
  EXPECT_EQ(to_string(Rational(-161, 202)), "-161/202");
}

// Exact check of round-to-nearest: no double is closer to q than x, and on
// a tie x is the one with an even last bit.
bool nearest(double x, const Rational& q) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const Rational err = abs(Rational(x) - q);
  for (double y : {std::nextafter(x, -inf), std::nextafter(x, inf)}) {
    const Rational other = abs(Rational(y) - q);
    if (other < err) return false;
    if (other == err) {
      std::int64_t bits_x;
      std::memcpy(&bits_x, &x, 8);
      if (bits_x & 1) return false;
    }
  }
  return true;
}

GTEST_TEST(ToDouble, RoundsEveryRationalToTheNearestDoubleOnBothPaths) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 20000; ++trial) {
    // Numerator and denominator from 1 to 70 bits: both sides of the 53-bit
    // one-division path.
    auto draw = [&](int bits) {
      Integer v = 1;
      for (int b = 1; b < bits; ++b) v = 2 * v + static_cast<int>(rng() & 1);
      return v;
    };
    const int nb = 1 + static_cast<int>(rng() % 70), db = 1 + static_cast<int>(rng() % 70);
    Rational q(draw(nb), draw(db));
    if (rng() & 1) q = -q;
    const double x = to_double(q);
    ASSERT_TRUE(nearest(x, q)) << to_string(q) << " -> " << x;
    ASSERT_EQ(x, q.convert_to<double>()) << to_string(q);
  }
  EXPECT_EQ(to_double(Rational(0)), 0.0);
  EXPECT_FALSE(std::signbit(to_double(Rational(0))));
  EXPECT_EQ(to_double(Rational(-1, 3)), -1.0 / 3.0);
}

}  // namespace
}  // namespace fixel
