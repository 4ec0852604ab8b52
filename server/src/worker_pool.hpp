#pragma once
/// \file
/// The threads that run the algebra, so that no computation ever blocks a network
/// thread. A fixed number of workers takes jobs from a bounded queue; a full queue
/// refuses at once (the caller answers 503) rather than letting latency grow without
/// bound.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "implicitizer/core/budget.hpp"

namespace implicitizer::server {

/// A fixed set of worker threads and a bounded FIFO queue of jobs.
///
/// The workers share the pool's state through a shared pointer, so a worker whose
/// job never stops (a loop that does not check its budget) can be left behind,
/// detached, without reading freed memory when the pool itself is destroyed.
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
  /// shutdown(0 ms, kDestructorStopWait) if not done yet: what is left is cancelled
  /// at once, and a worker that does not stop within that wait is detached. After a
  /// shutdown(), does not wait again: a worker still running is detached.
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// How long the destructor waits for cancelled jobs to stop.
  static constexpr std::chrono::milliseconds kDestructorStopWait{1000};

  /// Names a queued job for withdraw(); never 0.
  using Ticket = std::uint64_t;

  /// Queues `job` and returns its ticket; nullopt (and `job` untouched) when the pool
  /// holds `threads + queue_capacity` jobs (running or waiting) or is shutting down.
  /// A job accepted here runs unless withdrawn, even if cancelled meanwhile: its
  /// `run` sees the cancelled budget and answers accordingly.
  std::optional<Ticket> try_submit(Job& job);

  /// Takes back the job `ticket` if no worker has started it: it will never run, and
  /// its slot is free at once. Nullopt when it has started (or finished): its budget
  /// is the only way to stop it then. Lets a caller answer a job whose deadline
  /// passed in the queue without waiting for a worker to reach it.
  std::optional<Job> withdraw(Ticket ticket);

  /// Stops accepting jobs, lets queued and running ones finish for up to `grace`,
  /// then cancels the budgets of all that remain and waits up to `stop_wait` for the
  /// workers to exit. Returns the number of jobs (running or still queued) that had
  /// not finished by then: 0 means every worker was joined. Otherwise the workers
  /// are detached and keep running what they hold; whatever those jobs refer to
  /// must outlive them, or the process must end (Server::stop() ends it). Returns
  /// within about `grace + stop_wait`. A later call has no grace: it only waits up to
  /// `stop_wait` again.
  std::size_t shutdown(std::chrono::milliseconds grace, std::chrono::milliseconds stop_wait);

  std::size_t queued() const;                               ///< jobs waiting
  std::size_t busy() const;                                 ///< jobs running
  std::size_t threads() const { return threads_.size(); }   ///< workers
  std::size_t queue_capacity() const { return capacity_; }  ///< most jobs waiting
  std::uint64_t rejected() const;                           ///< try_submit refusals

 private:
  struct State;
  static void work(State& state);

  const std::size_t capacity_;
  std::shared_ptr<State> state_;
  std::vector<std::thread> threads_;
};

}  // namespace implicitizer::server
