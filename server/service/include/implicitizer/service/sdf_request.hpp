#pragma once
/// \file
/// A distance-function request as the outside world states it (the contract's
/// `POST /v1/sdf` body, or `implicitizer sdf`'s arguments), its answer, and the one
/// function that computes it, shared by the CLI and the HTTP handler. The input is
/// one implicit surface or a scene (docs/sdf.md, "Scenes"), in mode fast or safe.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/scene/compiled_scene.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/sdf/glsl_export.hpp"

namespace implicitizer {

/// The fields of a request; the surface and the box are still text (exact numbers,
/// parsed under the budget).
struct SdfRequest {
  std::string implicit;  ///< F(x, y, z): the surface F = 0 (used when `scene` is absent)
  /// A scene, already decoded (parse_scene_json); replaces `implicit`.
  std::optional<SceneNode> scene;
  SdfMode mode = SdfMode::fast;
  /// x0, y0, z0, x1, y1, z1 as exact numbers ("0.25", "1e-30", "-3/7"); empty:
  /// the default box [-2, 2]^3.
  std::vector<std::string> box;
  std::string name = "surface";  ///< the function is NAME_sdf
  /// Wall-time limit in seconds; absent means the caller's budget alone.
  std::optional<double> timeout_seconds;
};

/// One polynomial leaf of a scene, as the answer reports it.
struct SdfLeafSummary {
  std::string implicit;  ///< its equation F (a parametric leaf's, implicitized)
  std::int32_t degree = 0;
  bool trimmed = false;  ///< a parametric patch trimmed to its box (an unsigned sheet)
};

/// What a request computed.
struct SdfAnswer {
  std::string glsl;                    ///< the source of `float NAME_sdf(vec3 p)`
  std::string function;                ///< NAME_sdf
  SdfMode mode = SdfMode::fast;        ///< the mode of the request
  std::array<double, 6> box{};         ///< the box used, rounded to double
  std::int32_t degree = 0;             ///< total degree of F; for a scene, the largest of its leaves (0: none)
  std::size_t nodes = 0;               ///< nodes of the scene (0: an implicit surface)
  std::vector<SceneUniform> uniforms;  ///< the scene's uniforms, in declaration order
  std::vector<SdfLeafSummary> leaves;  ///< the scene's polynomial leaves
};

/// "fast" or "safe": the mode's name in requests and answers (parse_sdf_mode reads it).
const char* to_string(SdfMode mode);

/// The scene box of a request's `box` field: six exact numbers x0, y0, z0, x1, y1,
/// z1 ("0.25", "1e-30", "-3/7"); empty: SceneBox::default_box(). Throws InputError
/// `invalid_box` (field "box") when there are not six numbers; the frame's checks
/// (hi > lo, magnitudes) are make_scene_frame()'s. Shared with POST /v1/render.
SceneBox parse_request_box(const std::vector<std::string>& box, const Budget& budget = Budget());

/// Answers `request` under `budget` (whose deadline the request's timeout, when
/// present, replaces). Throws InputError with its field
/// set: parse errors and `unknown_variable` ("implicit": only x, y, z may occur),
/// `constant_polynomial` ("implicit"), `degree_too_high` ("implicit": mode safe,
/// terms beyond fp32's range, see SafeSdf::build), `invalid_box` ("box": not six
/// numbers, or hi <= lo), `invalid_name` ("name"); for a scene the errors of
/// compile_scene() (fields are the node paths "scene.children[1].radius"), with the
/// request's box as the scene box and its name as the scene's name.
SdfAnswer answer_sdf_request(const SdfRequest& request, const Budget& budget = Budget());

}  // namespace implicitizer
