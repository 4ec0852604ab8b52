#pragma once
/// \file
/// The jobs API's engine: takes submissions (validated exactly as the synchronous
/// endpoint would validate them), runs them on threads of its own, keeps their
/// progress and cancellation handles, and answers what a job is and what it answered.
///
/// The threads are dedicated, not the request WorkerPool's: a job may run for an
/// hour, and the pool's few workers (one per core) are what keeps interactive
/// requests answering; jobs sharing them would turn an hour of jobs into an hour of
/// 503s. The job queue itself is the store, so a persistent store keeps it across
/// restarts.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "handlers/handler.hpp"
#include "implicitizer/codec/job_json.hpp"
#include "jobs/job_store.hpp"

namespace implicitizer::server {

/// Submits, runs, cancels and reports jobs. Thread-safe.
class JobManager {
 public:
  /// The endpoint a job kind runs: the synchronous route's handler.
  using KindHandler = std::function<HandlerResult(const Request&, const HandlerContext&)>;

  /// Jobs kept in `store`, computed with `config`'s job limits (--max-job-seconds as
  /// the time cap) sharing `cache`, `metrics` and `shared_cache` (may be null) with
  /// the synchronous endpoints.
  /// Starts config.job_threads threads.
  JobManager(const ServerConfig& config, std::unique_ptr<JobStore> store, ResultCache& cache, MetricsRegistry& metrics,
             SharedResultCache* shared_cache = nullptr);
  /// stop().
  ~JobManager();
  JobManager(const JobManager&) = delete;
  JobManager& operator=(const JobManager&) = delete;

  /// POST /v1/jobs from `client`: 202 with `{"id", "status"}` and Location; the
  /// endpoint's own error (same status and body) for a request it would refuse;
  /// 400 `unknown_job_kind`; 429 `too_many_jobs` with Retry-After at the client's cap;
  /// 507 `job_storage_full` with Retry-After when the unfinished jobs' requests would
  /// pass a byte cap (finished jobs are evicted instead, oldest first).
  Response submit(const Request& request, const std::string& client);
  /// The state of job `id` (encode_job), or nullopt when there is no such job.
  std::optional<JobView> view(const std::string& id);
  /// GET /v1/jobs/{id}/result: the finished job's stored response; 409
  /// `job_not_finished` before that, 404 `job_not_found`.
  Response result(const std::string& id);
  /// DELETE /v1/jobs/{id}: cancels a queued or running job (202 with its state; a
  /// running computation stops at its next budget check), removes a finished one
  /// (204); 404 `job_not_found`.
  Response cancel(const std::string& id);

  /// Stops taking jobs, cancels the running ones (a persistent store keeps them as
  /// running, to be queued again at the next start) and joins the threads within
  /// about `wait`. Returns the number of threads that did not stop: they are
  /// detached and still refer to this manager, so the process must end
  /// (Server::stop() does). Idempotent.
  std::size_t stop(std::chrono::milliseconds wait);

  /// Jobs queued or running (for /metrics).
  std::size_t unfinished();

  /// How often a running job's lease is renewed and its progress published; also how
  /// soon a cancel asked on another replica reaches the computation.
  static constexpr std::chrono::milliseconds kHeartbeat{250};

 private:
  struct Live {
    Budget budget;  // the running computation's: cancel and progress
    std::chrono::steady_clock::time_point started;
    bool cancel_requested = false;
  };
  void work();
  HandlerResult route_job(const JobRecord& job) const;
  void run_job(const JobRecord& job);
  JobView make_view(const JobRecord& job);
  Request make_endpoint_request(const std::string& kind, const std::string& body) const;
  Response make_too_many_jobs_response() const;
  Response make_storage_full_response(JobAdmission refusal) const;
  // Every kHeartbeat: renews the leases of this replica's running jobs in the store,
  // publishes their progress, and cancels those another replica asked to cancel.
  void beat();
  static JobProgressView read_progress(const Live& live);
  // Once a second at most: drops expired results, queues again jobs whose lease ended.
  void tidy_store();
  // Logs a store error of the job threads, naming the store; the same message again
  // within kRepeatedErrorQuiet is counted, not logged (a store that is gone fails
  // every claim, once a second).
  void report_store_error(const std::exception& e);
  static constexpr std::chrono::seconds kRepeatedErrorQuiet{60};

  const ServerConfig& server_config_;
  ServerConfig job_config_;  // the server's, with the job time limit as timeout cap and default
  HandlerContext context_;
  std::map<std::string, KindHandler> kinds_;
  std::unique_ptr<JobStore> store_;
  MetricsRegistry& metrics_;

  std::mutex report_mutex_;  // guards the three below
  std::string last_store_error_;
  std::chrono::steady_clock::time_point last_store_error_logged_at_;
  std::size_t store_error_repeats_ = 0;

  std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::string, Live> live_;        // running jobs by id
  std::condition_variable heartbeat_wake_;  // only at stop
  bool stopping_ = false;
  std::int64_t next_tidy_ms_ = 0;
  const std::int64_t lease_ms_;
  std::size_t live_workers_ = 0;
  std::condition_variable exited_;  // a worker thread returned
  std::vector<std::thread> threads_;
};

/// The caps of config's --max-finished-jobs[-per-client] and --max-job-bytes[-per-client].
JobStorageLimits make_job_storage_limits(const ServerConfig& config);

/// The store `--store` names (config.store): MemoryJobStore, SqliteJobStore or RedisJobStore,
/// holding within make_job_storage_limits(config).
/// Throws std::runtime_error when the SQLite file cannot be opened.
std::unique_ptr<JobStore> make_job_store(const ServerConfig& config);

/// The shared result cache of `--store redis://...` (entries kept --job-ttl), or null
/// for the stores of one process. Throws std::runtime_error when Redis cannot be reached.
std::unique_ptr<SharedResultCache> make_shared_result_cache(const ServerConfig& config);

}  // namespace implicitizer::server
