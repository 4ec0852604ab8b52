#pragma once
/// \file
/// A job as the stores keep it: what was asked, by whom, how far it got and, once
/// finished, the synchronous endpoint's response. Progress is not here: it lives in
/// the running computation's budget (JobManager reads it there).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "implicitizer/codec/job_json.hpp"

namespace implicitizer::server {

/// Where a job is in its life: queued → running → done | failed | cancelled
/// (queued → cancelled too). A job still running when its process died is queued
/// again by a persistent store.
enum class JobStatus { queued, running, done, failed, cancelled };

/// "queued", "running", "done", "failed" or "cancelled".
const char* to_string(JobStatus status);
/// The status named `text`; nullopt for any other text.
std::optional<JobStatus> parse_job_status(std::string_view text);
/// Whether `status` is one a job never leaves (done, failed, cancelled).
bool is_finished(JobStatus status);

/// The response a finished job answers: exactly what its synchronous endpoint
/// would have written (status, content type, the endpoint's own headers, body).
struct JobResult {
  unsigned http_status = 200;
  std::string content_type;
  /// The endpoint's own headers (X-Cache, X-Render-*), not the transport's.
  std::vector<std::pair<std::string, std::string>> headers;
  std::string body;
};

/// `headers` as "name\tvalue\n" lines, the form the persistent stores keep (HTTP
/// allows neither character in a header's name or value).
std::string join_headers(const std::vector<std::pair<std::string, std::string>>& headers);
/// The headers join_headers() wrote; a line without a tab is skipped.
std::vector<std::pair<std::string, std::string>> split_headers(const std::string& text);

/// One job.
struct JobRecord {
  std::string id;       ///< 32 random hex digits: unguessable, since ids are the only access control
  std::string kind;     ///< the endpoint: implicitize, groebner, resultant, sdf or render
  std::string request;  ///< the endpoint's request body (JSON text)
  std::string client;   ///< who submitted it (the peer address), for the per-client cap
  JobStatus status = JobStatus::queued;
  std::int64_t created_at_ms = 0;   ///< Unix milliseconds
  std::int64_t started_at_ms = 0;   ///< Unix milliseconds; 0 until it first runs
  std::int64_t finished_at_ms = 0;  ///< Unix milliseconds; 0 until finished (the TTL counts from here)
  std::optional<JobResult> result;  ///< set when done or failed
  /// A shared store's copy of a running job's progress and cancellation request,
  /// written by the replica that runs it (JobStore::heartbeat); empty otherwise.
  JobProgressView progress;
  bool cancel_requested = false;
};

}  // namespace implicitizer::server
