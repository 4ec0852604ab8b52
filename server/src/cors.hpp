#pragma once
/// \file
/// Cross-origin access for browser front-ends. Only the origin is policed: the API is
/// read-only toward the server's state and uses no cookies, so any method the route
/// allows, with a JSON Content-Type, is allowed to an allowed origin.

#include <string>
#include <string_view>
#include <vector>

#include "http_message.hpp"

namespace implicitizer::server {

/// The allowed origins: `*` among them allows any origin; empty allows none.
class CorsPolicy {
 public:
  /// A policy allowing `origins` (ServerConfig::cors_origins).
  explicit CorsPolicy(std::vector<std::string> origins);

  /// Whether a browser page from `origin` may read responses.
  bool allows(std::string_view origin) const;

  /// Adds Access-Control-Allow-Origin (`*`, or the origin itself with `Vary:
  /// Origin` for a list) when the request came with an allowed Origin; otherwise
  /// leaves `response` alone (the browser then hides it from the page).
  void apply(std::string_view origin, Response& response) const;

  /// The answer to a preflight (OPTIONS with Access-Control-Request-Method) for a
  /// route allowing `methods` (e.g. "GET, HEAD"): 204 with the Allow-* headers and a
  /// 10-minute Max-Age, or 403 `origin_not_allowed`.
  Response answer_preflight(std::string_view origin, std::string_view methods) const;

 private:
  std::vector<std::string> origins_;
  bool any_ = false;
};

}  // namespace implicitizer::server
