#pragma once
/// \file
/// `POST /v1/sdf` in JSON (json_params.hpp has the rules every decoder follows).

#include <string>
#include <string_view>

#include "implicitizer/codec/json_params.hpp"
#include "implicitizer/service/sdf_request.hpp"

namespace implicitizer {

/// Reads a `POST /v1/sdf` body: the object, one of `"implicit": F`, `"x": X, "y": Y,
/// "z": Z?, "parameters": [..]?` (a parametric surface, or a plane curve without z) or
/// `"scene": SCENE`; `"shape": "auto"|"sheet"|"solid"?`, `"domain": [s0, s1, t0,
/// t1]?` (numbers or exact strings), `"tolerance": EPS?` (a parametric surface's),
/// `"mode": "fast"?`, `"box": [x0, y0, z0, x1, y1,
/// z1]?` (a curve: [x0, y0, x1, y1]), `"name": N?`, `"timeout_ms": T?`. Box numbers are
/// read as doubles and passed on as their exact decimal value. A scene is read as
/// scene_json.hpp describes (nesting up to kMaxSceneJsonDepth is allowed here
/// whatever `limits` says). Throws InputError as decode_implicitize_request(), the
/// scene's errors (fields "scene.children[1]…"), `invalid_value` ("scene": more than
/// one object; "mode", "shape": a value outside its list; "z": empty),
/// `invalid_tolerance` ("tolerance": not a number),
/// `missing_field` ("implicit", "x", "y") and `invalid_domain` ("domain": not an
/// array; "domain[i]": neither a number nor a string).
SdfRequest decode_sdf_request(std::string_view body, const JsonParams& limits = {});

/// `{"glsl", "function", "mode", "shape"?, "dimension", "box": [x0, y0, z0, x1, y1, z1]
/// (a curve: [x0, y0, x1, y1]), "degree", "uniforms": [{"name", "type", "default"}...]}`,
/// and for a scene also `"nodes"` and `"leaves": [{"implicit", "degree", "trimmed",
/// "shape", "approximation"?}...]`: the answer of `POST /v1/sdf` (and `implicitizer sdf
/// --json`). `shape` is the one picked (sheet or solid), absent for a scene that is not
/// one leaf; `"approximation"` (write_approximation) when the input had a tolerance.
std::string encode_sdf_response(const SdfAnswer& answer);

}  // namespace implicitizer
