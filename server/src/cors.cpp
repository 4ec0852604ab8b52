#include "cors.hpp"

#include <algorithm>

namespace implicitizer::server {

CorsPolicy::CorsPolicy(std::vector<std::string> origins) : origins_(std::move(origins)) {
  any_ = std::find(origins_.begin(), origins_.end(), "*") != origins_.end();
}

bool CorsPolicy::allows(std::string_view origin) const {
  if (origin.empty()) return false;
  return any_ || std::find(origins_.begin(), origins_.end(), origin) != origins_.end();
}

void CorsPolicy::apply(std::string_view origin, Response& response) const {
  if (!allows(origin)) return;
  if (any_) {
    response.set(http::field::access_control_allow_origin, "*");
  } else {
    response.set(http::field::access_control_allow_origin, origin);
    response.set(http::field::vary, "Origin");
  }
  // The render statistics travel in headers beside the PNG body (handlers/render.cpp):
  // a browser page on another origin reads them only if they are exposed.
  response.set(http::field::access_control_expose_headers,
               "Retry-After, X-Cache, X-Render-Width, X-Render-Height, X-Render-Method, X-Render-Mode, "
               "X-Render-Precision, X-Render-Rays, X-Render-Hits, X-Render-Out-Of-Steps, "
               "X-Render-Mean-Evaluations, X-Render-Max-Evaluations, X-Render-Elapsed-Ms, X-Render-Shape, "
               "X-Render-Dimension, X-Render-Tolerance, X-Render-Approximation-Exact, X-Render-Degree, "
               "X-Render-Pieces, X-Render-Glsl-Lines, X-Render-Patch-To-Surface, X-Render-Surface-To-Patch");
}

Response CorsPolicy::answer_preflight(std::string_view origin, std::string_view methods) const {
  if (!allows(origin)) {
    return make_error_response(http::status::forbidden, "origin_not_allowed",
                               "cross-origin requests from this origin are not allowed");
  }
  Response response = make_response(http::status::no_content, "", "text/plain");
  response.erase(http::field::content_type);
  apply(origin, response);
  response.set(http::field::access_control_allow_methods, methods);
  response.set(http::field::access_control_allow_headers, "Content-Type");
  response.set(http::field::access_control_max_age, "600");
  return response;
}

}  // namespace implicitizer::server
