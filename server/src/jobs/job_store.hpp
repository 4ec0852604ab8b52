#pragma once
/// \file
/// Where jobs are kept: one interface, so that the embedded store (memory), SQLite
/// and a shared store (Redis) are interchangeable behind --store. Every operation is
/// atomic on its own; the JobManager holds no lock of the store's while computing.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "jobs/job.hpp"
#include "jobs/job_storage_limits.hpp"

namespace implicitizer::server {

/// What messages call the store `spec` (--store): "SQLite job store PATH", "Redis job
/// store HOST:PORT", "memory job store".
inline std::string describe_job_store(const std::string& spec) {
  if (spec.rfind("sqlite:", 0) == 0) return "SQLite job store " + spec.substr(7);
  if (spec.rfind("redis://", 0) == 0) return "Redis job store " + spec.substr(8);
  return spec + " job store";
}

/// The jobs of one server (or of several replicas sharing a store). A store holds
/// within the JobStorageLimits it was made with: the insert, finish or cancel that
/// passes a cap evicts the oldest finished jobs (never the job it acts on) in the
/// same atomic step, and a finished job keeps no request.
class JobStore {
 public:
  virtual ~JobStore() = default;

  /// Adds `job` (a new id) unless it is queued and its client already has
  /// `max_unfinished` jobs queued or running, or its request would bring the queued
  /// and running jobs past a byte cap: that refusal then, and nothing is added. The
  /// check and the insertion are one step, so concurrent submissions (on several
  /// threads or replicas) cannot pass a cap together. A job inserted queued is
  /// later returned by claim_next().
  virtual JobAdmission insert(const JobRecord& job, std::size_t max_unfinished) = 0;
  /// The job `id`, or nullopt when there is none (never was, removed, expired).
  virtual std::optional<JobRecord> find(const std::string& id) = 0;
  /// Takes the oldest queued job and marks it running, started at `now_ms` (Unix
  /// milliseconds); nullopt when none is queued.
  virtual std::optional<JobRecord> claim_next(std::int64_t now_ms) = 0;
  /// Marks the running job `id` finished with `status` (done, failed, cancelled) and
  /// `result` at `finished_at_ms` (Unix milliseconds), dropping its request. False
  /// when it is not running.
  virtual bool finish(const std::string& id, JobStatus status, const std::optional<JobResult>& result,
                      std::int64_t finished_at_ms) = 0;
  /// Marks the queued job `id` cancelled at `finished_at`, dropping its request;
  /// false when it is not queued.
  virtual bool cancel_queued(const std::string& id, std::int64_t finished_at_ms) = 0;
  /// Removes the finished job `id`; false when there is no finished job `id`.
  virtual bool remove_finished(const std::string& id) = 0;
  /// Jobs of `client` that are queued or running.
  virtual std::size_t count_unfinished(const std::string& client) = 0;
  /// Removes the jobs finished before `cutoff_ms` (Unix milliseconds); returns how many.
  virtual std::size_t remove_finished_before(std::int64_t cutoff_ms) = 0;
  /// Jobs queued or running, of every client.
  virtual std::size_t count_unfinished() = 0;

  // A store shared by several replicas also needs what follows: a job may run on
  // another replica, and a replica may die with a job. A store of one process keeps
  // these no-ops: the JobManager cancels and watches its own jobs directly.

  /// Asks whichever replica runs job `id` to cancel it (seen at its next heartbeat).
  virtual void request_cancel(const std::string& /*id*/) {}
  /// Called every JobManager::kHeartbeat by the replica running job `id`: renews its
  /// lease until `lease_until_ms` and publishes `progress`. Returns whether a cancel
  /// was requested (request_cancel, perhaps on another replica).
  virtual bool heartbeat(const std::string& /*id*/, const JobProgressView& /*progress*/,
                         std::int64_t /*lease_until_ms*/) {
    return false;
  }
  /// Queues again the running jobs whose lease ended before `now_ms` (their replica
  /// died); returns how many.
  virtual std::size_t requeue_expired(std::int64_t /*now_ms*/) { return 0; }
};

}  // namespace implicitizer::server
