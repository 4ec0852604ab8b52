#include "router.hpp"

#include <algorithm>
#include <utility>

#include "computation_runner.hpp"
#include "handlers/groebner.hpp"
#include "handlers/healthz.hpp"
#include "handlers/implicitize.hpp"
#include "handlers/jobs.hpp"
#include "handlers/metrics.hpp"
#include "handlers/render.hpp"
#include "handlers/resultant.hpp"
#include "handlers/sdf.hpp"
#include "handlers/static_files.hpp"

namespace implicitizer::server {

bool Router::Route::accepts(http::verb method) const {
  if (method == http::verb::head) method = http::verb::get;
  return std::find(methods.begin(), methods.end(), method) != methods.end();
}

bool Router::Route::matches(std::string_view target, std::vector<std::string>& segments) const {
  segments.clear();
  std::string_view pattern = path;
  while (!pattern.empty() && !target.empty()) {
    const std::size_t p_end = std::min(pattern.find('/', 1), pattern.size());
    const std::size_t t_end = std::min(target.find('/', 1), target.size());
    const std::string_view want = pattern.substr(0, p_end);
    const std::string_view got = target.substr(0, t_end);
    if (want.size() > 2 && want[1] == '{') {
      if (got.size() < 2) return false;  // "/" alone: an empty segment matches nothing
      segments.emplace_back(got.substr(1));
    } else if (want != got) {
      return false;
    }
    pattern.remove_prefix(p_end);
    target.remove_prefix(t_end);
  }
  return pattern.empty() && target.empty();
}

namespace {

constexpr const char* kStaticAllow = "GET, HEAD, OPTIONS";

std::string_view header_value(const Request& request, http::field field) {
  const auto it = request.find(field);
  if (it == request.end()) return {};
  return {it->value().data(), it->value().size()};
}

}  // namespace

Router::Router(HandlerContext context) : context_(std::move(context)), cors_(context_.config.cors_origins) {
  const HandlerContext& c = context_;
  auto answer_now = [](Response r) { return HandlerResult(std::move(r)); };
  routes_.push_back(
      {"/healthz", {http::verb::get}, "GET, HEAD, OPTIONS", [answer_now](const Request& r, const RouteCall&) {
         return answer_now(handle_healthz(r));
       }});
  routes_.push_back(
      {"/metrics", {http::verb::get}, "GET, HEAD, OPTIONS", [&c, answer_now](const Request& r, const RouteCall&) {
         return answer_now(handle_metrics(r, c));
       }});
  routes_.push_back({"/v1/implicitize", {http::verb::post}, "POST, OPTIONS", [&c](const Request& r, const RouteCall&) {
                       return handle_implicitize(r, c);
                     }});
  routes_.push_back({"/v1/groebner", {http::verb::post}, "POST, OPTIONS", [&c](const Request& r, const RouteCall&) {
                       return handle_groebner(r, c);
                     }});
  routes_.push_back({"/v1/resultant", {http::verb::post}, "POST, OPTIONS", [&c](const Request& r, const RouteCall&) {
                       return handle_resultant(r, c);
                     }});
  routes_.push_back({"/v1/sdf", {http::verb::post}, "POST, OPTIONS", [&c](const Request& r, const RouteCall&) {
                       return handle_sdf(r, c);
                     }});
  routes_.push_back({"/v1/render", {http::verb::post}, "POST, OPTIONS", [&c](const Request& r, const RouteCall&) {
                       return handle_render(r, c);
                     }});
  add_job_routes();
}

void Router::add_job_routes() {
  const HandlerContext& c = context_;
  routes_.push_back({"/v1/jobs", {http::verb::post}, "POST, OPTIONS", [&c](const Request& r, const RouteCall& call) {
                       return handle_job_submit(r, call.peer, c);
                     }});
  routes_.push_back({"/v1/jobs/{id}",
                     {http::verb::get, http::verb::delete_},
                     "GET, HEAD, DELETE, OPTIONS",
                     [&c](const Request& r, const RouteCall& call) {
                       const std::string& id = call.segments.front();
                       return r.method() == http::verb::delete_ ? handle_job_cancel(id, c) : handle_job_status(id, c);
                     }});
  routes_.push_back(
      {"/v1/jobs/{id}/result", {http::verb::get}, "GET, HEAD, OPTIONS", [&c](const Request&, const RouteCall& call) {
         return HandlerResult(handle_job_result(call.segments.front(), c));
       }});
  routes_.push_back(
      {"/v1/jobs/{id}/events", {http::verb::get}, "GET, HEAD, OPTIONS", [&c](const Request& r, const RouteCall& call) {
         return handle_job_events(r, call.segments.front(), c);
       }});
}

std::vector<RouteInfo> Router::routes() const {
  std::vector<RouteInfo> out;
  for (const Route& route : routes_) out.push_back({route.path, route.allow});
  return out;
}

Routed Router::route(const Request& request, std::string_view peer) const {
  const std::string_view target(request.target().data(), request.target().size());
  if (target.empty() || target.front() != '/') {
    return {"other", finish(request, make_error_response(http::status::bad_request, "invalid_path",
                                                         "the request target must be a path starting with '/'"))};
  }
  const std::string_view path = target.substr(0, target.find_first_of("?#"));
  const std::string_view origin = header_value(request, http::field::origin);
  const bool preflight = request.method() == http::verb::options;

  // Behind a proxy the peer is the proxy: the configured header names the client.
  std::string_view client = peer;
  if (!context_.config.client_ip_header.empty()) {
    if (const auto it = request.find(context_.config.client_ip_header); it != request.end()) {
      client = std::string_view(it->value().data(), it->value().size());
    }
  }
  RouteCall call{{}, std::string(client)};
  const auto route =
      std::find_if(routes_.begin(), routes_.end(), [&](const Route& r) { return r.matches(path, call.segments); });
  if (route != routes_.end()) {
    if (preflight) {
      Response response = origin.empty() ? make_response(http::status::no_content, "", "text/plain")
                                         : cors_.answer_preflight(origin, route->allow);
      response.set(http::field::allow, route->allow);
      return {route->path, finish(request, std::move(response))};
    }
    if (!route->accepts(request.method())) {
      Response response = make_error_response(http::status::method_not_allowed, "method_not_allowed",
                                              "method " + std::string(request.method_string()) + " is not allowed on " +
                                                  route->path + " (allowed: " + route->allow + ")");
      response.set(http::field::allow, route->allow);
      return {route->path, finish(request, std::move(response))};
    }
    HandlerResult result = route->handle(request, call);
    if (auto* response = std::get_if<Response>(&result)) return {route->path, finish(request, std::move(*response))};
    if (auto* stream = std::get_if<EventStream>(&result)) return {route->path, finish(request, std::move(*stream))};
    if (auto* store_call = std::get_if<StoreCall>(&result))
      return {route->path, finish(request, std::move(*store_call))};
    return {route->path, finish(request, route->path, std::get<Computation>(std::move(result)))};
  }

  // Not an API route: the API namespace never falls through to files.
  const bool api_path = path == "/v1" || path.rfind("/v1/", 0) == 0;
  if (api_path || context_.config.static_dir.empty()) {
    return {"other", finish(request, make_error_response(http::status::not_found, "not_found",
                                                         "no such endpoint: " + std::string(path)))};
  }
  if (request.method() == http::verb::get || request.method() == http::verb::head) {
    return {"static", finish(request, handle_static_file(request, context_))};
  }
  if (preflight) {
    Response response = origin.empty() ? make_response(http::status::no_content, "", "text/plain")
                                       : cors_.answer_preflight(origin, kStaticAllow);
    response.set(http::field::allow, kStaticAllow);
    return {"static", finish(request, std::move(response))};
  }
  Response response = handle_static_file(request, context_);
  if (response.result() == http::status::ok) {
    response = make_error_response(http::status::method_not_allowed, "method_not_allowed",
                                   "static files allow GET and HEAD only");
    response.set(http::field::allow, kStaticAllow);
  }
  return {"static", finish(request, std::move(response))};
}

Response Router::make_overloaded_response(const Request& request, std::string_view queue) const {
  Response response = make_error_response(http::status::service_unavailable, "overloaded",
                                          "the server is busy (" + std::string(queue) + " queue full); retry later");
  response.set(http::field::retry_after, std::to_string(context_.config.retry_after_seconds));
  return finish(request, std::move(response));
}

Response Router::make_transport_error_response(const Request& request, http::status status, std::string_view code,
                                               std::string_view message) const {
  Response response = finish(request, make_error_response(status, code, message));
  response.keep_alive(false);
  return response;
}

Response Router::finish(const Request& request, Response response) const {
  response.version(request.version() == 10 ? 10 : 11);
  response.keep_alive(request.keep_alive());
  cors_.apply(header_value(request, http::field::origin), response);
  if (request.method() == http::verb::head) {
    // HEAD: the headers GET would send, Content-Length included, and no body.
    const std::size_t length = response.body().size();
    response.body().clear();
    response.content_length(length);
  }
  return response;
}

EventStream Router::finish(const Request& request, EventStream stream) const {
  stream.head.version(request.version() == 10 ? 10 : 11);
  // The body ends when the connection closes: nothing may follow it on this connection.
  stream.head.keep_alive(false);
  cors_.apply(header_value(request, http::field::origin), stream.head);
  return stream;
}

StoreCall Router::finish(const Request& request, StoreCall call) const {
  // Like a computation's: the header is all finishing needs.
  call.run = [this, inner = std::move(call.run), head = Request(request.base())]() -> StoreAnswer {
    StoreAnswer answer = inner();
    if (auto* response = std::get_if<Response>(&answer)) return finish(head, std::move(*response));
    return finish(head, std::get<EventStream>(std::move(answer)));
  };
  return call;
}

Computation Router::finish(const Request& request, const std::string& endpoint, Computation computation) const {
  // The worker needs the request's header to finish the response, not its body
  // (which may be a megabyte): copy only the header.
  computation.run = [this, inner = std::move(computation.run), budget = computation.budget, endpoint,
                     head = Request(request.base())]() {
    ComputationRun done = run_computation(inner, budget, context_.metrics, endpoint);
    return finish(head, std::move(done.response));
  };
  return computation;
}

}  // namespace implicitizer::server
