#include "fixel/verify.h"

#include <gtest/gtest.h>

#include "fixel/error.h"

namespace fixel {
namespace {

GTEST_TEST(Verify, EveryBuiltInCheckPasses) {
  const auto checks = run_verification();
  EXPECT_GE(checks.size(), 9u);
  for (const auto& c : checks) EXPECT_TRUE(c.passed) << c.name << ": " << c.detail;
}

GTEST_TEST(RoundDecimal, RoundsHalfAwayFromZeroExactly) {
  EXPECT_EQ(round_decimal(Rational(90, 101), 4), parse_rational("0.8911"));
  EXPECT_EQ(round_decimal(Rational(-38, 505), 4), parse_rational("-0.0752"));
  EXPECT_EQ(round_decimal(parse_rational("0.00005"), 4), parse_rational("0.0001"));
  EXPECT_EQ(round_decimal(parse_rational("0.000049999999999999999"), 4), Rational(0));
  EXPECT_EQ(round_decimal(parse_rational("-0.00005"), 4), parse_rational("-0.0001"));
}

// -1 became 10^4294967295 through an unsigned cast, and ran for ever.
GTEST_TEST(RoundDecimal, PlacesOutsideZeroToTheLimitAreAnInputError) {
  EXPECT_THROW(round_decimal(Rational(1, 3), -1), InputError);
  EXPECT_THROW(round_decimal(Rational(1, 3), kMaxRoundDecimals + 1), InputError);
  EXPECT_EQ(round_decimal(Rational(1, 3), 0), Rational(0));
  EXPECT_EQ(round_decimal(Rational(2, 3), 0), Rational(1));
}

}  // namespace
}  // namespace fixel
