#include "jobs/job_manager.hpp"

#include <iostream>
#include <random>

#include "computation_runner.hpp"
#include "handlers/groebner.hpp"
#include "handlers/implicitize.hpp"
#include "handlers/render.hpp"
#include "handlers/resultant.hpp"
#include "handlers/sdf.hpp"
#include "jobs/memory_job_store.hpp"
#include "jobs/redis_job_store.hpp"
#include "jobs/sqlite_job_store.hpp"

namespace implicitizer::server {

namespace {

// A computation whose peak passed this gives its freed memory back to the system,
// as the request workers do (worker_pool.cpp).
constexpr std::size_t kReleaseAfterBytes = std::size_t{64} << 20;
// How often an idle job thread looks for expired results (a submission wakes it at once).
constexpr std::chrono::seconds kIdleWake{1};
constexpr const char* kKnownKinds = "implicitize, groebner, resultant, sdf, render";

std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// 128 random bits as hex: the id is the only key to a job, so it must not be guessable.
std::string make_job_id() {
  static thread_local std::random_device device;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string id;
  for (int word = 0; word < 4; ++word) {
    std::uint32_t bits = device();
    for (int nibble = 0; nibble < 8; ++nibble, bits >>= 4) id += kHex[bits & 15];
  }
  return id;
}

// The endpoint's answer as a job keeps it: its own headers, not the transport's.
JobResult make_job_result(const Response& response) {
  JobResult result;
  result.http_status = response.result_int();
  result.body = response.body();
  for (const auto& field : response) {
    const http::field name = field.name();
    if (name == http::field::content_type) {
      result.content_type = std::string(field.value());
    } else if (name != http::field::content_length && name != http::field::server) {
      result.headers.emplace_back(std::string(field.name_string()), std::string(field.value()));
    }
  }
  return result;
}

JobStatus status_after(const ComputationRun& run, bool cancel_requested) {
  if (run.response.result_int() < 300) return JobStatus::done;
  return run.outcome == ComputationOutcome::cancelled && cancel_requested ? JobStatus::cancelled : JobStatus::failed;
}

ServerConfig with_job_limits(const ServerConfig& config) {
  ServerConfig jobs = config;
  // A job's request is answered as its endpoint would answer it, with the job time
  // limit in place of the synchronous cap: timeout_ms may lower it, not raise it.
  jobs.max_timeout = std::chrono::duration_cast<std::chrono::milliseconds>(config.max_job_time);
  jobs.default_timeout = jobs.max_timeout;
  return jobs;
}

}  // namespace

JobStorageLimits make_job_storage_limits(const ServerConfig& config) {
  return JobStorageLimits{config.max_finished_jobs_per_client, config.max_finished_jobs,
                          config.max_job_bytes_per_client, config.max_job_bytes};
}

std::unique_ptr<JobStore> make_job_store(const ServerConfig& config) {
  const JobStorageLimits limits = make_job_storage_limits(config);
  if (config.store.rfind("sqlite:", 0) == 0) return std::make_unique<SqliteJobStore>(config.store.substr(7), limits);
  if (config.store.rfind("redis://", 0) == 0) {
    const auto [host, port] = parse_redis_address(config.store);
    return std::make_unique<RedisJobStore>(
        host, port, std::chrono::duration_cast<std::chrono::milliseconds>(config.job_lease), limits);
  }
  return std::make_unique<MemoryJobStore>(limits);
}

std::unique_ptr<SharedResultCache> make_shared_result_cache(const ServerConfig& config) {
  if (config.store.rfind("redis://", 0) != 0) return nullptr;
  const auto [host, port] = parse_redis_address(config.store);
  return std::make_unique<RedisResultCache>(host, port, config.job_ttl);
}

JobManager::JobManager(const ServerConfig& config, std::unique_ptr<JobStore> store, ResultCache& cache,
                       MetricsRegistry& metrics, SharedResultCache* shared_cache)
    : server_config_(config),
      job_config_(with_job_limits(config)),
      context_{job_config_, cache, metrics, [] { return MetricsGauges{}; }, nullptr, shared_cache},
      kinds_{{"implicitize", handle_implicitize},
             {"groebner", handle_groebner},
             {"resultant", handle_resultant},
             {"sdf", handle_sdf},
             {"render", handle_render}},
      store_(std::move(store)),
      metrics_(metrics),
      lease_ms_(std::chrono::duration_cast<std::chrono::milliseconds>(config.job_lease).count()) {
  const unsigned n = std::max(1U, config.job_threads);
  live_workers_ = n + 1;
  for (unsigned i = 0; i < n; ++i) threads_.emplace_back([this] { work(); });
  threads_.emplace_back([this] {
    beat();
    std::lock_guard lock(mutex_);
    --live_workers_;
    exited_.notify_all();
  });
}

JobManager::~JobManager() { stop(std::chrono::milliseconds(1000)); }

Request JobManager::make_endpoint_request(const std::string& kind, const std::string& body) const {
  Request request(http::verb::post, "/v1/" + kind, 11);
  request.set(http::field::content_type, "application/json");
  request.body() = body;
  request.prepare_payload();
  return request;
}

Response JobManager::make_too_many_jobs_response() const {
  Response response = make_error_response(http::status::too_many_requests, "too_many_jobs",
                                          "this client has " + std::to_string(server_config_.max_jobs_per_client) +
                                              " jobs queued or running, the most allowed; retry when one has finished");
  response.set(http::field::retry_after, std::to_string(server_config_.retry_after_seconds));
  return response;
}

Response JobManager::make_storage_full_response(JobAdmission refusal) const {
  const bool per_client = refusal == JobAdmission::client_bytes_cap;
  const std::size_t cap = per_client ? server_config_.max_job_bytes_per_client : server_config_.max_job_bytes;
  Response response = make_error_response(
      http::status::insufficient_storage, "job_storage_full",
      std::string("the queued and running jobs of ") + (per_client ? "this client" : "all clients") +
          " with this request would hold more than " + std::to_string(cap) + " bytes (--max-job-bytes" +
          (per_client ? "-per-client" : "") + "); retry when one has finished");
  response.set(http::field::retry_after, std::to_string(server_config_.retry_after_seconds));
  return response;
}

Response JobManager::submit(const Request& request, const std::string& client) {
  JobSubmission submission;
  try {
    submission = decode_job_submission(request.body(), JsonParams{server_config_.json_max_depth});
  } catch (const InputError& e) {
    return make_refusal_response(e);
  }
  const auto kind = kinds_.find(submission.kind);
  if (kind == kinds_.end()) {
    return make_error_response(http::status::bad_request, "unknown_job_kind",
                               "unknown job kind '" + submission.kind + "' (known: " + kKnownKinds + ")");
  }
  // The cap first, so that a client at it is not decoded for nothing; the store checks
  // it again, atomically, when it inserts.
  if (store_->count_unfinished(client) >= server_config_.max_jobs_per_client) return make_too_many_jobs_response();
  // Exactly the synchronous endpoint's checks: its refusal is this answer. What it
  // would compute is computed later, on a job thread, under a fresh budget.
  HandlerResult checked = kind->second(make_endpoint_request(kind->first, submission.request), context_);
  JobRecord job;
  job.id = make_job_id();
  job.kind = kind->first;
  job.request = std::move(submission.request);
  job.client = client;
  job.created_at_ms = now_ms();
  if (auto* answered = std::get_if<Response>(&checked)) {
    if (answered->result_int() >= 300) return std::move(*answered);
    // Answered at once (a cached result): the job is born finished.
    job.status = JobStatus::done;
    job.started_at_ms = job.finished_at_ms = job.created_at_ms;
    job.result = make_job_result(*answered);
  }
  switch (store_->insert(job, server_config_.max_jobs_per_client)) {
    case JobAdmission::admitted:
      break;
    case JobAdmission::client_job_cap:
      return make_too_many_jobs_response();
    case JobAdmission::client_bytes_cap:
      return make_storage_full_response(JobAdmission::client_bytes_cap);
    case JobAdmission::store_bytes_cap:
      return make_storage_full_response(JobAdmission::store_bytes_cap);
  }
  wake_.notify_one();
  Response response = make_json_response(http::status::accepted, encode_job(make_view(job)));
  response.set(http::field::location, "/v1/jobs/" + job.id);
  return response;
}

std::optional<JobView> JobManager::view(const std::string& id) {
  std::optional<JobRecord> job = store_->find(id);
  if (!job) return std::nullopt;
  const std::int64_t ttl_ms = std::chrono::duration_cast<std::chrono::milliseconds>(server_config_.job_ttl).count();
  if (is_finished(job->status) && job->finished_at_ms + ttl_ms < now_ms()) return std::nullopt;  // expired
  return make_view(*job);
}

JobView JobManager::make_view(const JobRecord& job) {
  JobView view;
  view.id = job.id;
  view.kind = job.kind;
  view.status = to_string(job.status);
  view.progress.phase = view.status;
  if (job.status == JobStatus::running) {
    std::lock_guard lock(mutex_);
    if (const auto live = live_.find(job.id); live != live_.end()) {
      view.cancel_requested = live->second.cancel_requested;
      view.progress = read_progress(live->second);
    } else if (!job.progress.phase.empty()) {
      // Running on another replica: what its last heartbeat published.
      view.cancel_requested = job.cancel_requested;
      view.progress = job.progress;
      view.progress.elapsed_ms = static_cast<double>(std::max<std::int64_t>(0, now_ms() - job.started_at_ms));
    }
  } else if (is_finished(job.status)) {
    if (job.status == JobStatus::done) view.progress.fraction = 1.0;
    if (job.started_at_ms > 0) view.progress.elapsed_ms = static_cast<double>(job.finished_at_ms - job.started_at_ms);
    view.cancel_requested = job.status == JobStatus::cancelled;
  }
  if (job.result) {
    view.http_status = job.result->http_status;
    if (job.result->content_type == "application/json") view.result_json = job.result->body;
    view.result_url = "/v1/jobs/" + job.id + "/result";
  }
  return view;
}

JobProgressView JobManager::read_progress(const Live& live) {
  JobProgressView progress;
  progress.phase = "running";
  const ProgressReport step = live.budget.progress().step();
  const ProgressReport stage = live.budget.progress().stage();
  if (step.phase != nullptr) progress.phase = step.phase;
  if (step.fraction() >= 0) progress.fraction = step.fraction();
  progress.done = step.done;
  progress.total = step.total;
  if (stage.phase != nullptr) progress.stage = stage.phase;
  progress.stage_done = stage.done;
  progress.stage_total = stage.total;
  progress.elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - live.started).count();
  return progress;
}

