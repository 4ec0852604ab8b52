#include "worker_pool.hpp"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <list>
#include <mutex>

namespace implicitizer::server {

namespace {

// A computation whose peak passed this gives its freed memory back to the system
// (malloc_trim walks the heap, so small computations skip it).
constexpr std::size_t kReleaseAfterBytes = std::size_t{64} << 20;

}  // namespace

// Everything the workers touch; each worker holds a reference (see the class comment).
struct WorkerPool::State {
  std::mutex mutex;
  std::condition_variable wake;  // a job arrived, or stopping
  std::condition_variable idle;  // a job finished, or a worker exited
  std::deque<std::pair<Ticket, Job>> queue;
  Ticket last_ticket = 0;
  std::list<Budget> running;  // budgets of running jobs, for cancellation
  std::size_t live_workers = 0;
  bool accepting = true;
  bool stopping = false;
  std::uint64_t rejected = 0;
};

WorkerPool::WorkerPool(unsigned threads, std::size_t queue_capacity)
    : capacity_(queue_capacity), state_(std::make_shared<State>()) {
  const unsigned n = std::max(1U, threads);
  state_->live_workers = n;
  threads_.reserve(n);
  for (unsigned i = 0; i < n; ++i) threads_.emplace_back([state = state_] { work(*state); });
}

WorkerPool::~WorkerPool() {
  bool stopped = false;
  {
    std::lock_guard lock(state_->mutex);
    stopped = state_->stopping;
  }
  // After a shutdown() the jobs have had their wait; a worker still running is detached.
  (void)shutdown(std::chrono::milliseconds(0), stopped ? std::chrono::milliseconds(0) : kDestructorStopWait);
}

std::optional<WorkerPool::Ticket> WorkerPool::try_submit(Job& job) {
  Ticket ticket = 0;
  {
    std::lock_guard lock(state_->mutex);
    // The bound counts jobs beyond those the workers can run at once, so with
    // capacity 0 the pool still takes one job per idle worker.
    if (!state_->accepting || state_->queue.size() + state_->running.size() >= threads_.size() + capacity_) {
      ++state_->rejected;
      return std::nullopt;
    }
    ticket = ++state_->last_ticket;
    state_->queue.emplace_back(ticket, std::move(job));
  }
  state_->wake.notify_one();
  return ticket;
}

std::optional<WorkerPool::Job> WorkerPool::withdraw(Ticket ticket) {
  std::lock_guard lock(state_->mutex);
  auto& queue = state_->queue;
  const auto it = std::find_if(queue.begin(), queue.end(), [ticket](const auto& q) { return q.first == ticket; });
  if (it == queue.end()) return std::nullopt;
  Job job = std::move(it->second);
  queue.erase(it);
  // Shutdown may be waiting for the queue to empty.
  state_->idle.notify_all();
  return job;
}

void WorkerPool::work(State& state) {
  for (;;) {
    Job job;
    std::list<Budget>::iterator mine;
    {
      std::unique_lock lock(state.mutex);
      state.wake.wait(lock, [&state] { return state.stopping || !state.queue.empty(); });
      if (state.queue.empty()) {  // stopping, and nothing left to answer
        --state.live_workers;
        state.idle.notify_all();
        return;
      }
      job = std::move(state.queue.front().second);
      state.queue.pop_front();
      state.running.push_front(job.budget);
      mine = state.running.begin();
    }
    // run() does not throw by contract; if it does anyway (out of memory while
    // finishing a response), the job's session is dropped rather than the process.
    try {
      job.run();
    } catch (...) {
    }
    // glibc keeps freed memory for reuse; after a large computation that would leave
    // the process holding gigabytes (docs/api.md, "Reliability", has the measurement).
    if (const MemoryAccount* account = job.budget.memory_account()) {
      release_free_memory(account->peak_bytes(), kReleaseAfterBytes);
    }
    {
      std::lock_guard lock(state.mutex);
      state.running.erase(mine);
    }
    state.idle.notify_all();
  }
}

std::size_t WorkerPool::shutdown(std::chrono::milliseconds grace, std::chrono::milliseconds stop_wait) {
  std::unique_lock lock(state_->mutex);
  State& s = *state_;
  s.accepting = false;
  if (!s.stopping) s.idle.wait_for(lock, grace, [&s] { return s.queue.empty() && s.running.empty(); });
  // Whatever is left runs to its first budget check and answers `cancelled`.
  for (const auto& queued : s.queue) queued.second.budget.cancel();
  for (const Budget& budget : s.running) budget.cancel();
  s.stopping = true;
  s.wake.notify_all();
  // Bounded: a job that never checks its budget must not keep the caller (and the
  // process) waiting forever.
  s.idle.wait_for(lock, stop_wait, [&s] { return s.live_workers == 0; });
  const bool all_exited = s.live_workers == 0;
  const std::size_t unfinished = s.running.size() + s.queue.size();
  lock.unlock();
  for (std::thread& t : threads_) {
    if (!t.joinable()) continue;
    // A worker that has not exited cannot be joined without waiting for its job; a
    // std::thread destroyed while joinable would call std::terminate.
    if (all_exited) {
      t.join();
    } else {
      t.detach();
    }
  }
  return unfinished;
}

std::size_t WorkerPool::queued() const {
  std::lock_guard lock(state_->mutex);
  return state_->queue.size();
}

std::size_t WorkerPool::busy() const {
  std::lock_guard lock(state_->mutex);
  return state_->running.size();
}

std::uint64_t WorkerPool::rejected() const {
  std::lock_guard lock(state_->mutex);
  return state_->rejected;
}

}  // namespace implicitizer::server
