#include "jobs/sqlite_job_store.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace implicitizer::server {

namespace {

// Durable against a killed process (the WAL is fsync'ed at checkpoints, not at each
// commit: a power cut may lose the last commits, a kill -9 does not). The busy
// timeout covers another connection (sqlite3's shell) holding the file briefly.
// The WAL is cut back to journal_size_limit after each checkpoint; without it the
// WAL keeps the size of its largest burst of writes for the server's life. Rows
// deleted (evicted, expired) free pages that later inserts reuse, so the main file
// stays near the most the caps let the jobs hold.
constexpr const char* kSchema =
    "PRAGMA journal_mode=WAL;"
    "PRAGMA synchronous=NORMAL;"
    "PRAGMA busy_timeout=5000;"
    "PRAGMA journal_size_limit=8388608;"
    "CREATE TABLE IF NOT EXISTS jobs ("
    " id TEXT PRIMARY KEY, kind TEXT NOT NULL, request TEXT NOT NULL, client TEXT NOT NULL,"
    " status TEXT NOT NULL, created_at_ms INTEGER NOT NULL, started_at_ms INTEGER NOT NULL,"
    " finished_at_ms INTEGER NOT NULL, http_status INTEGER, content_type TEXT, headers TEXT, body BLOB);"
    "CREATE INDEX IF NOT EXISTS jobs_by_status ON jobs (status, client);"
    "CREATE INDEX IF NOT EXISTS jobs_by_client_finish ON jobs (client, finished_at_ms);"
    "CREATE INDEX IF NOT EXISTS jobs_by_finish ON jobs (finished_at_ms);";

constexpr const char* kFinished = "status IN ('done', 'failed', 'cancelled')";
constexpr const char* kUnfinished = "status IN ('queued', 'running')";

// job_stored_bytes() of a row: the request and the result's content type, headers
// (joined as join_headers() does) and body, in bytes (length() of text counts characters).
constexpr const char* kStoredBytes =
    "(length(CAST(request AS BLOB)) + coalesce(length(CAST(content_type AS BLOB)), 0) + "
    "coalesce(length(CAST(headers AS BLOB)), 0) + coalesce(length(body), 0))";

std::int64_t budget_after(std::size_t cap, std::int64_t used) {
  if (cap == JobStorageLimits::kNone) return std::numeric_limits<std::int64_t>::max();
  return static_cast<std::int64_t>(cap) - used;
}

constexpr const char* kColumns =
    "id, kind, request, client, status, created_at_ms, started_at_ms, finished_at_ms, http_status, content_type, "
    "headers, body";

}  // namespace

// One prepared statement; binds by position (1-based), steps, finalizes on scope exit.
class SqliteJobStore::Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK) fail("prepare");
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int i, const std::string& text) {
    sqlite3_bind_text(stmt_, i, text.data(), static_cast<int>(text.size()), SQLITE_TRANSIENT);
    return *this;
  }
  Statement& bind_blob(int i, const std::string& bytes) {
    sqlite3_bind_blob(stmt_, i, bytes.data(), static_cast<int>(bytes.size()), SQLITE_TRANSIENT);
    return *this;
  }
  Statement& bind(int i, std::int64_t value) {
    sqlite3_bind_int64(stmt_, i, value);
    return *this;
  }
  /// True while a row is there to read; throws on errors.
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) fail("step");
    return false;
  }
  std::string text(int column) const {
    const auto* p = static_cast<const char*>(sqlite3_column_blob(stmt_, column));
    return p ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column))) : std::string();
  }
  std::int64_t integer(int column) const { return sqlite3_column_int64(stmt_, column); }
  bool is_null(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }
  /// Rows the last step changed.
  std::size_t changes() const { return static_cast<std::size_t>(sqlite3_changes(db_)); }

  /// The job of the current row (selected with kColumns).
  JobRecord job() const {
    JobRecord job;
    job.id = text(0);
    job.kind = text(1);
    job.request = text(2);
    job.client = text(3);
    job.status = parse_job_status(text(4)).value_or(JobStatus::failed);
    job.created_at_ms = integer(5);
    job.started_at_ms = integer(6);
    job.finished_at_ms = integer(7);
    if (!is_null(8)) {
      job.result = JobResult{static_cast<unsigned>(integer(8)), text(9), split_headers(text(10)), text(11)};
    }
    return job;
  }

 private:
  [[noreturn]] void fail(const char* what) const {
    const std::string message = std::string("sqlite job store: ") + what + ": " + sqlite3_errmsg(db_);
    const int code = sqlite3_errcode(db_) & 0xff;
    // The request that meets it gets a 503; the operator needs to hear of it too.
    if (code == SQLITE_CORRUPT || code == SQLITE_NOTADB) std::cerr << "implicitizer-server: " + message + "\n";
    throw std::runtime_error(message);
  }
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

