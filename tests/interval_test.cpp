// Magnitudes, the intervals of impulse magnitudes (include/fixel/interval.h).
#include "fixel/interval.h"

#include <gtest/gtest.h>

#include "fixel/error.h"

namespace fixel {
namespace {

GTEST_TEST(Magnitudes, EndsThatCrossLeaveTheIntervalEmpty) {
  EXPECT_TRUE(Magnitudes::make(Rational(2), true, Rational(1), true).empty);
  EXPECT_TRUE(Magnitudes::make(Rational(1), true, Rational(1), false).empty);
  const Magnitudes point = Magnitudes::make(Rational(1), true, Rational(1), true);
  EXPECT_FALSE(point.empty);
  EXPECT_TRUE(point.contains(Rational(1)));
  const Magnitudes half_line = Magnitudes::make(Rational(0), false, std::nullopt, true);
  EXPECT_TRUE(half_line.half_line());
  EXPECT_FALSE(half_line.hi_closed);  // an infinite end is never closed
  EXPECT_FALSE(half_line.contains(Rational(0)));
  EXPECT_TRUE(half_line.contains(Rational(1, 1000)));
}

// Magnitudes are >= 0; a negative lower end was taken as it came.
GTEST_TEST(Magnitudes, ANegativeLowerEndIsAnInputErrorNamingIt) {
  try {
    Magnitudes::make(Rational(-1), true, std::nullopt, false);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "lo");
    EXPECT_EQ(e.value(), "-1");
  }
  EXPECT_NO_THROW(Magnitudes::make(Rational(0), true, std::nullopt, false));
}

}  // namespace
}  // namespace fixel
