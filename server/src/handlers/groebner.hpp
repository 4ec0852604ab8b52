#pragma once
/// \file
/// POST /v1/groebner: the contract's Gröbner-basis endpoint.

#include <string>

#include "handlers/handler.hpp"
#include "implicitizer/service/groebner_request.hpp"

namespace implicitizer::server {

/// As handle_implicitize(), with decode_groebner_request() and answer_groebner_request().
HandlerResult handle_groebner(const Request& request, const HandlerContext& context);

/// The cache key of `request` (see canonical_key(const ImplicitizeRequest&)).
std::string canonical_key(const GroebnerRequest& request);

}  // namespace implicitizer::server
