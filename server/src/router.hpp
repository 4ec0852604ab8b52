#pragma once
/// \file
/// The pure heart of the server: a request in, a response (or a computation that
/// will produce one) out. No sockets, no threads: the session does the transport,
/// the worker pool runs the computations. Every endpoint is one handler file; adding
/// one is one line in the route table (router.cpp).

#include <string>
#include <variant>
#include <vector>

#include "cors.hpp"
#include "handlers/handler.hpp"

namespace implicitizer::server {

/// The router's decision for one request.
struct Routed {
  /// The metrics label: the route's path, "static" or "other" (never a raw path, so
  /// that label cardinality stays bounded).
  std::string endpoint;
  /// A finished response, a computation whose `run` returns a finished response
  /// and never throws (library errors are already mapped to the contract's errors),
  /// an event stream whose head is finished, or a store call whose `run` returns one
  /// of those finished.
  HandlerResult result;
};

/// One API route, for docs checks and Allow headers.
struct RouteInfo {
  std::string path;     ///< the path, e.g. "/v1/implicitize"; `{id}` matches one segment
  std::string methods;  ///< the Allow header value, e.g. "POST, OPTIONS"
};

/// Maps requests to handlers and puts the finishing touches every response shares:
/// HTTP version, keep-alive, CORS headers, HEAD's empty body.
class Router {
 public:
  /// A router over `context` (which must outlive it).
  explicit Router(HandlerContext context);
  // The route table refers to context_: a router stays where it was built.
  Router(const Router&) = delete;
  Router& operator=(const Router&) = delete;

  /// Routes `request` from `peer` (the client's address, for per-client limits; with
  /// --client-ip-header, that header's value when present): 404
  /// `not_found` for an unknown path, 405 `method_not_allowed` with Allow for a known
  /// path and a wrong method, preflight answers for OPTIONS, static files for other
  /// GET/HEAD paths when a static directory is configured.
  Routed route(const Request& request, std::string_view peer = {}) const;

  /// The 503 `overloaded` answer (with Retry-After) when the `queue` ("computation",
  /// "job store") refuses `request`'s work.
  Response make_overloaded_response(const Request& request, std::string_view queue) const;

  /// An error the transport found before the request was complete (`request` may
  /// hold only its header): finished, and with keep-alive off since the rest of the
  /// connection's bytes cannot be trusted.
  Response make_transport_error_response(const Request& request, http::status status, std::string_view code,
                                         std::string_view message) const;

  /// The API routes (not the static files), in table order.
  std::vector<RouteInfo> routes() const;

 private:
  // What a handler learns besides the request: the path's `{...}` segments and the peer.
  struct RouteCall {
    std::vector<std::string> segments;
    std::string peer;
  };
  struct Route {
    std::string path;                 // `{name}` segments match any one segment
    std::vector<http::verb> methods;  // HEAD is implied by GET
    std::string allow;                // the Allow header
    std::function<HandlerResult(const Request&, const RouteCall&)> handle;
    bool accepts(http::verb method) const;
    // Whether `path` is this route's; fills `segments` with the `{...}` parts.
    bool matches(std::string_view path, std::vector<std::string>& segments) const;
  };
  void add_job_routes();
  Response finish(const Request& request, Response response) const;
  EventStream finish(const Request& request, EventStream stream) const;
  Computation finish(const Request& request, const std::string& endpoint, Computation computation) const;
  StoreCall finish(const Request& request, StoreCall call) const;

  HandlerContext context_;
  CorsPolicy cors_;
  std::vector<Route> routes_;
};

}  // namespace implicitizer::server
