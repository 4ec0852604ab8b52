#include "jobs/sqlite_job_store.hpp"

#include <stdexcept>

namespace implicitizer::server {

namespace {

// Durable against a killed process (the WAL is fsync'ed at checkpoints, not at each
// commit: a power cut may lose the last commits, a kill -9 does not). The busy
// timeout covers another connection (sqlite3's shell) holding the file briefly.
constexpr const char* kSchema =
    "PRAGMA journal_mode=WAL;"
    "PRAGMA synchronous=NORMAL;"
    "PRAGMA busy_timeout=5000;"
    "CREATE TABLE IF NOT EXISTS jobs ("
    " id TEXT PRIMARY KEY, kind TEXT NOT NULL, request TEXT NOT NULL, client TEXT NOT NULL,"
    " status TEXT NOT NULL, created_at_ms INTEGER NOT NULL, started_at_ms INTEGER NOT NULL,"
    " finished_at_ms INTEGER NOT NULL, http_status INTEGER, content_type TEXT, headers TEXT, body BLOB);"
    "CREATE INDEX IF NOT EXISTS jobs_by_status ON jobs (status, client);";

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
    throw std::runtime_error(std::string("sqlite job store: ") + what + ": " + sqlite3_errmsg(db_));
  }
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

SqliteJobStore::SqliteJobStore(const std::string& path) {
  if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX, nullptr) !=
      SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw std::runtime_error("cannot open the job store '" + path + "': " + message);
  }
  try {
    execute(kSchema);
    Statement requeue(db_, "UPDATE jobs SET status = 'queued' WHERE status = 'running'");
    requeue.step();
    requeued_at_open_ = requeue.changes();
  } catch (...) {
    sqlite3_close(db_);
    throw;
  }
}

SqliteJobStore::~SqliteJobStore() { sqlite3_close(db_); }

void SqliteJobStore::execute(const char* sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : "unknown error";
    sqlite3_free(error);
    throw std::runtime_error("sqlite job store: " + message);
  }
}

bool SqliteJobStore::insert(const JobRecord& job, std::size_t max_unfinished) {
  std::lock_guard lock(mutex_);
  // One connection behind one mutex: nothing of this process writes between the
  // count and the insert (and one process per file).
  if (job.status == JobStatus::queued && count_unfinished_locked(job.client) >= max_unfinished) return false;
  Statement s(db_, std::string("INSERT INTO jobs (") + kColumns + ") VALUES (?,?,?,?,?,?,?,?,?,?,?,?)");
  s.bind(1, job.id).bind(2, job.kind).bind(3, job.request).bind(4, job.client);
  s.bind(5, std::string(to_string(job.status))).bind(6, job.created_at_ms).bind(7, job.started_at_ms);
  s.bind(8, job.finished_at_ms);
  if (job.result) {
    s.bind(9, static_cast<std::int64_t>(job.result->http_status)).bind(10, job.result->content_type);
    s.bind(11, join_headers(job.result->headers)).bind_blob(12, job.result->body);
  }
  s.step();
  return true;
}

std::optional<JobRecord> SqliteJobStore::find(const std::string& id) {
  std::lock_guard lock(mutex_);
  Statement s(db_, std::string("SELECT ") + kColumns + " FROM jobs WHERE id = ?");
  s.bind(1, id);
  if (!s.step()) return std::nullopt;
  return s.job();
}

std::optional<JobRecord> SqliteJobStore::claim_next(std::int64_t now_ms) {
  std::lock_guard lock(mutex_);
  // One connection behind one mutex: the select and the update cannot interleave
  // with another claim of this process.
  Statement s(db_, std::string("SELECT ") + kColumns + " FROM jobs WHERE status = 'queued' ORDER BY rowid LIMIT 1");
  if (!s.step()) return std::nullopt;
  JobRecord job = s.job();
  Statement claim(db_, "UPDATE jobs SET status = 'running', started_at_ms = ? WHERE id = ?");
  claim.bind(1, now_ms).bind(2, job.id);
  claim.step();
  job.status = JobStatus::running;
  job.started_at_ms = now_ms;
  return job;
}

bool SqliteJobStore::finish(const std::string& id, JobStatus status, const std::optional<JobResult>& result,
                            std::int64_t finished_at_ms) {
  std::lock_guard lock(mutex_);
  Statement s(db_,
              "UPDATE jobs SET status = ?, finished_at_ms = ?, http_status = ?, content_type = ?, headers = ?, "
              "body = ? WHERE id = ? AND status = 'running'");
  s.bind(1, std::string(to_string(status))).bind(2, finished_at_ms);
  if (result) {
    s.bind(3, static_cast<std::int64_t>(result->http_status)).bind(4, result->content_type);
    s.bind(5, join_headers(result->headers)).bind_blob(6, result->body);
  }
  s.bind(7, id);
  s.step();
  return s.changes() == 1;
}

bool SqliteJobStore::cancel_queued(const std::string& id, std::int64_t finished_at_ms) {
  std::lock_guard lock(mutex_);
  Statement s(db_, "UPDATE jobs SET status = 'cancelled', finished_at_ms = ? WHERE id = ? AND status = 'queued'");
  s.bind(1, finished_at_ms).bind(2, id);
  s.step();
  return s.changes() == 1;
}

bool SqliteJobStore::remove_finished(const std::string& id) {
  std::lock_guard lock(mutex_);
  Statement s(db_, "DELETE FROM jobs WHERE id = ? AND status IN ('done', 'failed', 'cancelled')");
  s.bind(1, id);
  s.step();
  return s.changes() == 1;
}

std::size_t SqliteJobStore::count_unfinished(const std::string& client) {
  std::lock_guard lock(mutex_);
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
  Statement s(db_, "SELECT COUNT(*) FROM jobs WHERE status IN ('queued', 'running')");
  s.step();
  return static_cast<std::size_t>(s.integer(0));
}

std::size_t SqliteJobStore::remove_finished_before(std::int64_t cutoff_ms) {
  std::lock_guard lock(mutex_);
  Statement s(db_, "DELETE FROM jobs WHERE status IN ('done', 'failed', 'cancelled') AND finished_at_ms < ?");
  s.bind(1, cutoff_ms);
  s.step();
  return s.changes();
}

}  // namespace implicitizer::server
