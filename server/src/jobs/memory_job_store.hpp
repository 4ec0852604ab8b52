#pragma once
/// \file
/// The embedded default store: jobs in this process's memory, no set-up, lost with the
/// process (`--store memory`).

#include <cstdint>
#include <deque>
#include <mutex>
#include <unordered_map>

#include "jobs/job_store.hpp"

namespace implicitizer::server {

/// Jobs in a hash map, the queued ones also in FIFO order; one mutex.
class MemoryJobStore : public JobStore {
 public:
  /// An empty store that holds within `limits`.
  explicit MemoryJobStore(JobStorageLimits limits = {}) : limits_(limits) {}

  JobAdmission insert(const JobRecord& job, std::size_t max_unfinished) override;
  std::optional<JobRecord> find(const std::string& id) override;
  std::optional<JobRecord> claim_next(std::int64_t now_ms) override;
  bool finish(const std::string& id, JobStatus status, const std::optional<JobResult>& result,
              std::int64_t finished_at_ms) override;
  bool cancel_queued(const std::string& id, std::int64_t finished_at_ms) override;
  bool remove_finished(const std::string& id) override;
  std::size_t count_unfinished(const std::string& client) override;
  std::size_t remove_finished_before(std::int64_t cutoff_ms) override;
  std::size_t count_unfinished() override;

 private:
  struct Entry {
    JobRecord job;
    std::uint64_t order = 0;  // insertion order: breaks ties of finished_at_ms as SQLite's rowid does
  };
  // Evicts the oldest finished jobs (other than `keep`) of `client`, then of everyone,
  // until the store is within limits_.
  void evict_over_limits(const std::string& client, const std::string& keep);
  void evict_within(const std::string* client, const std::string& keep, std::size_t max_bytes,
                    std::size_t max_finished);

  const JobStorageLimits limits_;
  std::mutex mutex_;
  std::unordered_map<std::string, Entry> jobs_;
  std::deque<std::string> queue_;  // ids in submission order; a cancelled one is skipped when reached
  std::uint64_t next_order_ = 0;
};

}  // namespace implicitizer::server