void JobManager::beat() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    heartbeat_wake_.wait_for(lock, kHeartbeat);
    if (stopping_) break;
    std::vector<std::pair<std::string, JobProgressView>> running;
    for (const auto& [id, live] : live_) running.emplace_back(id, read_progress(live));
    lock.unlock();
    const std::int64_t lease_until = now_ms() + lease_ms_;
    std::vector<std::string> to_cancel;
    for (const auto& [id, progress] : running) {
      try {
        if (store_->heartbeat(id, progress, lease_until)) to_cancel.push_back(id);
      } catch (const std::exception& e) {
        report_store_error(e);  // the lease may lapse: another replica may take the job over
      }
    }
    lock.lock();
    for (const std::string& id : to_cancel) {
      if (const auto live = live_.find(id); live != live_.end()) {
        live->second.cancel_requested = true;
        live->second.budget.cancel();
      }
    }
  }
}

void JobManager::report_store_error(const std::exception& e) {
  const std::string message = describe_job_store(server_config_.store) + ": " + e.what();
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard lock(report_mutex_);
  if (message == last_store_error_ && now - last_store_error_logged_at_ < kRepeatedErrorQuiet) {
    ++store_error_repeats_;
    return;
  }
  std::string line = "implicitizer-server: job threads: " + message;
  if (store_error_repeats_ > 0) {
    line += " (the previous error came " + std::to_string(store_error_repeats_) + " more times)";
  }
  std::cerr << line + "\n" << std::flush;
  last_store_error_ = message;
  last_store_error_logged_at_ = now;
  store_error_repeats_ = 0;
}

