#pragma once
/// \file
/// POST /v1/resultant: the resultant of two polynomials with respect to one variable.

#include <string>

#include "handlers/handler.hpp"
#include "implicitizer/service/resultant_request.hpp"

namespace implicitizer::server {

/// As handle_implicitize(), with decode_resultant_request() and answer_resultant_request().
HandlerResult handle_resultant(const Request& request, const HandlerContext& context);

/// The cache key of `request` (see canonical_key(const ImplicitizeRequest&)).
std::string canonical_key(const ResultantRequest& request);

}  // namespace implicitizer::server
