#pragma once
/// \file
/// Jobs in one SQLite file (`--store sqlite:PATH`): finished results survive a
/// restart, and jobs that were queued or running when the process ended (a crash, a
/// kill -9, a shutdown) are queued again when the next process opens the file. One
/// process per file: SQLite's locking keeps the file sound, but two servers would
/// each requeue the other's running jobs (several replicas need a shared store).

#include <sqlite3.h>

#include <mutex>

#include "jobs/job_store.hpp"

namespace implicitizer::server {

/// A JobStore over one SQLite connection, serialized by a mutex.
class SqliteJobStore : public JobStore {
 public:
  /// Opens (creating if needed) the database at `path` and queues again the jobs a
  /// previous process left running. Throws std::runtime_error when the file cannot
  /// be opened or is not a jobs database.
  explicit SqliteJobStore(const std::string& path);
  ~SqliteJobStore() override;
  SqliteJobStore(const SqliteJobStore&) = delete;
  SqliteJobStore& operator=(const SqliteJobStore&) = delete;

  /// Jobs queued again at opening (they were running when the last process ended).
  std::size_t requeued_at_open() const { return requeued_at_open_; }

  bool insert(const JobRecord& job, std::size_t max_unfinished) override;
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
  class Statement;
  void execute(const char* sql);
  std::size_t count_unfinished_locked(const std::string& client);

  std::mutex mutex_;
  sqlite3* db_ = nullptr;
  std::size_t requeued_at_open_ = 0;
};

}  // namespace implicitizer::server