// BEGIN IMMEDIATE ... COMMIT, rolled back when left by an exception: a check and the
// write it allows, or a write and the evictions it calls for, are one step.
class SqliteJobStore::Transaction {
 public:
  explicit Transaction(SqliteJobStore& store) : store_(store) { store_.execute("BEGIN IMMEDIATE"); }
  ~Transaction() {
    if (!committed_) sqlite3_exec(store_.db_, "ROLLBACK", nullptr, nullptr, nullptr);
  }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit() {
    store_.execute("COMMIT");
    committed_ = true;
  }

 private:
  SqliteJobStore& store_;
  bool committed_ = false;
};

namespace {

// Takes the exclusive lock of the store at `path` (flock on PATH.lock, released by
// the kernel however the process ends) and writes who holds it; throws, naming the
// holder, when another process has it. The descriptor stays open for the store's life.
int lock_store_file(const std::string& path) {
  const std::string lock_path = path + ".lock";
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot open the job store's lock '" + lock_path + "'");
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    char owner[256] = {};
    const ssize_t n = ::pread(fd, owner, sizeof owner - 1, 0);
    std::string holder(owner, n > 0 ? static_cast<std::size_t>(n) : 0);
    while (!holder.empty() && holder.back() == '\n') holder.pop_back();
    ::close(fd);
    throw std::runtime_error("the job store '" + path + "' is in use by another server (" +
                             (holder.empty() ? std::string("unknown process") : holder) + ", lock '" + lock_path +
                             "'): one server per SQLite file; several replicas share --store redis://HOST:PORT");
  }
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::string owner = "pid " + std::to_string(::getpid()) + " on " + host + "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, owner.data(), owner.size(), 0) < 0) {
    // The lock holds without the note: only the refusal's message is poorer.
  }
  return fd;
}

}  // namespace

SqliteJobStore::SqliteJobStore(const std::string& path, JobStorageLimits limits) : path_(path), limits_(limits) {
  lock_fd_ = lock_store_file(path);
  if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX, nullptr) !=
      SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    ::close(lock_fd_);
    throw std::runtime_error("cannot open the job store '" + path + "': " + message);
  }
  try {
    execute(kSchema);
    // Sound only because the lock says no other process runs these jobs.
    Statement requeue(db_, "UPDATE jobs SET status = 'queued' WHERE status = 'running'");
    requeue.step();
    requeued_at_open_ = requeue.changes();
    count_usage();
    header_fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    header_at_open_ = has_sqlite_header();
    for (const char* suffix : {"", "-wal", "-shm"}) {
      struct stat st {};
      const std::string file = path + suffix;
      if (::stat(file.c_str(), &st) == 0) files_.push_back(FileIdentity{file, st.st_dev, st.st_ino});
    }
  } catch (...) {
    close_files();
    throw;
  }
}

SqliteJobStore::~SqliteJobStore() { close_files(); }

void SqliteJobStore::close_files() {
  sqlite3_close(db_);
  if (header_fd_ >= 0) ::close(header_fd_);
  ::close(lock_fd_);
}

