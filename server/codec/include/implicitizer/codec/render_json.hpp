#pragma once
/// \file
/// `POST /v1/render` in JSON (json_params.hpp has the rules every decoder follows).

#include <string>
#include <string_view>

#include "implicitizer/codec/json_params.hpp"
#include "implicitizer/service/render_request.hpp"

namespace implicitizer {

/// Reads a `POST /v1/render` body: the surface as for /v1/sdf (`"implicit": F` or
/// `"scene": SCENE`) or parametric (`"x", "y", "z": E`, `"parameters": [..]?`), and
/// `"mode"?, "box"?, "name"?, "width"?, "height"?, "method"?, "aa"?, "eye": [x, y,
/// z]?, "target": [x, y, z]?, "precision"?, "format": "png"|"json"?, "timeout_ms"?`.
/// Throws InputError as decode_sdf_request(), `wrong_type` (sizes must be positive
/// integers, eye and target three numbers), `missing_field` ("x": some of x, y, z
/// but not all), `invalid_value` ("scene": more than one surface; "mode", "method",
/// "precision", "format": a value outside its list).
RenderRequest decode_render_request(std::string_view body, const JsonParams& limits = {});

/// `{"width", "height", "method", "mode", "precision", "rays", "mean_evaluations",
/// "max_evaluations", "out_of_steps", "hits", "shading_evaluations", "threads",
/// "elapsed_ms"}`, and `"png_base64"` (the PNG in base64) when `with_png`: what
/// `implicitizer render --json` prints (without the PNG) and POST /v1/render answers
/// with `"format": "json"` (with it).
std::string encode_render_response(const RenderAnswer& answer, bool with_png);

}  // namespace implicitizer