Response JobManager::result(const std::string& id) {
  const std::optional<JobView> current = view(id);
  if (!current) return make_error_response(http::status::not_found, "job_not_found", "no job " + id);
  const std::optional<JobRecord> job = store_->find(id);
  if (!job || !job->result) {
    const bool cancelled = job && job->status == JobStatus::cancelled;
    return make_error_response(http::status::conflict, cancelled ? "job_cancelled" : "job_not_finished",
                               cancelled ? "job " + id + " was cancelled: it has no result"
                                         : "job " + id + " is " + current->status + "; poll /v1/jobs/" + id);
  }
  const JobResult& r = *job->result;
  Response response = make_response(static_cast<http::status>(r.http_status), r.body, r.content_type);
  for (const auto& [name, value] : r.headers) response.set(name, value);
  return response;
}

Response JobManager::cancel(const std::string& id) {
  std::optional<JobView> current = view(id);
  if (!current) return make_error_response(http::status::not_found, "job_not_found", "no job " + id);
  const std::optional<JobStatus> status = parse_job_status(current->status);
  if (status && is_finished(*status)) {
    store_->remove_finished(id);
    return make_response(http::status::no_content, "", "application/json");
  }
  if (!store_->cancel_queued(id, now_ms())) {
    // Running: here (claims and live_ change together under mutex_, so it is in
    // live_ unless it finished meanwhile) or on another replica sharing the store.
    store_->request_cancel(id);
    std::lock_guard lock(mutex_);
    if (const auto live = live_.find(id); live != live_.end()) {
      live->second.cancel_requested = true;
      live->second.budget.cancel();
    }
  }
  current = view(id);
  if (!current) return make_error_response(http::status::not_found, "job_not_found", "no job " + id);
  return make_json_response(http::status::accepted, encode_job(*current));
}

