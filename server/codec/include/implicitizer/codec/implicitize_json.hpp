#pragma once
/// \file
/// `POST /v1/implicitize` in JSON (json_params.hpp has the rules every decoder follows).

#include <string>
#include <string_view>

#include "implicitizer/codec/json_params.hpp"
#include "implicitizer/service/implicitize_request.hpp"

namespace implicitizer {

/// Reads a `POST /v1/implicitize` body: `{"x": E, "y": E, "z": E, "parameters": [..]?,
/// "method": M?, "modular": B?, "timeout_ms": T?}`. Throws InputError: `invalid_json`
/// (at the byte offset of the syntax error), `json_too_deep`, `wrong_type`,
/// `missing_field`, `unknown_field`, `duplicate_field`, `invalid_value` (a negative or
/// non-finite timeout), `unknown_method` ("method"); the error's field names the
/// offending member ("parameters[1]").
ImplicitizeRequest decode_implicitize_request(std::string_view body, const JsonParams& limits = {});

/// `{"implicit", "degree", "variables", "method", "verified", "elapsed_ms", "stats":
/// {"pairs", "product_criterion", "chain_criterion", "reductions", "zero_reductions",
/// "reduction_steps", "work", "max_degree", "basis_size", "groebner_ms", "verify_ms",
/// "route"?, "resultant"?, "interpolation"?, "modular"?}, "reproduce": {"singular",
/// "macaulay2"}}`.
std::string encode_implicitize_response(const ImplicitizeAnswer& answer);

}  // namespace implicitizer
