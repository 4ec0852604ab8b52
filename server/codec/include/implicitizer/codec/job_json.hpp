#pragma once
/// \file
/// The JSON of the jobs API (POST /v1/jobs, GET /v1/jobs/{id}, its events): a
/// submission in, a job's state out. The inner request stays JSON text: the endpoint
/// named by `kind` decodes it, exactly as its synchronous route would.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "implicitizer/codec/json_params.hpp"

namespace implicitizer {

/// A decoded POST /v1/jobs body.
struct JobSubmission {
  std::string kind;     ///< the endpoint's name ("groebner", ...); not checked here
  std::string request;  ///< the `request` member re-encoded as compact JSON text
};

/// Reads `{"kind": K, "request": {...}}`. Throws InputError (`invalid_json`,
/// `json_too_deep`, `wrong_type`, `missing_field`, `unknown_field`, `duplicate_field`)
/// naming the field; `request` must be an object.
JobSubmission decode_job_submission(std::string_view body, const JsonParams& limits);

/// How far a job has got (the progress member of a job's state).
struct JobProgressView {
  std::string phase;               ///< the innermost loop's phase, or the job's state ("queued", ...)
  std::optional<double> fraction;  ///< in [0, 1] when the loop knows its total
  std::uint64_t done = 0;          ///< units done of `total` (0 and 0 when unknown)
  std::uint64_t total = 0;         ///< 0 when unknown
  std::string stage;               ///< the outer loop's phase ("" when none reported)
  std::uint64_t stage_done = 0;    ///< units of the outer loop done
  std::uint64_t stage_total = 0;   ///< 0 when unknown
  double elapsed_ms = 0;           ///< since the job started running (0 while queued)
};

/// A job's state as GET /v1/jobs/{id} answers it.
struct JobView {
  std::string id;
  std::string kind;
  std::string status;  ///< queued, running, done, failed or cancelled
  bool cancel_requested = false;
  JobProgressView progress;
  /// When finished: the status the synchronous endpoint would have answered.
  std::optional<unsigned> http_status;
  /// When finished with a JSON body: that body, as text (embedded as JSON).
  std::optional<std::string> result_json;
  /// When finished: where the response itself (any content type) is served.
  std::string result_url;
};

/// `{"id", "kind", "status", "cancel_requested", "progress": {"phase", "fraction",
/// "done", "total", "stage"?, "elapsed_ms"}, "http_status"?, "result"?, "result_url"?}`.
std::string encode_job(const JobView& job);

}  // namespace implicitizer
