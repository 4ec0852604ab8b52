#pragma once
/// \file
/// POST /v1/sdf: the GLSL distance function of an implicit surface.

#include <string>

#include "handlers/handler.hpp"
#include "implicitizer/service/sdf_request.hpp"

namespace implicitizer::server {

/// As handle_implicitize(), with decode_sdf_request() and answer_sdf_request(): the
/// exact change of frame can take a while for a high degree and a far box, so it
/// runs on the worker pool under the request's budget and is cached.
HandlerResult handle_sdf(const Request& request, const HandlerContext& context);

/// The cache key of `request` (see canonical_key(const ImplicitizeRequest&)).
std::string canonical_key(const SdfRequest& request);

}  // namespace implicitizer::server