void SqliteJobStore::check_files() {
  for (const FileIdentity& file : files_) {
    struct stat st {};
    if (::stat(file.path.c_str(), &st) == 0 && st.st_dev == file.device && st.st_ino == file.inode) continue;
    // SQLite would go on writing to the unlinked inode: every job written from now on
    // would be lost at the next start. Refuse instead, and say so once in the log.
    refuse_to_work("the job store's file '" + file.path +
                   "' was deleted or replaced while the server ran; its jobs are lost to the next start, so the "
                   "store refuses to work (restart the server)");
  }
  if (header_at_open_ && !has_sqlite_header()) {
    // Overwritten in place (same inode), the file goes unnoticed by SQLite as long as
    // its cache holds the pages; its first bytes are the cheap witness.
    refuse_to_work("the job store's file '" + path_ +
                   "' no longer starts with SQLite's header: it was overwritten or truncated while the server ran, "
                   "so the store refuses to work (restore it, or restart on a new file)");
  }
}

void SqliteJobStore::refuse_to_work(const std::string& message) {
  if (!reported_file_) {
    reported_file_ = true;
    std::cerr << "implicitizer-server: " + message + "\n" << std::flush;
  }
  throw std::runtime_error(message);
}

bool SqliteJobStore::has_sqlite_header() const {
  // SQLite's own magic string, the first 16 bytes of every database file.
  static constexpr char kMagic[] = "SQLite format 3";
  char header[sizeof kMagic] = {};
  if (header_fd_ < 0) return false;
  const ssize_t n = ::pread(header_fd_, header, sizeof header, 0);
  return n == static_cast<ssize_t>(sizeof header) && std::equal(header, header + sizeof header, kMagic);
}

void SqliteJobStore::execute(const char* sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : "unknown error";
    sqlite3_free(error);
    throw std::runtime_error("sqlite job store: " + message);
  }
}

void SqliteJobStore::count_usage() {
  usage_.clear();
  total_ = Usage{};
  Statement s(db_, std::string("SELECT client, ") + kFinished + ", COUNT(*), coalesce(SUM(" + kStoredBytes +
                       "), 0) FROM jobs GROUP BY client, " + kFinished);
  while (s.step()) {
    Usage& usage = usage_[s.text(0)];
    const bool finished = s.integer(1) != 0;
    (finished ? usage.finished_bytes : usage.unfinished_bytes) += s.integer(3);
    if (finished) usage.finished += s.integer(2);
  }
  for (const auto& [client, usage] : usage_) {
    total_.finished += usage.finished;
    total_.finished_bytes += usage.finished_bytes;
    total_.unfinished_bytes += usage.unfinished_bytes;
  }
}

void SqliteJobStore::add_usage(const std::string& client, std::int64_t finished, std::int64_t finished_bytes,
                               std::int64_t unfinished_bytes) {
  for (Usage* usage : {&usage_[client], &total_}) {
    usage->finished += finished;
    usage->finished_bytes += finished_bytes;
    usage->unfinished_bytes += unfinished_bytes;
  }
}

void SqliteJobStore::evict_over_limits(const std::string& client, const std::string& keep) {
  // The oldest finished job but `keep` goes while a cap is passed: the same jobs as
  // JobStorageLimits's rule (first_evicted()), one indexed delete at a time.
  const auto over = [](const Usage& usage, std::size_t max_finished, std::size_t max_bytes) {
    return budget_after(max_finished, usage.finished) < 0 ||
           budget_after(max_bytes, usage.finished_bytes + usage.unfinished_bytes) < 0;
  };
  for (const bool per_client : {true, false}) {
    const std::size_t max_finished = per_client ? limits_.max_finished_per_client : limits_.max_finished;
    const std::size_t max_bytes = per_client ? limits_.max_bytes_per_client : limits_.max_bytes;
    while (over(per_client ? usage_[client] : total_, max_finished, max_bytes)) {
      Statement s(db_, std::string("DELETE FROM jobs WHERE rowid = (SELECT rowid FROM jobs WHERE ") + kFinished +
                           " AND id <> ?" + (per_client ? " AND client = ?" : "") +
                           " ORDER BY finished_at_ms, rowid LIMIT 1) RETURNING client, " + kStoredBytes);
      s.bind(1, keep);
      if (per_client) s.bind(2, client);
      if (!s.step()) break;  // only `keep` is left
      const std::string victim = s.text(0);
      const std::int64_t bytes = s.integer(1);
      while (s.step()) {
      }
      add_usage(victim, -1, -bytes, 0);
    }
  }
}

