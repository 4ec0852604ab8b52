#include "worker_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <thread>

namespace implicitizer::server {
namespace {

using namespace std::chrono_literals;

// A job that blocks until `release` is set or its budget is cancelled.
WorkerPool::Job blocking_job(std::shared_future<void> release, std::atomic<int>& done, std::atomic<int>& cancelled) {
  Budget budget;
  return {[release, budget, &done, &cancelled] {
            while (release.wait_for(1ms) != std::future_status::ready) {
              if (budget.is_cancelled()) {
                ++cancelled;
                return;
              }
            }
            ++done;
          },
          budget};
}

TEST(WorkerPool, RunsEveryAcceptedJob) {
  std::atomic<int> count{0};
  {
    WorkerPool pool(2, 100);
    for (int i = 0; i < 50; ++i) {
      WorkerPool::Job job{[&count] { ++count; }, Budget()};
      ASSERT_TRUE(pool.try_submit(job));
    }
    EXPECT_EQ(pool.shutdown(5s, 5s), 0u);
  }
  EXPECT_EQ(count.load(), 50);
}

TEST(WorkerPool, WithdrawTakesBackAQueuedJobOnly) {
  std::promise<void> release;
  std::shared_future<void> gate = release.get_future().share();
  std::atomic<int> done{0};
  std::atomic<int> cancelled{0};
  WorkerPool pool(1, 1);
  WorkerPool::Job first = blocking_job(gate, done, cancelled);
  const std::optional<WorkerPool::Ticket> running = pool.try_submit(first);
  ASSERT_TRUE(running);
  // Polled for up to a minute: a loaded machine may start the worker late.
  for (int i = 0; i < 12000 && pool.busy() != 1; ++i) std::this_thread::sleep_for(5ms);
  ASSERT_EQ(pool.busy(), 1u);
  std::atomic<int> second_ran{0};
  WorkerPool::Job second{[&second_ran] { ++second_ran; }, Budget()};
  const std::optional<WorkerPool::Ticket> queued = pool.try_submit(second);
  ASSERT_TRUE(queued);
  EXPECT_NE(*queued, *running);
  EXPECT_FALSE(pool.withdraw(*running)) << "a started job is stopped by its budget, not taken back";
  std::optional<WorkerPool::Job> back = pool.withdraw(*queued);
  ASSERT_TRUE(back);
  EXPECT_TRUE(static_cast<bool>(back->run));
  EXPECT_EQ(pool.queued(), 0u);
  EXPECT_FALSE(pool.withdraw(*queued)) << "taken back once";
  WorkerPool::Job third{[] {}, Budget()};
  EXPECT_TRUE(pool.try_submit(third)) << "the withdrawn job's slot is free";
  release.set_value();
  EXPECT_EQ(pool.shutdown(60s, 5s), 0u);
  EXPECT_EQ(second_ran.load(), 0) << "a withdrawn job never runs";
  EXPECT_EQ(done.load(), 1);
}

TEST(WorkerPool, RefusesBeyondThreadsPlusQueueCapacity) {
  std::promise<void> release;
  std::shared_future<void> gate = release.get_future().share();
  std::atomic<int> done{0};
  std::atomic<int> cancelled{0};
  WorkerPool pool(1, 2);
  for (int i = 0; i < 3; ++i) {
    WorkerPool::Job job = blocking_job(gate, done, cancelled);
    EXPECT_TRUE(pool.try_submit(job)) << i;
  }
  WorkerPool::Job extra = blocking_job(gate, done, cancelled);
  EXPECT_FALSE(pool.try_submit(extra));
  EXPECT_EQ(pool.rejected(), 1u);
  EXPECT_TRUE(static_cast<bool>(extra.run)) << "a refused job is left to the caller";
  // One job runs, two wait.
  // Polled for up to a minute: a loaded machine may start the worker late.
  for (int i = 0; i < 12000 && pool.busy() != 1; ++i) std::this_thread::sleep_for(5ms);
  EXPECT_EQ(pool.busy(), 1u);
  EXPECT_EQ(pool.queued(), 2u);
  release.set_value();
  EXPECT_EQ(pool.shutdown(60s, 5s), 0u);  // returns as soon as the three jobs are done
  EXPECT_EQ(done.load(), 3);
  EXPECT_EQ(cancelled.load(), 0);
}

TEST(WorkerPool, ShutdownCancelsWhatOutlivesTheGrace) {
  std::promise<void> never;
  std::shared_future<void> gate = never.get_future().share();
  std::atomic<int> done{0};
  std::atomic<int> cancelled{0};
  WorkerPool pool(1, 4);
  for (int i = 0; i < 3; ++i) {
    WorkerPool::Job job = blocking_job(gate, done, cancelled);
    ASSERT_TRUE(pool.try_submit(job));
  }
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(pool.shutdown(50ms, 5s), 0u);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
  EXPECT_EQ(cancelled.load(), 3) << "queued jobs still run, and see their cancelled budget";
  WorkerPool::Job late{[] {}, Budget()};
  EXPECT_FALSE(pool.try_submit(late)) << "no jobs after shutdown";
}

// Issue 16: a job that never checks its budget kept shutdown (and the server) waiting
// forever. Now shutdown gives up after grace + stop_wait and says how many jobs did
// not finish; the pool can then be destroyed while the job still runs.
TEST(WorkerPool, ShutdownGivesUpOnAJobThatIgnoresItsBudget) {
  std::promise<void> release;
  std::shared_future<void> gate = release.get_future().share();
  // Shared with the job, which outlives the pool (and could outlive this test).
  auto finished = std::make_shared<std::atomic<bool>>(false);
  auto pool = std::make_unique<WorkerPool>(1, 1);
  WorkerPool::Job job{[gate, finished] {
                        gate.wait();
                        *finished = true;
                      },
                      Budget()};
  ASSERT_TRUE(pool->try_submit(job));
  for (int i = 0; i < 2000 && pool->busy() != 1; ++i) std::this_thread::sleep_for(5ms);
  ASSERT_EQ(pool->busy(), 1u);

  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(pool->shutdown(50ms, 200ms), 1u);
  const auto elapsed = std::chrono::steady_clock::now() - start;
  EXPECT_GE(elapsed, 250ms) << "the grace and the stop wait were both given";
  EXPECT_LT(elapsed, 10s) << "bounded, even on a loaded machine";
  EXPECT_FALSE(finished->load());
  EXPECT_EQ(pool->shutdown(0ms, 10ms), 1u) << "a second call only waits again";
  pool.reset();  // the worker is detached: no std::terminate (which would end this test binary)

  release.set_value();
  for (int i = 0; i < 2000 && !finished->load(); ++i) std::this_thread::sleep_for(5ms);
  EXPECT_TRUE(finished->load()) << "the detached worker ran its job to the end";
}

}  // namespace
}  // namespace implicitizer::server
