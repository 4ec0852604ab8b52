#pragma once
/// \file
/// A distance-function request as the outside world states it (the contract's
/// `POST /v1/sdf` body, or `implicitizer sdf`'s arguments), its answer, and the one
/// function that computes it, shared by the CLI and the HTTP handler. The input is an
/// implicit surface or curve, a parametric surface or curve, or a scene (docs/sdf.md),
/// compiled as a scene (scene_request.hpp), in mode fast or safe.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/scene/compiled_scene.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"
#include "implicitizer/service/scene_request.hpp"

namespace implicitizer {

/// The fields of a request: the object, its shape, domain and box, mode and name
/// (scene_request.hpp), and a timeout.
struct SdfRequest : SceneRequest {
  /// Wall-time limit in seconds; absent means the caller's budget alone.
  std::optional<double> timeout_seconds;
};

/// One polynomial leaf of a scene, as the answer reports it.
struct SdfLeafSummary {
  std::string implicit;  ///< its equation F (a parametric leaf's, implicitized)
  std::int32_t degree = 0;
  bool trimmed = false;              ///< a parametric patch trimmed to its box (an unsigned sheet)
  SdfShape shape = SdfShape::solid;  ///< what the leaf's value describes (never automatic)
  std::optional<TrimmingSummary> trimming;  ///< how, when trimmed
  /// With a tolerance: how the leaf was built (glsl_lines: the whole scene's).
  std::optional<ApproximationSummary> approximation;
};

/// What a request computed.
struct SdfAnswer {
  std::string glsl;              ///< the source of `float NAME_sdf(vec3 p)` (vec2 p: a curve)
  std::string function;          ///< NAME_sdf
  SdfMode mode = SdfMode::fast;  ///< the mode of the request
  /// The frame box actually used (a fitted patch's, else the request's), rounded to
  /// double; a curve's z side is its frame's and is not reported.
  std::array<double, 6> box{};
  int dimension = 3;  ///< 3: `NAME_sdf(vec3 p)`; 2: a plane curve, `NAME_sdf(vec2 p)`
  /// The shape picked: the leaf's, for an implicit or parametric input or a scene
  /// that is one polynomial leaf; absent for other scenes (each leaf says its own).
  std::optional<SdfShape> shape;
  std::int32_t degree = 0;             ///< total degree of F; for a scene, the largest of its leaves (0: none)
  std::size_t nodes = 0;               ///< nodes of the scene (0: an implicit surface)
  std::vector<SceneUniform> uniforms;  ///< the scene's uniforms, in declaration order
  std::vector<SdfLeafSummary> leaves;  ///< the scene's polynomial leaves
  /// How the patch of an input is trimmed (a scene's leaves say their own).
  std::optional<TrimmingSummary> trimming;
  /// An approximated sheet's side (sheet_side.hpp): `float NAME_side(vec3 p)`, whose
  /// sign tells the sheet's sides apart; empty otherwise.
  std::string side_glsl;
  std::string side_function;  ///< NAME_side, with side_glsl
  /// An input with a tolerance (not a scene: its leaves say their own): how it was built.
  std::optional<ApproximationSummary> approximation;
};

/// A request's scene, compiled: what answer_sdf_request() describes, and what
/// `implicitizer sdf --eval` evaluates.
struct CompiledSdfRequest {
  RequestScene source;  ///< the scene and the options it was compiled with
  CompiledScene scene;
};

/// Compiles `request` under `budget` (whose deadline the request's timeout, when
/// present, replaces). Throws what answer_sdf_request() throws.
CompiledSdfRequest compile_sdf_request(const SdfRequest& request, const Budget& budget = Budget());

/// What a compiled request answers: GLSL, function, box, shape, degree, …
SdfAnswer describe_sdf_request(const CompiledSdfRequest& compiled);

/// Answers `request` under `budget` (whose deadline the request's timeout, when
/// present, replaces): describe_sdf_request(compile_sdf_request(request, budget)).
/// Throws InputError with its field set: `invalid_name` ("name"), those of
/// make_request_scene() (one object, `invalid_box`, `invalid_domain`, parse errors),
/// then the errors of compile_scene() under the request's field names (an implicit
/// input's "implicit": `unknown_variable`, `constant_polynomial`, `degree_too_high`
/// in mode safe where terms leave fp32's range; a parametric input's "x", "y", "z",
/// "domain": `invalid_domain`, `unbounded_patch`; "tolerance": `invalid_tolerance`; a scene's node paths
/// "scene.children[1].radius"); NoSingleEquation for a parametrization whose image
/// is not a surface or curve; ToleranceNotMet (a tolerance the approximation could not
/// reach within its limits, with the best bound reached); LimitExceeded.
SdfAnswer answer_sdf_request(const SdfRequest& request, const Budget& budget = Budget());

}  // namespace implicitizer
