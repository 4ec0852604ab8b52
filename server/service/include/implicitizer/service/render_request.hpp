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
#include "implicitizer/service/sdf_request.hpp"  // the mode and the box as for /v1/sdf

namespace implicitizer {

/// What POST /v1/render answers with: the image, or its statistics as JSON with the
/// image in base64.
enum class RenderFormat {
  png,   ///< image/png, the statistics in X-Render-* headers
  json,  ///< encode_render_response with png_base64
};

/// The fields of a request; the surface and the box are still text (parsed under
/// the budget), the choices typed.
struct RenderRequest {
  std::string implicit;  ///< F(x, y, z): the surface F = 0 (when neither parametric nor scene is given)
  /// x, y, z of a parametric surface (implicitized by the library, then drawn as its
  /// implicit equation: the whole surface, untrimmed).
  std::optional<std::array<std::string, 3>> parametric;
  std::optional<std::vector<std::string>> parameters;  ///< the parametric surface's parameters, in order
  std::optional<SceneNode> scene;                      ///< a decoded scene (replaces the others)
  SdfMode mode = SdfMode::fast;                        ///< docs/sdf.md
  std::vector<std::string> box;                 ///< six exact numbers, or empty: [-2, 2]^3 (see parse_request_box)
  std::string name = "surface";                 ///< the scene's name (as for /v1/sdf; it names nothing in a PNG)
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
/// InputError: those of check_render_size(), parse errors and `unknown_variable`
/// ("implicit"; "x", "y", "z" for a parametric surface), `invalid_value` ("scene":
/// more than one of implicit, x/y/z, scene), `missing_field` ("x": some but not all of x, y, z), `invalid_box`,
/// `invalid_camera` ("eye", "target"), `method_not_applicable` ("method": exact on a
/// scene that is not one polynomial leaf), the errors of compile_scene();
/// NoSingleEquation for a parametric surface that is not a surface; LimitExceeded.
RenderAnswer answer_render_request(const RenderRequest& request, const Budget& budget = Budget(),
                                   const RenderRequestParams& limits = {}, std::size_t threads = 0);

}  // namespace implicitizer
