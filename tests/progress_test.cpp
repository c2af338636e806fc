// RunControl's time limit (include/fixel/progress.h): a limit beyond what
// steady_clock can hold sets none, instead of a deadline in the past.
#include "fixel/progress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fixel {
namespace {

using Clock = RunControl::Clock;

GTEST_TEST(RunControl, ATimeLimitSetsADeadlineThatManySecondsAhead) {
  RunControl control;
  const Clock::time_point from = Clock::now();
  control.set_time_limit(2.5, "max_seconds", from);
  ASSERT_TRUE(control.deadline.has_value());
  EXPECT_EQ(*control.deadline - from, std::chrono::milliseconds(2500));
  EXPECT_NO_THROW(control.poll("test", 0, 0, "units"));  // 2.5 s ahead: not past
}

GTEST_TEST(RunControl, ALimitOfABillionSecondsOrMoreSetsNoDeadlineAndNeverStops) {
  // 1e10 s in nanoseconds overflowed int64 once: the deadline fell in the
  // past, and the run stopped at its first poll.
  for (const double limit : {RunControl::kNoLimitSeconds, 1e10, 1e300, std::numeric_limits<double>::infinity()}) {
    RunControl control;
    control.deadline = Clock::now();  // a limit set before is replaced
    control.set_time_limit(limit);
    EXPECT_FALSE(control.deadline.has_value()) << limit;
    EXPECT_NO_THROW(control.poll("test", 0, 0, "units")) << limit;
  }
  RunControl just_below;
  just_below.set_time_limit(RunControl::kNoLimitSeconds / 2);
  EXPECT_TRUE(just_below.deadline.has_value());
}

GTEST_TEST(RunControl, ALimitThatIsNotPositiveIsAnInputErrorNamingTheField) {
  for (const double limit : {0.0, -1.0, -std::numeric_limits<double>::infinity(), std::nan("")}) {
    RunControl control;
    try {
      control.set_time_limit(limit, "--max-seconds");
      ADD_FAILURE() << limit;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "--max-seconds");
      EXPECT_NE(std::string(e.what()).find("must be a positive number of seconds"), std::string::npos);
    }
    EXPECT_FALSE(control.deadline.has_value());
  }
  RunControl zero;
  try {
    zero.set_time_limit(0);
  } catch (const InputError& e) {
    EXPECT_EQ(e.value(), "0");  // not std::to_string's "0.000000"
  }
}

}  // namespace
}  // namespace fixel
