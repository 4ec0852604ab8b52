#include "jobs/job_event_feed.hpp"

#include "implicitizer/codec/error_json.hpp"

namespace implicitizer::server {

namespace {

std::string make_event(const char* name, const std::string& data) {
  return std::string("event: ") + name + "\ndata: " + data + "\n\n";
}

}  // namespace

JobEventFeed::JobEventFeed(JobManager& jobs, std::string id, std::chrono::steady_clock::duration max_duration)
    : jobs_(jobs),
      id_(std::move(id)),
      deadline_(std::chrono::steady_clock::now() + max_duration),
      last_sent_(std::chrono::steady_clock::now()) {}

std::pair<std::string, bool> JobEventFeed::next() {
  const auto now = std::chrono::steady_clock::now();
  std::optional<JobView> view;
  try {
    view = jobs_.view(id_);
  } catch (const std::exception& e) {
    return {make_event("end", encode_error("job_store_unavailable", e.what())), true};
  }
  if (!view) return {make_event("end", encode_error("job_not_found", "no job " + id_)), true};
  const std::optional<JobStatus> status = parse_job_status(view->status);
  if ((status && is_finished(*status)) || now >= deadline_) return {make_event("end", encode_job(*view)), true};
  // A change is a change of anything but the clock.
  const double elapsed_ms = view->progress.elapsed_ms;
  view->progress.elapsed_ms = 0;
  std::string state = encode_job(*view);
  if (state != last_state_) {
    last_state_ = std::move(state);
    last_sent_ = now;
    view->progress.elapsed_ms = elapsed_ms;
    return {make_event("progress", encode_job(*view)), false};
  }
  if (now - last_sent_ >= kKeepAlive) {
    last_sent_ = now;
    return {": keep-alive\n\n", false};
  }
  return {"", false};
}

}  // namespace implicitizer::server
