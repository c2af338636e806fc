#include "fixel/verify.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace fixel