bool SqliteJobStore::settle_and_evict(Statement& update, const std::string& id, std::int64_t result_bytes) {
  std::int64_t unfinished_bytes = 0;
  {
    Statement s(db_, std::string("SELECT ") + kStoredBytes + " FROM jobs WHERE id = ?");
    s.bind(1, id);
    if (s.step()) unfinished_bytes = s.integer(0);
  }
  if (!update.step()) return false;
  const std::string client = update.text(0);
  while (update.step()) {
  }
  add_usage(client, 1, result_bytes, -unfinished_bytes);
  evict_over_limits(client, id);
  return true;
}

template <typename Change>
auto SqliteJobStore::keeping_usage(Change change) {
  try {
    return change();
  } catch (...) {
    // Rolled back: the counts may have moved with it, so they are counted again.
    try {
      count_usage();
    } catch (...) {
    }
    throw;
  }
}

JobAdmission SqliteJobStore::insert(const JobRecord& job, std::size_t max_unfinished) {
  std::lock_guard lock(mutex_);
  check_files();
  return keeping_usage([&] { return insert_locked(job, max_unfinished); });
}

JobAdmission SqliteJobStore::insert_locked(const JobRecord& job, std::size_t max_unfinished) {
  Transaction transaction(*this);
  const bool queued = job.status == JobStatus::queued;
  const auto bytes =
      static_cast<std::int64_t>(job_stored_bytes(job)) - (queued ? 0 : static_cast<std::int64_t>(job.request.size()));
  if (queued) {
    if (count_unfinished_locked(job.client) >= max_unfinished) return JobAdmission::client_job_cap;
    if (budget_after(limits_.max_bytes_per_client, usage_[job.client].unfinished_bytes) < bytes) {
      return JobAdmission::client_bytes_cap;
    }
    if (budget_after(limits_.max_bytes, total_.unfinished_bytes) < bytes) return JobAdmission::store_bytes_cap;
  }
  Statement s(db_, std::string("INSERT INTO jobs (") + kColumns + ") VALUES (?,?,?,?,?,?,?,?,?,?,?,?)");
  s.bind(1, job.id)
      .bind(2, job.kind)
      .bind(3, is_finished(job.status) ? std::string() : job.request)
      .bind(4, job.client);
  s.bind(5, std::string(to_string(job.status))).bind(6, job.created_at_ms).bind(7, job.started_at_ms);
  s.bind(8, job.finished_at_ms);
  if (job.result) {
    s.bind(9, static_cast<std::int64_t>(job.result->http_status)).bind(10, job.result->content_type);
    s.bind(11, join_headers(job.result->headers)).bind_blob(12, job.result->body);
  }
  s.step();
  add_usage(job.client, queued ? 0 : 1, queued ? 0 : bytes, queued ? bytes : 0);
  evict_over_limits(job.client, job.id);
  transaction.commit();
  return JobAdmission::admitted;
}

std::optional<JobRecord> SqliteJobStore::find(const std::string& id) {
  std::lock_guard lock(mutex_);
  check_files();
  Statement s(db_, std::string("SELECT ") + kColumns + " FROM jobs WHERE id = ?");
  s.bind(1, id);
  if (!s.step()) return std::nullopt;
  return s.job();
}

std::optional<JobRecord> SqliteJobStore::claim_next(std::int64_t now_ms) {
  std::lock_guard lock(mutex_);
  check_files();
  // One statement: the oldest queued job becomes running, whoever else reads the file.
  Statement s(db_, std::string("UPDATE jobs SET status = 'running', started_at_ms = ? WHERE rowid = (SELECT rowid "
                               "FROM jobs WHERE status = 'queued' ORDER BY rowid LIMIT 1) RETURNING ") +
                       kColumns);
  s.bind(1, now_ms);
  if (!s.step()) return std::nullopt;
  JobRecord job = s.job();
  while (s.step()) {
  }
  return job;
}

