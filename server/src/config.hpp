#pragma once
/// \file
/// Every limit and setting of implicitizer-server in one place, with its default and
/// the command-line flag that changes it (docs/api.md lists the same table).

#include <chrono>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace implicitizer::server {

/// The server's settings. Defaults are the documented ones; parse_server_flags()
/// overrides them from the command line.
struct ServerConfig {
  // ---- transport ------------------------------------------------------------
  std::string host = "127.0.0.1";  ///< --host: address to bind
  unsigned short port = 8080;      ///< --port: TCP port (0 = any free port, printed at start)
  unsigned io_threads = 1;         ///< --io-threads: threads running the network loop
  /// --static: directory served at `/` (empty = no static files, `/` answers 404).
  std::string static_dir;
  std::size_t max_body_bytes = 1 << 20;    ///< --max-body-bytes: larger bodies get 413
  std::size_t max_header_bytes = 8 << 10;  ///< --max-header-bytes: larger headers get 431
  /// --read-timeout-ms: armed before every read (request line, headers, body, and the
  /// idle wait between keep-alive requests); a client that is slower is dropped.
  std::chrono::milliseconds read_timeout{10'000};
  std::chrono::milliseconds write_timeout{10'000};  ///< --write-timeout-ms: per response
  /// --keep-alive-requests: requests answered on one connection before it is closed.
  unsigned max_requests_per_connection = 100;
  std::size_t max_static_file_bytes = 16 << 20;  ///< --max-static-file-bytes: larger files get 404

  // ---- computation ----------------------------------------------------------
  unsigned worker_threads = 0;  ///< --threads: workers running the algebra (0 = one per core)
  /// --queue-size: computations waiting for a worker; one more gets 503 + Retry-After.
  std::size_t queue_capacity = 256;
  unsigned retry_after_seconds = 1;  ///< --retry-after: the Retry-After of a 503
  /// --default-timeout-ms: budget of a request without `timeout_ms`.
  std::chrono::milliseconds default_timeout{10'000};
  /// --max-timeout-ms: the cap; a larger `timeout_ms`, or 0 ("no limit"), gets this.
  std::chrono::milliseconds max_timeout{60'000};
  /// --max-terms: largest intermediate polynomial (terms) of a computation; beyond → 413.
  std::size_t max_terms = 200'000;
  /// --max-memory-mb: memory one computation may hold, in MiB; beyond → 413
  /// `memory_limit_exceeded`. 0 (the default) derives it: three quarters of the
  /// machine's memory shared by the workers, so that all of them at their limit
  /// still fit.
  std::size_t max_memory_mb = 0;
  /// --max-variables: variables (identifiers) of one request; more → 413 at once.
  std::size_t max_variables = 64;
  /// --max-polynomials: polynomials of one groebner request; more → 413 at once.
  std::size_t max_polynomials = 1000;
  std::size_t json_max_depth = 32;   ///< --json-max-depth: deeper request JSON gets 400
  std::size_t cache_capacity = 256;  ///< --cache-size: results kept (LRU; 0 = no cache)
  /// --shutdown-grace-ms: on SIGTERM/SIGINT, how long in-flight work may finish
  /// before it is cancelled.
  std::chrono::milliseconds shutdown_grace{5'000};

  // ---- jobs (POST /v1/jobs) ------------------------------------------------
  /// --max-job-seconds: a job's time limit (its request's timeout_ms may lower it).
  std::chrono::seconds max_job_time{3600};
  /// --job-ttl: how long a finished job's result is kept, in seconds.
  std::chrono::seconds job_ttl{3600};
  /// --max-jobs-per-client: jobs one client (peer address) may have queued or
  /// running; one more gets 429 + Retry-After.
  std::size_t max_jobs_per_client = 16;
  /// --max-finished-jobs-per-client: finished jobs (results) kept per client; past
  /// it the client's oldest finished job is evicted (a cache, not a refusal).
  std::size_t max_finished_jobs_per_client = 256;
  /// --max-finished-jobs: finished jobs kept of all clients; past it the oldest goes.
  std::size_t max_finished_jobs = 4096;
  /// --max-job-bytes-per-client: bytes of one client's stored jobs (requests of
  /// unfinished jobs, results of finished ones). Past it the client's oldest finished
  /// jobs are evicted; a submission whose request would bring the queued and running
  /// jobs alone past it gets 507 job_storage_full.
  std::size_t max_job_bytes_per_client = std::size_t{64} << 20;
  /// --max-job-bytes: the same for all clients together.
  std::size_t max_job_bytes = std::size_t{256} << 20;
  /// --job-threads: threads running jobs, apart from the request workers.
  unsigned job_threads = 1;
  /// --store: where jobs are kept: `memory` (the default; lost on restart),
  /// `sqlite:PATH` (`sqlite` alone: kDefaultSqlitePath) or `redis://HOST:PORT` (one
  /// queue and result store for several replicas).
  std::string store = "memory";
  /// --client-ip-header: behind a proxy, the request header that names the client
  /// (e.g. X-Real-IP), used for the per-client job cap instead of the peer address
  /// (which is the proxy's). Empty (the default): the peer address; only set it when
  /// every request comes through a proxy that sets the header, or clients could pick it.
  std::string client_ip_header;
  /// --job-lease-seconds: with a shared store, a running job whose replica has not
  /// renewed its lease for this long (it died) is queued again for another replica.
  std::chrono::seconds job_lease{15};

  // ---- browsers and logs ----------------------------------------------------
  /// --cors-origins: origins allowed to call the API from a browser; `*` (the
  /// default) allows any, an empty list none.
  std::vector<std::string> cors_origins{"*"};
  bool quiet = false;  ///< --quiet: no access log on stderr

  /// The number of workers to start: worker_threads, or the number of cores.
  unsigned effective_worker_threads() const;
  /// The memory limit of one computation in bytes: max_memory_mb, or the derived default.
  std::size_t effective_max_memory_bytes() const;
};

/// The file `--store sqlite` uses: in the server's working directory.
inline constexpr const char* kDefaultSqlitePath = "implicitizer-jobs.sqlite3";

/// A command line the server cannot start with; main() prints it with the usage.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The flags, one per line, for `--help`.
extern const char* const kServerUsage;

/// Reads the flags of `implicitizer-server` (see kServerUsage). Returns nullopt for
/// `--help`. Throws UsageError for an unknown flag, a missing value or a value out
/// of range.
std::optional<ServerConfig> parse_server_flags(const std::vector<std::string>& args);

}  // namespace implicitizer::server
