// Tests of try_within (lib/include/implicitizer/core/try_within.hpp): only the work
// allowance hands over; the caller's own limits propagate with their own names.

#include "implicitizer/core/try_within.hpp"

#include <gtest/gtest.h>

namespace implicitizer {
namespace {

// Charges `units` one at a time, as a reduction loop does, and returns how many.
int spend(const Budget& budget, int units) {
  for (int i = 0; i < units; ++i) budget.charge_work(1, "test loop");
  return units;
}

TEST(TryWithin, ReturnsTheResultWhenTheAllowanceSuffices) {
  const Budget budget;
  const auto result = try_within(budget, 100, [](const Budget& trial) { return spend(trial, 100); });
  ASSERT_TRUE(result);
  EXPECT_EQ(*result, 100);
}

TEST(TryWithin, ReturnsNulloptWhenTheAllowanceRunsOut) {
  const Budget budget;
  EXPECT_FALSE(try_within(budget, 100, [](const Budget& trial) { return spend(trial, 101); }));
  // The caller's budget has no allowance of its own and was not charged.
  EXPECT_EQ(budget.work_done(), 0u);
}

TEST(TryWithin, TheSameInputGetsTheSameVerdict) {
  // What decides is the work done, not the time taken: no run can differ.
  for (int run = 0; run < 20; ++run) {
    EXPECT_TRUE(try_within(Budget(), 50, [](const Budget& trial) { return spend(trial, 50); }));
    EXPECT_FALSE(try_within(Budget(), 50, [](const Budget& trial) { return spend(trial, 51); }));
  }
}

TEST(TryWithin, TheCallersLimitsPropagate) {
  Budget cancelled;
  cancelled.cancel();
  try {
    try_within(cancelled, 100, [](const Budget& trial) {
      trial.check("test loop");
      return 0;
    });
    ADD_FAILURE() << "cancellation did not propagate";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
  Budget sized;
  sized.set_max_terms(10);
  try {
    try_within(sized, 100, [](const Budget& trial) {
      trial.check_terms(11, "test loop");
      return 0;
    });
    ADD_FAILURE() << "the term limit did not propagate";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
  }
}

TEST(TryWithin, AnInnerAllowanceReplacesAnOuterOne) {
  Budget outer;
  outer.set_max_work(5);
  EXPECT_TRUE(try_within(outer, 100, [](const Budget& trial) { return spend(trial, 100); }));
  EXPECT_EQ(outer.work_done(), 0u);
}

}  // namespace
}  // namespace implicitizer
