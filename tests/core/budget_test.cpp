// Tests of Budget (lib/src/core/budget.cpp): each limit fires with its own Limit value
// and a message that names the loop that was running.

#include "implicitizer/core/budget.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

namespace implicitizer {
namespace {

// Runs `f`, expects LimitExceeded with `limit`, and returns its message.
template <typename F>
std::string limit_message(F f, Limit limit) {
  try {
    f();
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), limit) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no LimitExceeded thrown (expected " << to_string(limit) << ")";
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Budget, UnlimitedByDefault) {
  const Budget budget;
  EXPECT_NO_THROW(budget.check("anything"));
  EXPECT_NO_THROW(budget.check_terms(1'000'000'000, "anything"));
  EXPECT_EQ(budget.max_terms(), 0u);
  EXPECT_EQ(budget.timeout_seconds(), 0.0);
  EXPECT_TRUE(std::isinf(budget.seconds_left()));
  EXPECT_FALSE(budget.is_cancelled());
}

TEST(Budget, TimeoutFiresWithLimitTime) {
  const Budget budget = Budget::with_timeout(0.02);
  EXPECT_NO_THROW(budget.check("buchberger"));
  EXPECT_GT(budget.seconds_left(), 0.0);
  EXPECT_LE(budget.seconds_left(), 0.02);
  std::this_thread::sleep_for(std::chrono::milliseconds(40));
  EXPECT_LT(budget.seconds_left(), 0.0);
  const std::string message = limit_message([&] { budget.check("buchberger"); }, Limit::time);
  EXPECT_TRUE(contains(message, "buchberger")) << message;
  EXPECT_TRUE(contains(message, "0.02")) << message;
  // check_terms also checks the time.
  limit_message([&] { budget.check_terms(1, "reduction"); }, Limit::time);
}

// A timeout longer than the clock's range (std::chrono nanoseconds hold ~292 years)
// must not wrap around into the past and fire at once.
TEST(Budget, HugeTimeoutNeverFires) {
  for (double seconds : {1e9, 1e10, 1e12, 1e300, std::numeric_limits<double>::infinity()}) {
    const Budget budget = Budget::with_timeout(seconds);
    EXPECT_NO_THROW(budget.check("loop")) << seconds;
    EXPECT_GT(budget.seconds_left(), 1e8) << seconds;
    EXPECT_EQ(budget.timeout_seconds(), seconds);
  }
}

TEST(Budget, NonPositiveTimeoutMeansNone) {
  Budget budget = Budget::with_timeout(0.01);
  budget.set_timeout(0);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_NO_THROW(budget.check("loop"));
  EXPECT_EQ(budget.timeout_seconds(), 0.0);
  EXPECT_TRUE(std::isinf(budget.seconds_left()));
  EXPECT_NO_THROW(Budget::with_timeout(-1).check("loop"));
  EXPECT_NO_THROW(Budget::with_timeout(std::numeric_limits<double>::quiet_NaN()).check("loop"));
}

TEST(Budget, CancelFiresWithLimitCancelledInEveryCopy) {
  const Budget budget;
  const Budget copy = budget;  // e.g. handed to a worker thread
  budget.cancel();
  EXPECT_TRUE(copy.is_cancelled());
  const std::string message = limit_message([&] { copy.check("resultant"); }, Limit::cancelled);
  EXPECT_TRUE(contains(message, "resultant")) << message;
  limit_message([&] { budget.check_terms(0, "resultant"); }, Limit::cancelled);
}

TEST(Budget, CancelFromAnotherThread) {
  const Budget budget = Budget::with_timeout(10);
  std::thread canceller([copy = budget] { copy.cancel(); });
  canceller.join();
  limit_message([&] { budget.check("worker"); }, Limit::cancelled);
}

TEST(Budget, CancellationIsReportedBeforeTime) {
  const Budget budget = Budget::with_timeout(0.001);
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  budget.cancel();
  limit_message([&] { budget.check("loop"); }, Limit::cancelled);
}

TEST(Budget, IndependentBudgetsDoNotShareCancellation) {
  const Budget a, b;
  a.cancel();
  EXPECT_FALSE(b.is_cancelled());
  EXPECT_NO_THROW(b.check("loop"));
}

TEST(Budget, CheckTermsFiresWithLimitSize) {
  Budget budget;
  budget.set_max_terms(100);
  EXPECT_EQ(budget.max_terms(), 100u);
  EXPECT_NO_THROW(budget.check_terms(100, "s-polynomial reduction"));
  const std::string message = limit_message([&] { budget.check_terms(101, "s-polynomial reduction"); }, Limit::size);
  EXPECT_TRUE(contains(message, "s-polynomial reduction")) << message;
  EXPECT_TRUE(contains(message, "101")) << message;
  EXPECT_TRUE(contains(message, "100")) << message;
  // The size limit does not apply to check(), only to check_terms().
  EXPECT_NO_THROW(budget.check("s-polynomial reduction"));
  budget.set_max_terms(0);
  EXPECT_NO_THROW(budget.check_terms(1'000'000, "loop"));
}

TEST(Budget, SizeIsReportedBeforeCancellation) {
  Budget budget;
  budget.set_max_terms(1);
  budget.cancel();
  limit_message([&] { budget.check_terms(2, "loop"); }, Limit::size);
}

TEST(Limit, Names) {
  EXPECT_STREQ(to_string(Limit::time), "time");
  EXPECT_STREQ(to_string(Limit::size), "size");
  EXPECT_STREQ(to_string(Limit::cancelled), "cancelled");
}

}  // namespace
}  // namespace implicitizer
