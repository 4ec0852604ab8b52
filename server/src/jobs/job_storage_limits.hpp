#pragma once
/// \file
/// How much a job store may hold, and what a submission is told when it would pass
/// that. Finished jobs are a cache of results: past a cap the oldest finished jobs go
/// first (of the client, then of everyone), so only jobs still queued or running can
/// make a store refuse a submission. Every store applies these in the same atomic
/// step as the insert, finish or cancel that brought it over a cap.

#include <cstddef>
#include <limits>
#include <vector>

#include "jobs/job.hpp"

namespace implicitizer::server {

/// The caps of one store (the flags --max-finished-jobs[-per-client] and
/// --max-job-bytes[-per-client]); the defaults are no caps.
struct JobStorageLimits {
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::size_t max_finished_per_client = kNone;  ///< finished jobs one client keeps
  std::size_t max_finished = kNone;             ///< finished jobs of all clients
  std::size_t max_bytes_per_client = kNone;     ///< job_stored_bytes() of one client's jobs
  std::size_t max_bytes = kNone;                ///< job_stored_bytes() of all jobs
};

/// What JobStore::insert() did with a job.
enum class JobAdmission {
  admitted,
  /// The client already has the most jobs queued or running (429 too_many_jobs).
  client_job_cap,
  /// The client's queued and running jobs with this one would pass
  /// max_bytes_per_client (507 job_storage_full).
  client_bytes_cap,
  /// All queued and running jobs with this one would pass max_bytes (507 job_storage_full).
  store_bytes_cap,
};

/// The bytes of `job` that a store's caps count: its request (empty once finished,
/// since a result never needs it again) and its result's content type, headers and
/// body. The fixed fields (id, kind, client, times) are bounded by the count caps.
std::size_t job_stored_bytes(const JobRecord& job);

/// Which finished jobs to evict, given them newest first with their bytes: keep
/// while the running sums stay within `bytes_budget` and `count_budget` jobs, evict
/// from the first one past either (so the oldest go first). Returns the index of the
/// first job to evict (`bytes.size()` when all fit). The SQLite store states the
/// same rule in SQL (a window sum); this is the memory store's.
std::size_t first_evicted(const std::vector<std::size_t>& bytes_newest_first, long long bytes_budget,
                          long long count_budget);

}  // namespace implicitizer::server
