#pragma once
/// \file
/// `POST /v1/render` in JSON (json_params.hpp has the rules every decoder follows).

#include <string>
#include <string_view>

#include "implicitizer/codec/json_params.hpp"
#include "implicitizer/service/render_request.hpp"

namespace implicitizer {

/// Reads a `POST /v1/render` body: the object, `shape`, `domain`, `mode`, `box` and
/// `name` as for /v1/sdf (decode_sdf_request), and `"width"?, "height"?, "method"?,
/// "aa"?, "eye": [x, y, z]?, "target": [x, y, z]?, "precision"?, "format":
/// "png"|"json"?, "timeout_ms"?`. Throws InputError as decode_sdf_request(),
/// `wrong_type` (sizes must be positive integers, eye and target three numbers),
/// `invalid_value` ("method", "precision", "format": a value outside its list).
RenderRequest decode_render_request(std::string_view body, const JsonParams& limits = {});

/// `{"width", "height", "method", "mode", "precision", "rays", "mean_evaluations",
/// "max_evaluations", "out_of_steps", "hits", "shading_evaluations", "threads",
/// "elapsed_ms", "shape"?, "dimension"}` (shape: what was drawn, when the object is one
/// polynomial leaf; dimension 2: a curve drawn in the plane), and `"png_base64"` (the PNG in base64) when `with_png`:
/// what `implicitizer render --json` prints (without the PNG) and POST /v1/render answers with `"format": "json"` (with
/// it).
std::string encode_render_response(const RenderAnswer& answer, bool with_png);

}  // namespace implicitizer
