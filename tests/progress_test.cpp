// RunControl's time limit (include/fixel/progress.h): a limit beyond what
// steady_clock can hold sets none, instead of a deadline in the past. And
// ControlScope: which control the exact steps inside one call poll.
#include "fixel/progress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <thread>

#include <limits>
#include "test_util.h"

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

GTEST_TEST(ControlScope, WithoutAScopeAnExactStepPollsNothing) { EXPECT_NO_THROW(internal::poll_exact_step()); }

GTEST_TEST(ControlScope, InsideAScopeAnExactStepStopsWithTheInnermostTaskNamed) {
  const test::CancelledControl c;
  const ControlScope scope(&c.control);
  EXPECT_EQ(test::stop_message([] { internal::poll_exact_step(); }),
            "exact arithmetic: interrupted after 0 exact steps; no result");
  const internal::ExactTask task("building it");
  EXPECT_EQ(test::stop_message([] { internal::poll_exact_step(); }),
            "building it: interrupted after 0 exact steps; no result");
}

GTEST_TEST(ControlScope, APastDeadlineIsATimeLimitStop) {
  RunControl control;
  control.deadline = RunControl::Clock::now() - std::chrono::seconds(1);
  const ControlScope scope(&control);
  try {
    internal::poll_exact_step();
    ADD_FAILURE() << "no stop";
  } catch (const StoppedError& e) {
    EXPECT_EQ(e.reason(), StopReason::kTimeLimit);
  }
}

GTEST_TEST(ControlScope, ScopesNestAndTheOuterOneAppliesAgainAfterAnInnerOneEnds) {
  const test::CancelledControl c;
  const ControlScope outer(&c.control);
  {
    const ControlScope none(nullptr);  // as design() sets
    EXPECT_NO_THROW(internal::poll_exact_step());
    const internal::ControlScopeIfGiven not_given(nullptr);  // keeps `none`
    EXPECT_NO_THROW(internal::poll_exact_step());
  }
  {
    const internal::ControlScopeIfGiven not_given(nullptr);  // keeps `outer`
    EXPECT_THROW(internal::poll_exact_step(), StoppedError);
  }
  EXPECT_THROW(internal::poll_exact_step(), StoppedError);
}

GTEST_TEST(ControlScope, AnExactStepReportsNoProgressSoAnyThreadMayPollTheSameControl) {
  RunControl control;
  int reports = 0;
  control.interval = std::chrono::milliseconds(0);
  control.start = RunControl::Clock::now() - std::chrono::seconds(5);
  control.on_progress = [&](const char*, long, long, const char*) { ++reports; };
  const ControlScope scope(&control);
  for (int k = 0; k < 3; ++k) internal::poll_exact_step();
  EXPECT_EQ(reports, 0);
  control.poll("loop", 1, 2, "units");  // the loop's own poll reports
  EXPECT_EQ(reports, 1);
}

GTEST_TEST(ControlScope, AScopeIsPerThread) {
  const test::CancelledControl c;
  const ControlScope scope(&c.control);
  bool stopped_elsewhere = false;
  std::thread other([&] {
    try {
      internal::poll_exact_step();
    } catch (const StoppedError&) {
      stopped_elsewhere = true;
    }
  });
  other.join();
  EXPECT_FALSE(stopped_elsewhere);
  EXPECT_THROW(internal::poll_exact_step(), StoppedError);
}

GTEST_TEST(ControlScope, AnExactStepInsideALoopThatPollsIsToldAsTheLoopsPoll) {
  RunControl control;
  {
    const internal::ControlScopeIfGiven scope(&control);  // as simulate opens
    control.poll("simulate", 3, 10, "steps");             // the loop's own poll, before its step's exact work
    control.cancel = true;
    const internal::ExactTask task("LCP (Lemke)");
    EXPECT_EQ(test::stop_message([] { internal::poll_exact_step(); }),
              "simulate: interrupted after 3 of 10 steps; no result");
  }
  // Outside that scope the loop's poll is forgotten: the task is named.
  const ControlScope later(&control);
  const internal::ExactTask task("sustained set J");
  EXPECT_EQ(test::stop_message([] { internal::poll_exact_step(); }),
            "sustained set J: interrupted after 0 exact steps; no result");
}

GTEST_TEST(ControlScope, OnlyALoopsScopeRecordsItsPolls) {
  const test::CancelledControl cancelled;
  RunControl other;
  const internal::ControlScopeIfGiven scope(&cancelled.control);
  other.poll("elsewhere", 1, 2, "units");  // not the scope's control
  EXPECT_EQ(test::stop_message([] { internal::poll_exact_step(); }),
            "exact arithmetic: interrupted after 0 exact steps; no result");
  RunControl reading;  // a caller's scope (the CLI's): its polls, as a file's reading, name no later stop
  const ControlScope caller(&reading);
  reading.poll("load", 0, 6, "points read");
  reading.cancel = true;
  EXPECT_EQ(test::stop_message([] { internal::poll_exact_step(); }),
            "exact arithmetic: interrupted after 0 exact steps; no result");
}

}  // namespace
}  // namespace fixel
