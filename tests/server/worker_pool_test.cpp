#include "worker_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
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
    pool.shutdown(5s);
  }
  EXPECT_EQ(count.load(), 50);
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
  pool.shutdown(60s);  // returns as soon as the three jobs are done
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
  pool.shutdown(50ms);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
  EXPECT_EQ(cancelled.load(), 3) << "queued jobs still run, and see their cancelled budget";
  WorkerPool::Job late{[] {}, Budget()};
  EXPECT_FALSE(pool.try_submit(late)) << "no jobs after shutdown";
}

}  // namespace
}  // namespace implicitizer::server
