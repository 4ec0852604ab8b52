#pragma once
/// \file
/// Jobs in Redis (`--store redis://HOST:PORT`), shared by several replicas: one
/// queue, one result store. Built on Redis's own primitives: a list is the queue, a
/// claim moves an id atomically to the running list (RPOPLPUSH) and stamps a lease on
/// the job's hash; the replica running it renews the lease every heartbeat, and any
/// replica puts back on the queue a job whose lease has run out (its replica died).
/// Each multi-key step is one Lua script, so it is atomic in Redis.
///
/// Keys (prefix `implicitizer:`): `job:ID` a hash per job (fields of JobRecord, the
/// published progress `p_*`, `lease_until_ms`, `cancel_requested`); `jobs:queue` and
/// `jobs:running` lists of ids; `jobs:finished` a sorted set of ids by finishing time
/// (for the TTL); `client:PEER` the set of a client's unfinished ids (for its cap);
/// for JobStorageLimits, `finished:PEER` a client's finished ids by finishing time and
/// byte counters `ubytes:PEER`, `fbytes:PEER`, `jobs:ubytes`, `jobs:fbytes` (unfinished
/// and finished jobs' bytes, a client's and everyone's).

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "jobs/job_store.hpp"
#include "redis_connection.hpp"

namespace implicitizer::server {

/// A JobStore over one Redis connection (RedisConnection: serialized, reconnecting).
class RedisJobStore : public JobStore {
 public:
  /// Connects to `host`:`port` and checks it answers; `lease` is how long a claimed
  /// job stays with its replica without a heartbeat; holds within `limits` (every
  /// replica should give the same). Throws std::runtime_error when Redis cannot be
  /// reached.
  RedisJobStore(std::string host, int port, std::chrono::milliseconds lease, JobStorageLimits limits = {});

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
  void request_cancel(const std::string& id) override;
  bool heartbeat(const std::string& id, const JobProgressView& progress, std::int64_t lease_until_ms) override;
  std::size_t requeue_expired(std::int64_t now_ms) override;

 private:
  // `args` and then the four limits, in the order the scripts' limits_at() reads them.
  std::vector<std::string> append_limits(std::vector<std::string> args) const;

  const std::int64_t lease_ms_;
  const JobStorageLimits limits_;
  RedisConnection redis_;
};

}  // namespace implicitizer::server
