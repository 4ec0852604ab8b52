#pragma once
/// \file
/// `POST /v1/resultant` in JSON (json_params.hpp has the rules every decoder follows).

#include <string>
#include <string_view>

#include "implicitizer/codec/json_params.hpp"
#include "implicitizer/service/resultant_request.hpp"

namespace implicitizer {

/// Reads a `POST /v1/resultant` body: `{"polynomials": [F, G], "variable": V,
/// "timeout_ms": T?}`. Throws InputError as decode_implicitize_request(), and
/// `wrong_number_of_polynomials` (field "polynomials") unless there are exactly two.
ResultantRequest decode_resultant_request(std::string_view body, const JsonParams& limits = {});

/// `{"resultant", "variables", "degree", "method", "elapsed_ms"}`.
std::string encode_resultant_response(const ResultantAnswer& answer);

}  // namespace implicitizer
