#pragma once
/// \file
/// What GET /v1/jobs/{id}/events sends: a Server-Sent Event each time the job's state
/// or progress changes (at most one per poll), a comment now and then so that proxies
/// and dead peers are noticed, and a final `end` event when the job has finished.

#include <chrono>
#include <string>
#include <utility>

#include "jobs/job_manager.hpp"

namespace implicitizer::server {

/// The events of one job for one listener. Not thread-safe: one connection polls it.
class JobEventFeed {
 public:
  /// Events of job `id` of `jobs`; the stream ends by itself after `max_duration`
  /// (a listener that still wants events reconnects, as EventSource does).
  JobEventFeed(JobManager& jobs, std::string id, std::chrono::steady_clock::duration max_duration);

  /// The next bytes to send ("" when nothing changed) and whether they end the stream:
  /// `event: progress` with the job's state (encode_job) as data while it runs,
  /// `event: end` with the final state (or a `job_not_found` error) at the end.
  std::pair<std::string, bool> next();

  /// A comment line is sent after this long without an event.
  static constexpr std::chrono::seconds kKeepAlive{15};

 private:
  JobManager& jobs_;
  std::string id_;
  std::chrono::steady_clock::time_point deadline_;
  std::chrono::steady_clock::time_point last_sent_;
  std::string last_state_;  // the state last sent, without its elapsed time
};

}  // namespace implicitizer::server
