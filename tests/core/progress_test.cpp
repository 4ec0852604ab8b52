#include "implicitizer/core/progress.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <thread>

#include "implicitizer/core/budget.hpp"

namespace implicitizer {
namespace {

TEST(Progress, FractionIsKnownOnlyWithATotal) {
  EXPECT_LT((ProgressReport{"p", 3, 0}.fraction()), 0) << "no total: unknown";
  EXPECT_DOUBLE_EQ((ProgressReport{"p", 1, 4}.fraction()), 0.25);
  EXPECT_DOUBLE_EQ((ProgressReport{"p", 9, 4}.fraction()), 1.0) << "clamped";
}

TEST(Progress, EveryCopyOfABudgetSharesOneSink) {
  const Budget budget = Budget::with_timeout(60);
  EXPECT_EQ(budget.progress().step().phase, nullptr) << "nothing reported yet";
  Budget copy = budget;
  copy.set_max_work(1000);  // try_within's trial: a copy with its own allowance, same sink
  std::thread worker([copy] {
    copy.report_stage("outer", 2, 0);
    copy.report_step("inner", 5, 10);
  });
  worker.join();
  const ProgressReport step = budget.progress().step();
  ASSERT_NE(step.phase, nullptr);
  EXPECT_STREQ(step.phase, "inner");
  EXPECT_EQ(step.done, 5U);
  EXPECT_EQ(step.total, 10U);
  EXPECT_STREQ(budget.progress().stage().phase, "outer");
  EXPECT_EQ(budget.progress().stage().done, 2U);
  // A budget made apart has a sink of its own.
  EXPECT_EQ(Budget().progress().step().phase, nullptr);
}

}  // namespace
}  // namespace implicitizer
