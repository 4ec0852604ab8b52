#pragma once
/// \file
/// The threads that run the algebra, so that no computation ever blocks a network
/// thread. A fixed number of workers takes jobs from a bounded queue; a full queue
/// refuses at once (the caller answers 503) rather than letting latency grow without
/// bound.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <list>
#include <mutex>
#include <thread>
#include <vector>

#include "implicitizer/core/budget.hpp"

namespace implicitizer::server {

/// A fixed set of worker threads and a bounded FIFO queue of jobs.
class WorkerPool {
 public:
  /// One unit of work. `run` must not throw (the caller wraps its computation);
  /// `budget` is the computation's, kept so that shutdown can cancel it.
  struct Job {
    std::function<void()> run;
    Budget budget;
  };

  /// Starts `threads` workers (at least 1) with room for `queue_capacity` waiting jobs.
  WorkerPool(unsigned threads, std::size_t queue_capacity);
  /// Cancels what is left and joins the workers (shutdown with no grace).
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Queues `job`; false (and `job` untouched) when the pool holds `threads +
  /// queue_capacity` jobs (running or waiting) or is shutting down. A job accepted here always runs, even if cancelled
  /// meanwhile: its `run` sees the cancelled budget and answers accordingly.
  bool try_submit(Job& job);

  /// Stops accepting jobs, lets queued and running ones finish for up to `grace`,
  /// then cancels the budgets of all that remain and waits for the workers to exit.
  void shutdown(std::chrono::milliseconds grace);

  std::size_t queued() const;                               ///< jobs waiting
  std::size_t busy() const;                                 ///< jobs running
  std::size_t threads() const { return threads_.size(); }   ///< workers
  std::size_t queue_capacity() const { return capacity_; }  ///< most jobs waiting
  std::uint64_t rejected() const;                           ///< try_submit refusals

 private:
  void work();

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;  // a job arrived, or stopping
  std::condition_variable idle_;  // a job finished
  std::deque<Job> queue_;
  std::list<Budget> running_;  // budgets of running jobs, for cancellation
  bool accepting_ = true;
  bool stopping_ = false;
  std::uint64_t rejected_ = 0;
  std::vector<std::thread> threads_;
};

}  // namespace implicitizer::server
