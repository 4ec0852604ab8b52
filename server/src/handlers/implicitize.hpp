#pragma once
/// \file
/// POST /v1/implicitize: the contract's implicitization endpoint.

#include <string>

#include "handlers/handler.hpp"
#include "implicitizer/service/implicitize_request.hpp"

namespace implicitizer::server {

/// Decodes the body (400 with the codec's code and position on failure), answers a
/// request seen before from the cache (header `X-Cache: hit`), and otherwise returns
/// the computation: answer_implicitize_request() under the server's budget, whose
/// successful answer is stored in the cache (`X-Cache: miss`).
HandlerResult handle_implicitize(const Request& request, const HandlerContext& context);

/// The cache key of `request`: every field that changes the answer, length-prefixed
/// so that no two requests share a key; `timeout_ms` and JSON spelling (spaces, key
/// order) are not part of it.
std::string canonical_key(const ImplicitizeRequest& request);

}  // namespace implicitizer::server