void JobManager::work() {
  for (;;) {
    std::optional<JobRecord> job;
    {
      std::unique_lock lock(mutex_);
      while (!stopping_) {
        try {
          job = store_->claim_next(now_ms());
        } catch (const std::exception& e) {
          report_store_error(e);  // retried after the idle wait
        }
        if (job) {
          live_.emplace(job->id, Live{Budget(), std::chrono::steady_clock::now(), false});
          break;
        }
        wake_.wait_for(lock, kIdleWake);
        tidy_store();
      }
      if (!job) {
        --live_workers_;
        exited_.notify_all();
        return;
      }
    }
    try {
      run_job(*job);
    } catch (const std::exception& e) {
      // The store failed while the job finished: its lease (a shared store) or the
      // next start (SQLite) queues it again.
      report_store_error(e);
      std::lock_guard lock(mutex_);
      live_.erase(job->id);
    }
  }
}

HandlerResult JobManager::route_job(const JobRecord& job) const {
  const auto kind = kinds_.find(job.kind);
  if (kind == kinds_.end()) {  // a store written by another version of the server
    return make_error_response(http::status::bad_request, "unknown_job_kind", "unknown job kind '" + job.kind + "'");
  }
  try {
    return kind->second(make_endpoint_request(job.kind, job.request), context_);
  } catch (...) {
    return make_exception_response(std::current_exception());
  }
}

void JobManager::run_job(const JobRecord& job) {
  HandlerResult routed = route_job(job);
  ComputationRun run;
  bool cancel_requested = false;
  if (auto* answered = std::get_if<Response>(&routed)) {
    run.response = std::move(*answered);  // a cached result, or a refusal under a changed configuration
  } else if (auto* computation = std::get_if<Computation>(&routed)) {
    {
      std::lock_guard lock(mutex_);
      Live& live = live_.at(job.id);
      live.budget = computation->budget;
      if (live.cancel_requested || stopping_) live.budget.cancel();
    }
    run = run_computation(computation->run, computation->budget, metrics_, "/v1/jobs");
    if (const MemoryAccount* account = computation->budget.memory_account()) {
      release_free_memory(account->peak_bytes(), kReleaseAfterBytes);
    }
  }
  bool shutting_down = false;
  {
    std::lock_guard lock(mutex_);
    cancel_requested = live_.at(job.id).cancel_requested;
    shutting_down = stopping_ && !cancel_requested;
    live_.erase(job.id);
  }
  // Stopped by the shutdown, not by a client: left running in the store, so that a
  // persistent store queues it again at the next start.
  if (shutting_down && run.outcome == ComputationOutcome::cancelled) return;
  const JobStatus status = status_after(run, cancel_requested);
  std::optional<JobResult> result;
  if (status != JobStatus::cancelled) result = make_job_result(run.response);
  store_->finish(job.id, status, result, now_ms());
}

void JobManager::tidy_store() {
  const std::int64_t now = now_ms();
  if (now < next_tidy_ms_) return;
  next_tidy_ms_ = now + 1000;
  try {
    store_->remove_finished_before(
        now - std::chrono::duration_cast<std::chrono::milliseconds>(server_config_.job_ttl).count());
    store_->requeue_expired(now);
  } catch (const std::exception& e) {
    report_store_error(e);
  }
}

std::size_t JobManager::unfinished() {
  try {
    return store_->count_unfinished();
  } catch (const std::exception& e) {
    report_store_error(e);
    return 0;
  }
}

std::size_t JobManager::stop(std::chrono::milliseconds wait) {
  std::unique_lock lock(mutex_);
  if (!stopping_) {
    stopping_ = true;
    for (auto& [id, live] : live_) live.budget.cancel();
  }
  wake_.notify_all();
  heartbeat_wake_.notify_all();
  exited_.wait_for(lock, wait, [this] { return live_workers_ == 0; });
  const std::size_t left = live_workers_;
  lock.unlock();
  for (std::thread& t : threads_) {
    if (!t.joinable()) continue;
    if (left == 0) {
      t.join();
    } else {
      t.detach();
    }
  }
  return left;
}

}  // namespace implicitizer::server
