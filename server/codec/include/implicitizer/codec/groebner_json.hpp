#pragma once
/// \file
/// `POST /v1/groebner` in JSON (json_params.hpp has the rules every decoder follows).

#include <string>
#include <string_view>

#include "implicitizer/codec/json_params.hpp"
#include "implicitizer/service/groebner_request.hpp"

namespace implicitizer {

/// Reads a `POST /v1/groebner` body: `{"polynomials": [P..], "variables": [..]?,
/// "order": O?, "weights": [N..]?, "eliminate": [..]?, "method": M?, "timeout_ms": T?}`
/// (`weights`, `method` and `timeout_ms` extend the contract). Throws InputError as
/// decode_implicitize_request(), `unknown_order` ("order") and `unknown_method` ("method").
GroebnerRequest decode_groebner_request(std::string_view body, const JsonParams& limits = {});

/// `{"basis", "order", "method", "stats": {"pairs", "product_criterion",
/// "chain_criterion", "reductions", "zero_reductions", "reduction_steps", "work",
/// "max_degree", "basis_size", "groebner_ms", "modular"?}, "elapsed_ms"}`, plus
/// `"elimination_ideal"` when present.
std::string encode_groebner_response(const GroebnerAnswer& answer);

}  // namespace implicitizer