bool SqliteJobStore::finish(const std::string& id, JobStatus status, const std::optional<JobResult>& result,
                            std::int64_t finished_at_ms) {
  std::lock_guard lock(mutex_);
  check_files();
  return keeping_usage([&] { return finish_locked(id, status, result, finished_at_ms); });
}

bool SqliteJobStore::finish_locked(const std::string& id, JobStatus status, const std::optional<JobResult>& result,
                                   std::int64_t finished_at_ms) {
  Transaction transaction(*this);
  JobRecord settled;
  settled.result = result;
  Statement s(db_,
              "UPDATE jobs SET status = ?, finished_at_ms = ?, http_status = ?, content_type = ?, headers = ?, "
              "body = ?, request = '' WHERE id = ? AND status = 'running' RETURNING client");
  s.bind(1, std::string(to_string(status))).bind(2, finished_at_ms);
  if (result) {
    s.bind(3, static_cast<std::int64_t>(result->http_status)).bind(4, result->content_type);
    s.bind(5, join_headers(result->headers)).bind_blob(6, result->body);
  }
  s.bind(7, id);
  if (!settle_and_evict(s, id, static_cast<std::int64_t>(job_stored_bytes(settled)))) return false;
  transaction.commit();
  return true;
}

bool SqliteJobStore::cancel_queued(const std::string& id, std::int64_t finished_at_ms) {
  std::lock_guard lock(mutex_);
  check_files();
  return keeping_usage([&] {
    Transaction transaction(*this);
    Statement s(db_,
                "UPDATE jobs SET status = 'cancelled', finished_at_ms = ?, request = '' WHERE id = ? AND status = "
                "'queued' RETURNING client");
    s.bind(1, finished_at_ms).bind(2, id);
    if (!settle_and_evict(s, id, 0)) return false;
    transaction.commit();
    return true;
  });
}

bool SqliteJobStore::remove_finished(const std::string& id) {
  std::lock_guard lock(mutex_);
  check_files();
  return remove_returning_usage(std::string("DELETE FROM jobs WHERE id = ? AND ") + kFinished, id) == 1;
}

std::size_t SqliteJobStore::count_unfinished(const std::string& client) {
  std::lock_guard lock(mutex_);
  check_files();
  return count_unfinished_locked(client);
}

std::size_t SqliteJobStore::count_unfinished_locked(const std::string& client) {
  Statement s(db_, "SELECT COUNT(*) FROM jobs WHERE status IN ('queued', 'running') AND client = ?");
  s.bind(1, client);
  s.step();
  return static_cast<std::size_t>(s.integer(0));
}

std::size_t SqliteJobStore::count_unfinished() {
  std::lock_guard lock(mutex_);
  check_files();
  Statement s(db_, "SELECT COUNT(*) FROM jobs WHERE status IN ('queued', 'running')");
  s.step();
  return static_cast<std::size_t>(s.integer(0));
}

std::size_t SqliteJobStore::remove_finished_before(std::int64_t cutoff_ms) {
  std::lock_guard lock(mutex_);
  check_files();
  return remove_returning_usage(std::string("DELETE FROM jobs WHERE ") + kFinished + " AND finished_at_ms < ?",
                                cutoff_ms);
}

template <typename Key>
std::size_t SqliteJobStore::remove_returning_usage(const std::string& delete_where, const Key& key) {
  return keeping_usage([&] {
    Statement s(db_, delete_where + " RETURNING client, " + kStoredBytes);
    s.bind(1, key);
    std::size_t removed = 0;
    while (s.step()) {
      add_usage(s.text(0), -1, -s.integer(1), 0);
      ++removed;
    }
    return removed;
  });
}

}  // namespace implicitizer::server
