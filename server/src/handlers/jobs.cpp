#include "handlers/jobs.hpp"

#include <memory>

#include "jobs/job_event_feed.hpp"
#include "jobs/job_manager.hpp"

namespace implicitizer::server {

namespace {

Response make_job_not_found(const std::string& id) {
  return make_error_response(http::status::not_found, "job_not_found", "no job " + id + " (unknown or expired)");
}

Response make_jobs_disabled() {
  return make_error_response(http::status::not_found, "not_found", "this server runs no jobs");
}

}  // namespace

Response handle_job_submit(const Request& request, const std::string& client, const HandlerContext& context) {
  if (context.jobs == nullptr) return make_jobs_disabled();
  return context.jobs->submit(request, client);
}

Response handle_job_status(const std::string& id, const HandlerContext& context) {
  if (context.jobs == nullptr) return make_jobs_disabled();
  const std::optional<JobView> view = context.jobs->view(id);
  if (!view) return make_job_not_found(id);
  return make_json_response(http::status::ok, encode_job(*view));
}

Response handle_job_result(const std::string& id, const HandlerContext& context) {
  if (context.jobs == nullptr) return make_jobs_disabled();
  return context.jobs->result(id);
}

Response handle_job_cancel(const std::string& id, const HandlerContext& context) {
  if (context.jobs == nullptr) return make_jobs_disabled();
  return context.jobs->cancel(id);
}

HandlerResult handle_job_events(const Request& request, const std::string& id, const HandlerContext& context) {
  if (context.jobs == nullptr) return make_jobs_disabled();
  if (!context.jobs->view(id)) return make_job_not_found(id);
  EventStream stream;
  stream.head = Response(http::status::ok, 11);
  stream.head.set(http::field::content_type, "text/event-stream");
  stream.head.set(http::field::cache_control, "no-cache");
  stream.head.set(http::field::server, "implicitizer");
  // nginx buffers proxied bodies unless told not to; events must arrive as they are sent.
  stream.head.set("X-Accel-Buffering", "no");
  if (request.method() == http::verb::head) return stream.head;
  // Bounded: a stream outlives neither its job's queueing and running nor this.
  const auto max_duration = 2 * context.config.max_job_time;
  auto feed = std::make_shared<JobEventFeed>(*context.jobs, id, max_duration);
  stream.next = [feed] { return feed->next(); };
  return stream;
}

}  // namespace implicitizer::server
