#pragma once
/// \file
/// The JSON form of requests, responses and errors: the contract's HTTP bodies,
/// which the command line's `--json` prints byte for byte. This is the only code
/// in the project that reads or writes JSON.
///
/// Decoding is strict: the body must be one UTF-8 JSON object; unknown fields are
/// refused (`unknown_field`) rather than ignored, so that a misspelt optional field
/// (`"timeout"` for `"timeout_ms"`) cannot silently fall back to a default, and a
/// field given twice is refused (`duplicate_field`). Nesting deeper than
/// JsonParams::max_depth is refused before parsing, so no input can exhaust the stack.
///
/// Encoding writes compact JSON (no spaces, no trailing newline) with keys in the
/// order the contract lists them; times in milliseconds with at most 3 decimals.

#include <string>
#include <string_view>

#include "implicitizer/codec/groebner_request.hpp"
#include "implicitizer/codec/implicitize_request.hpp"
#include "implicitizer/codec/render_request.hpp"
#include "implicitizer/codec/resultant_request.hpp"
#include "implicitizer/codec/sdf_request.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"

namespace implicitizer {

/// Limits of the decoders.
struct JsonParams {
  std::size_t max_depth = 32;  ///< deepest nesting of arrays and objects
};

/// Reads a `POST /v1/implicitize` body: `{"x": E, "y": E, "z": E, "parameters": [..]?,
/// "method": M?, "timeout_ms": T?}`. Throws InputError: `invalid_json` (at the byte
/// offset of the syntax error), `json_too_deep`, `wrong_type`, `missing_field`,
/// `unknown_field`, `duplicate_field`, `invalid_value` (a negative or non-finite
/// timeout); the error's field names the offending member ("parameters[1]").
ImplicitizeRequest decode_implicitize_request(std::string_view body, const JsonParams& limits = {});

/// Reads a `POST /v1/groebner` body: `{"polynomials": [P..], "variables": [..]?,
/// "order": O?, "weights": [N..]?, "eliminate": [..]?, "timeout_ms": T?}`
/// (`weights` and `timeout_ms` extend the contract). Throws InputError as
/// decode_implicitize_request().
GroebnerRequest decode_groebner_request(std::string_view body, const JsonParams& limits = {});

/// Reads a `POST /v1/resultant` body: `{"polynomials": [F, G], "variable": V,
/// "timeout_ms": T?}`. Throws InputError as decode_implicitize_request(), and
/// `wrong_number_of_polynomials` (field "polynomials") unless there are exactly two.
ResultantRequest decode_resultant_request(std::string_view body, const JsonParams& limits = {});

/// Reads a `POST /v1/sdf` body: `{"implicit": F | "scene": SCENE, "mode": "fast"?,
/// "box": [x0, y0, z0, x1, y1, z1]?, "name": N?, "timeout_ms": T?}`. Box numbers are
/// read as doubles and passed on as their exact decimal value. A scene is decoded by
/// decode_scene() (scene_json.hpp; nesting up to kMaxSceneJsonDepth is allowed here
/// whatever `limits` says). Throws InputError as decode_implicitize_request(), the
/// errors of decode_scene() (fields "scene.children[1]…"), and `invalid_value`
/// (field "scene") when both implicit and scene are given.
SdfRequest decode_sdf_request(std::string_view body, const JsonParams& limits = {});

/// Reads a `POST /v1/render` body: the surface as for /v1/sdf (`"implicit": F` or
/// `"scene": SCENE`) or parametric (`"x", "y", "z": E`, `"parameters": [..]?`), and
/// `"mode"?, "box"?, "name"?, "width"?, "height"?, "method"?, "aa"?, "eye": [x, y,
/// z]?, "target": [x, y, z]?, "precision"?, "format": "png"|"json"?, "timeout_ms"?`.
/// Throws InputError as decode_sdf_request(), `wrong_type` (sizes must be positive
/// integers, eye and target three numbers), `missing_field` ("x": some of x, y, z
/// but not all) and `invalid_value` ("scene": more than one surface).
RenderRequest decode_render_request(std::string_view body, const JsonParams& limits = {});

/// `{"width", "height", "method", "mode", "precision", "rays", "mean_evaluations",
/// "max_evaluations", "out_of_steps", "hits", "shading_evaluations", "threads",
/// "elapsed_ms"}`, and `"png_base64"` (the PNG in base64) when `with_png`: what
/// `implicitizer render --json` prints (without the PNG) and POST /v1/render answers
/// with `"format": "json"` (with it).
std::string encode_render_response(const RenderAnswer& answer, bool with_png);

/// `{"implicit", "degree", "variables", "method", "verified", "elapsed_ms", "stats":
/// {"pairs", "product_criterion", "chain_criterion", "reductions", "zero_reductions",
/// "reduction_steps", "max_degree", "basis_size", "groebner_ms", "verify_ms"},
/// "reproduce": {"singular", "macaulay2"}}`.
std::string encode_implicitize_response(const ImplicitizeAnswer& answer);

/// `{"basis", "order", "stats": {"pairs", "product_criterion", "chain_criterion",
/// "reductions", "zero_reductions", "reduction_steps", "max_degree", "basis_size",
/// "groebner_ms"}, "elapsed_ms"}`, plus `"elimination_ideal"` when present.
std::string encode_groebner_response(const GroebnerAnswer& answer);

/// `{"resultant", "variables", "degree", "method", "elapsed_ms"}`.
std::string encode_resultant_response(const ResultantAnswer& answer);

/// `{"glsl", "function", "mode", "box": [x0, y0, z0, x1, y1, z1], "degree",
/// "uniforms": [{"name", "type", "default"}...]}`, and for a scene also `"nodes"` and
/// `"leaves": [{"implicit", "degree", "trimmed"}...]`: the answer of `POST /v1/sdf`
/// (and `implicitizer sdf --json`).
std::string encode_sdf_response(const SdfAnswer& answer);

/// `{"error": {"code", "message", "position"?, "field"?}}`: position when the error
/// has one, field when it is not empty.
std::string encode_error(const InputError& error);

/// `{"error": {"code": "no_single_equation", "message", "generators": [..]}}`.
std::string encode_error(const NoSingleEquation& error);

/// `{"error": {"code", "message", "limit"}}` with code `time_limit_exceeded`,
/// `size_limit_exceeded` or `cancelled` and limit `time`, `size` or `cancelled`.
std::string encode_error(const LimitExceeded& error);

/// `{"error": {"code", "message"}}` for errors of no library type (`internal_error`,
/// `not_found`, ...).
std::string encode_error(std::string_view code, std::string_view message);

/// `{"status": status}`: the body of the server's GET /healthz.
std::string encode_health_status(std::string_view status);

/// One line of the server's access log (JSON lines on stderr):
/// `{"method", "path", "status", "ms", "bytes"}`; `path` without the query string.
std::string encode_access_log_entry(std::string_view method, std::string_view path, unsigned status, double ms,
                                    std::size_t bytes);

/// The `code` encode_error() writes for `limit`: `time_limit_exceeded`,
/// `size_limit_exceeded` or `cancelled`.
const char* limit_error_code(Limit limit);

}  // namespace implicitizer
