#pragma once
/// \file
/// Jobs in one SQLite file (`--store sqlite:PATH`): finished results survive a
/// restart, and jobs that were queued or running when the process ended (a crash, a
/// kill -9, a shutdown) are queued again when the next process opens the file. One
/// process per file: requeueing at open is only sound when no other process runs
/// those jobs, so the store holds an exclusive lock (flock) on `PATH.lock` for its
/// life and a second store on the same file refuses to open (several replicas need
/// a shared store). The file is watched: deleted or replaced under the server (a
/// different inode), its header overwritten, or corrupt (SQLite's errors), every
/// operation fails (the handlers' 503 job_store_unavailable) instead of writing jobs
/// nobody will find.

#include <sqlite3.h>
#include <sys/types.h>

#include <map>
#include <mutex>
#include <vector>

#include "jobs/job_store.hpp"

namespace implicitizer::server {

/// A JobStore over one SQLite connection, serialized by a mutex.
class SqliteJobStore : public JobStore {
 public:
  /// Opens (creating if needed) the database at `path`, takes its lock and queues
  /// again the jobs a previous process left running; holds within `limits`. Throws
  /// std::runtime_error when the file cannot be opened, is not a jobs database, or
  /// another process holds it (the message names the file and that process).
  explicit SqliteJobStore(const std::string& path, JobStorageLimits limits = {});
  ~SqliteJobStore() override;
  SqliteJobStore(const SqliteJobStore&) = delete;
  SqliteJobStore& operator=(const SqliteJobStore&) = delete;

  /// Jobs queued again at opening (they were running when the last process ended).
  std::size_t requeued_at_open() const { return requeued_at_open_; }

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
  class Statement;
  class Transaction;
  struct FileIdentity {
    std::string path;
    dev_t device = 0;
    ino_t inode = 0;
  };
  void execute(const char* sql);
  std::size_t count_unfinished_locked(const std::string& client);
  // What the caps count, of one client or of all. Exact because this process is the
  // file's only writer (the lock): counted at opening, kept up to date by every
  // change, counted again after a change that failed.
  struct Usage {
    std::int64_t finished = 0;
    std::int64_t finished_bytes = 0;
    std::int64_t unfinished_bytes = 0;
  };
  void count_usage();
  void add_usage(const std::string& client, std::int64_t finished, std::int64_t finished_bytes,
                 std::int64_t unfinished_bytes);
  // Runs `change` (a write); if it throws, counts the usage again and rethrows.
  template <typename Change>
  auto keeping_usage(Change change);
  template <typename Key>
  std::size_t remove_returning_usage(const std::string& delete_where, const Key& key);
  JobAdmission insert_locked(const JobRecord& job, std::size_t max_unfinished);
  bool finish_locked(const std::string& id, JobStatus status, const std::optional<JobResult>& result,
                     std::int64_t finished_at_ms);
  void evict_over_limits(const std::string& client, const std::string& keep);
  // Steps `update` (an UPDATE that finishes job `id` ... RETURNING client; its
  // result now weighs `result_bytes`) and evicts what its change calls for; false
  // when it changed no row.
  bool settle_and_evict(Statement& update, const std::string& id, std::int64_t result_bytes);
  // Throws when the database file or its WAL is no longer the one opened, or the
  // file no longer starts with SQLite's header.
  void check_files();
  bool has_sqlite_header() const;
  // Closes the connection, then the header's and the lock's descriptors.
  void close_files();
  // Throws `message`, and logs it the first time.
  [[noreturn]] void refuse_to_work(const std::string& message);

  const std::string path_;
  const JobStorageLimits limits_;
  std::mutex mutex_;
  int lock_fd_ = -1;
  // The database file, opened once to read its header: closing a descriptor of the
  // file would drop every POSIX lock this process holds on it, SQLite's included
  // (another process would then think itself the last and delete the WAL). Closed
  // after SQLite's connection.
  int header_fd_ = -1;
  sqlite3* db_ = nullptr;
  std::vector<FileIdentity> files_;
  std::map<std::string, Usage> usage_;
  Usage total_;
  bool reported_file_ = false;
  bool header_at_open_ = false;  // a database in WAL mode has its header once created
  std::size_t requeued_at_open_ = 0;
};

}  // namespace implicitizer::server
