#pragma once
/// \file
/// A render request as the outside world states it (the `POST /v1/render` body, or
/// `implicitizer render`'s arguments), its answer, and the one function that
/// computes it, shared by the command line and the HTTP handler: an implicit
/// surface, a parametric surface or a scene, drawn by the preview renderer
/// (lib/include/implicitizer/render/) into a PNG.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/render/march_ray.hpp"
#include "implicitizer/render/render_image.hpp"
#include "implicitizer/render/render_target.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/service/scene_request.hpp"  // the object, shape, domain and box as for /v1/sdf

namespace implicitizer {

/// What POST /v1/render answers with: the image, or its statistics as JSON with the
/// image in base64.
enum class RenderFormat {
  png,   ///< image/png, the statistics in X-Render-* headers
  json,  ///< encode_render_response with png_base64
};

/// The fields of a request: the object, its shape, domain and box, mode and name as
/// for /v1/sdf (scene_request.hpp; the name names nothing in a PNG), then how to draw
/// it. A curve (dimension 2) is drawn in the plane.
struct RenderRequest : SceneRequest {
  std::size_t width = 256;                      ///< pixels
  std::size_t height = 256;                     ///< pixels
  MarchMethod method = MarchMethod::sphere;     ///< how rays march
  std::uint32_t antialiasing = 2;               ///< AA: AA×AA samples per pixel
  std::optional<std::array<double, 3>> eye;     ///< default: the box centre + (3, 3, 5)·unit
  std::optional<std::array<double, 3>> target;  ///< default: the box centre
  /// float (what the GLSL computes) or double
  EvaluationPrecision precision = EvaluationPrecision::single;
  RenderFormat format = RenderFormat::png;  ///< the endpoint's answer
  /// Wall-time limit in seconds; absent means the caller's budget alone.
  std::optional<double> timeout_seconds;
};

/// The sizes a request may ask for.
struct RenderRequestParams {
  std::size_t max_side = 4096;                      ///< width and height at most this
  std::uint64_t max_rays = std::uint64_t{4} << 20;  ///< width·height·AA² at most this (1024²·2²)
};

/// What a request computed.
struct RenderAnswer {
  std::string png;    ///< the PNG file
  RenderStats stats;  ///< size, method, mode, rays, evaluations, hits, out of steps, time
  EvaluationPrecision precision = EvaluationPrecision::single;
  int dimension = 3;              ///< 2: a plane curve, drawn in the plane
  std::optional<SdfShape> shape;  ///< the shape drawn, when the object is one polynomial leaf
  /// An input with a tolerance: how it was built (glsl_lines: of the GLSL /v1/sdf returns).
  std::optional<ApproximationSummary> approximation;
};

/// Parses "float" or "double"; throws InputError `invalid_value` (field "precision") otherwise.
EvaluationPrecision parse_evaluation_precision(const std::string& name);

/// "float" or "double".
const char* to_string(EvaluationPrecision precision);

/// Parses "png" or "json"; throws InputError `invalid_value` (field "format") otherwise.
RenderFormat parse_render_format(const std::string& name);

/// Checks the sizes of `request` against `limits` before anything is computed.
/// Throws InputError `invalid_size` (field "width"/"height": 0 or above max_side),
/// `invalid_value` (field "aa": 0 or above 8), `render_too_large` (field "width":
/// more than max_rays primary rays; HTTP 413).
void check_render_size(const RenderRequest& request, const RenderRequestParams& limits = {});

/// Answers `request` under `budget` (whose deadline the request's timeout, when
/// present, replaces), with `threads` render threads (0: one per core). Throws
/// InputError: those of check_render_size(), `invalid_name`, those of
/// make_request_scene() (one object, `invalid_box`, `invalid_domain`, parse errors
/// of "implicit"), the errors of compile_scene() under the request's field names
/// (rethrow_request_error: "implicit", "x", "domain", …), `invalid_camera` ("eye",
/// "target"), `method_not_applicable` ("method": exact on a scene that is not one
/// polynomial leaf, or an approximation); NoSingleEquation for a parametrization whose
/// image is not a surface or curve; ToleranceNotMet; LimitExceeded.
RenderAnswer answer_render_request(const RenderRequest& request, const Budget& budget = Budget(),
                                   const RenderRequestParams& limits = {}, std::size_t threads = 0);

}  // namespace implicitizer
