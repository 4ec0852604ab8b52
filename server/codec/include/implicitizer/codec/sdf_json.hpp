#pragma once
/// \file
/// `POST /v1/sdf` in JSON (json_params.hpp has the rules every decoder follows).

#include <string>
#include <string_view>

#include "implicitizer/codec/json_params.hpp"
#include "implicitizer/service/sdf_request.hpp"

namespace implicitizer {

/// Reads a `POST /v1/sdf` body: `{"implicit": F | "scene": SCENE, "mode": "fast"?,
/// "box": [x0, y0, z0, x1, y1, z1]?, "name": N?, "timeout_ms": T?}`. Box numbers are
/// read as doubles and passed on as their exact decimal value. A scene is read as
/// scene_json.hpp describes (nesting up to kMaxSceneJsonDepth is allowed here
/// whatever `limits` says). Throws InputError as decode_implicitize_request(), the
/// scene's errors (fields "scene.children[1]…"), `invalid_value` (field "scene") when
/// both implicit and scene are given, and `invalid_value` ("mode": neither fast nor safe).
SdfRequest decode_sdf_request(std::string_view body, const JsonParams& limits = {});

/// `{"glsl", "function", "mode", "box": [x0, y0, z0, x1, y1, z1], "degree",
/// "uniforms": [{"name", "type", "default"}...]}`, and for a scene also `"nodes"` and
/// `"leaves": [{"implicit", "degree", "trimmed"}...]`: the answer of `POST /v1/sdf`
/// (and `implicitizer sdf --json`).
std::string encode_sdf_response(const SdfAnswer& answer);

}  // namespace implicitizer
