#include "handlers/jobs.hpp"

#include <iostream>
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

// A store that cannot answer (Redis down, a disk error, a file another process has
// locked) is the server's trouble, not the request's: 503, naming the store, so that
// an operator reading it or the log knows which store to look at. `answer` runs as a
// StoreCall, on the store executor: however long the store takes, no network thread
// waits for it.
template <typename Answer>
HandlerResult answer_with_store(const HandlerContext& context, Answer answer) {
  if (context.jobs == nullptr) return make_jobs_disabled();
  return StoreCall{[&context, answer = std::move(answer)]() -> StoreAnswer {
    try {
      return answer(*context.jobs);
    } catch (const std::exception& e) {
      const std::string why = describe_job_store(context.config.store) + ": " + e.what();
      std::cerr << "implicitizer-server: " + why + "\n" << std::flush;
      Response response = make_error_response(http::status::service_unavailable, "job_store_unavailable",
                                              "the job store cannot answer: " + why);
      response.set(http::field::retry_after, std::to_string(context.config.retry_after_seconds));
      return response;
    }
  }};
}

}  // namespace

HandlerResult handle_job_submit(const Request& request, const std::string& client, const HandlerContext& context) {
  return answer_with_store(context,
                           [request, client](JobManager& jobs) -> StoreAnswer { return jobs.submit(request, client); });
}

HandlerResult handle_job_status(const std::string& id, const HandlerContext& context) {
  return answer_with_store(context, [id](JobManager& jobs) -> StoreAnswer {
    const std::optional<JobView> view = jobs.view(id);
    if (!view) return make_job_not_found(id);
    return make_json_response(http::status::ok, encode_job(*view));
  });
}

HandlerResult handle_job_result(const std::string& id, const HandlerContext& context) {
  return answer_with_store(context, [id](JobManager& jobs) -> StoreAnswer { return jobs.result(id); });
}

HandlerResult handle_job_cancel(const std::string& id, const HandlerContext& context) {
  return answer_with_store(context, [id](JobManager& jobs) -> StoreAnswer { return jobs.cancel(id); });
}

HandlerResult handle_job_events(const Request& request, const std::string& id, const HandlerContext& context) {
  const bool head = request.method() == http::verb::head;
  return answer_with_store(context, [id, head, &context](JobManager& jobs) -> StoreAnswer {
    if (!jobs.view(id)) return make_job_not_found(id);
    EventStream stream;
    stream.head = Response(http::status::ok, 11);
    stream.head.set(http::field::content_type, "text/event-stream");
    stream.head.set(http::field::cache_control, "no-cache");
    stream.head.set(http::field::server, "implicitizer");
    // nginx buffers proxied bodies unless told not to; events must arrive as they are sent.
    stream.head.set("X-Accel-Buffering", "no");
    if (head) return stream.head;
    // Bounded: a stream outlives neither its job's queueing and running nor this.
    const auto max_duration = 2 * context.config.max_job_time;
    auto feed = std::make_shared<JobEventFeed>(jobs, id, max_duration);
    stream.next = [feed] { return feed->next(); };
    return stream;
  });
}

}  // namespace implicitizer::server
