#include "worker_pool.hpp"

#include <algorithm>

namespace implicitizer::server {

namespace {

// A computation whose peak passed this gives its freed memory back to the system
// (malloc_trim walks the heap, so small computations skip it).
constexpr std::size_t kReleaseAfterBytes = std::size_t{64} << 20;

}  // namespace

WorkerPool::WorkerPool(unsigned threads, std::size_t queue_capacity) : capacity_(queue_capacity) {
  threads_.reserve(std::max(1U, threads));
  for (unsigned i = 0; i < std::max(1U, threads); ++i) threads_.emplace_back([this] { work(); });
}

WorkerPool::~WorkerPool() { shutdown(std::chrono::milliseconds(0)); }

bool WorkerPool::try_submit(Job& job) {
  {
    std::lock_guard lock(mutex_);
    // The bound counts jobs beyond those the workers can run at once, so with
    // capacity 0 the pool still takes one job per idle worker.
    if (!accepting_ || queue_.size() + running_.size() >= threads_.size() + capacity_) {
      ++rejected_;
      return false;
    }
    queue_.push_back(std::move(job));
  }
  wake_.notify_one();
  return true;
}

void WorkerPool::work() {
  for (;;) {
    Job job;
    std::list<Budget>::iterator mine;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping, and nothing left to answer
      job = std::move(queue_.front());
      queue_.pop_front();
      running_.push_front(job.budget);
      mine = running_.begin();
    }
    // run() does not throw by contract; if it does anyway (out of memory while
    // finishing a response), the job's session is dropped rather than the process.
    // Its allocations, and those of the threads it starts, count against its budget.
    {
      const MemoryScope scope(job.budget.memory_account());
      try {
        job.run();
      } catch (...) {
      }
    }
    // glibc keeps freed memory for reuse; after a large computation that would leave
    // the process holding gigabytes (docs/api.md, "Reliability", has the measurement).
    if (const MemoryAccount* account = job.budget.memory_account()) {
      release_free_memory(account->peak_bytes(), kReleaseAfterBytes);
    }
    {
      std::lock_guard lock(mutex_);
      running_.erase(mine);
    }
    idle_.notify_all();
  }
}

void WorkerPool::shutdown(std::chrono::milliseconds grace) {
  std::unique_lock lock(mutex_);
  accepting_ = false;
  idle_.wait_for(lock, grace, [this] { return queue_.empty() && running_.empty(); });
  // Whatever is left runs to its first budget check and answers `cancelled`.
  for (const Job& job : queue_) job.budget.cancel();
  for (const Budget& budget : running_) budget.cancel();
  stopping_ = true;
  lock.unlock();
  wake_.notify_all();
  for (std::thread& t : threads_) {
    if (t.joinable()) t.join();
  }
}

std::size_t WorkerPool::queued() const {
  std::lock_guard lock(mutex_);
  return queue_.size();
}

std::size_t WorkerPool::busy() const {
  std::lock_guard lock(mutex_);
  return running_.size();
}

std::uint64_t WorkerPool::rejected() const {
  std::lock_guard lock(mutex_);
  return rejected_;
}

}  // namespace implicitizer::server
