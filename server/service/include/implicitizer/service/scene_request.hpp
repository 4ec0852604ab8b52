#pragma once
/// \file
/// The object a distance-function or render request describes (`POST /v1/sdf`,
/// `POST /v1/render`, `implicitizer sdf` and `render`), as the outside world states it:
/// exactly one of an implicit equation, a parametric surface or curve, or a scene; and
/// how it is shaped (auto, sheet, solid), over which parameter domain and in which box.
///
/// Every object compiles through the scene compiler (compile_scene): an implicit
/// equation or a parametrization becomes a scene of one leaf, so one path decides
/// shape, patch and curve for every request (docs/sdf.md, "Shapes", "Patches",
/// "Curves"). An equation without z, or a parametrization with x and y only, is a
/// plane curve: the scene's dimension is 2 and its box is four numbers x0, y0, x1, y1.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "implicitizer/approximation/patch_approximation.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/scene/compiled_scene.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/sdf/scene_frame.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer {

/// The fields sdf and render requests share; texts are exact numbers and expressions,
/// parsed under the budget when the request is answered.
struct SceneRequest {
  std::string implicit;  ///< F(x, y, z): the surface F = 0, or F(x, y): the plane curve F = 0
  /// x, y, z of a parametric surface; z empty: x, y of a plane curve.
  std::optional<std::array<std::string, 3>> parametric;
  std::optional<std::vector<std::string>> parameters;  ///< the parametrization's parameters, in order
  std::optional<SceneNode> scene;                      ///< a decoded scene (replaces the others)
  /// What the value describes; a scene's leaves carry their own (anything but
  /// automatic with a scene is `invalid_value`, field "shape").
  SdfShape shape = SdfShape::automatic;
  /// The parameter domain of a parametric input as exact numbers s0, s1[, t0, t1]
  /// (two per parameter); empty: the default domain (docs/sdf.md, "Patches").
  std::vector<std::string> domain;
  /// Exact numbers x0, y0, z0, x1, y1, z1 (a curve: x0, y0, x1, y1, or six with z
  /// ignored); empty: fitted to the patch for a parametric input, else [-2, 2]^3.
  std::vector<std::string> box;
  SdfMode mode = SdfMode::fast;  ///< docs/sdf.md
  std::string name = "surface";  ///< the GLSL function is NAME_sdf
  /// A parametric surface's tolerance, a fraction of its patch box's diagonal: the
  /// patch is approximated within it both ways (polynomial_leaf.hpp, "Approximated
  /// patches"); none: the exact equation. A scene's leaves carry their own.
  std::optional<double> tolerance;
};

/// How a leaf with a tolerance was built: what the answers report as "approximation".
struct ApproximationSummary {
  double tolerance = 0;        ///< EPS asked
  std::string kept_exact;      ///< why the exact equation was kept ("" when approximated)
  std::int32_t degree = 0;     ///< the largest piece degree (kept exact: F's)
  std::size_t pieces = 1;      ///< surfaces joined by min
  std::size_t glsl_lines = 0;  ///< lines of the scene's GLSL
  /// Both one-sided distances relative to the patch box's diagonal (0, certified,
  /// when the exact equation was kept), and how each was established.
  double patch_to_surface = 0;
  BoundMethod patch_to_surface_method = BoundMethod::certified;
  double surface_to_patch = 0;
  BoundMethod surface_to_patch_method = BoundMethod::certified;
  std::size_t surface_to_patch_samples = 0;  ///< the sample a measured bound was taken on
};

/// The summary of `leaf` when its source had a tolerance (nullopt otherwise), with
/// `glsl_lines` lines of GLSL.
std::optional<ApproximationSummary> summarize_approximation(const PolynomialLeaf& leaf, std::size_t glsl_lines);

/// The number of lines of `text` (a last line without its newline counts).
std::size_t count_lines(const std::string& text);

/// "fast" or "safe": the mode's name in requests and answers (parse_sdf_mode reads it).
const char* to_string(SdfMode mode);

/// The scene a request compiles, and the options to compile it with.
struct RequestScene {
  SceneNode root;
  SceneParams params;
  bool one_leaf = false;  ///< an implicit or parametric input (not a scene): root is its leaf
};

/// The scene box of a request's `box` field for a scene of `dimension` (3: six exact
/// numbers x0, y0, z0, x1, y1, z1; 2: four, x0, y0, x1, y1, or six with z ignored,
/// the z side being [-m, m] with m the larger half side, so the frame's scale is that
/// of the plane box); empty: SceneBox::default_box(). Throws InputError `invalid_box`
/// (field "box") for another count or a text that is not a number; the frame's checks
/// (hi > lo, magnitudes) are make_scene_frame()'s.
SceneBox parse_request_box(const std::vector<std::string>& box, int dimension = 3, const Budget& budget = Budget());

/// The parameter domain of a request's `domain` field: `2 * parameters` exact numbers
/// s0, s1[, t0, t1], one closed interval per parameter. Throws InputError
/// `invalid_domain`: field "domain" for the wrong count, "domain[i]" for a text that
/// is not a finite number, or for the lower end of an interval with lo >= hi.
std::vector<std::pair<Rational, Rational>> parse_request_domain(const std::vector<std::string>& domain,
                                                                std::size_t parameters,
                                                                const Budget& budget = Budget());

/// The scene of `request`: its scene, or one implicit or parametric leaf carrying the
/// request's shape, domain and box, with the dimension (2 for an equation without z
/// or a parametrization without z) and the scene box. Throws InputError
/// `invalid_value` ("scene": more than one object; "shape": a shape with a scene),
/// `missing_field` ("implicit": none), `invalid_domain` ("domain": a domain without a
/// parametric input, or see parse_request_domain), `invalid_box`, and the parse
/// errors of the implicit equation (field "implicit"); LimitExceeded.
RequestScene make_request_scene(const SceneRequest& request, const Budget& budget = Budget());

/// Rethrows an error of compiling `scene` under the request's own field names: a
/// one-leaf scene's "scene.equation" is "implicit", "scene.x" is "x", "scene.domain"
/// is "domain", "scene.box" is "box"; and a parametric input whose image is not a
/// surface (or curve) is NoSingleEquation with its generators, as for implicitize
/// (HTTP 422, exit 4), rather than the InputError of one wrong leaf of a scene (the
/// elimination runs again under `budget` to find them).
[[noreturn]] void rethrow_request_error(const InputError& e, const RequestScene& scene, const Budget& budget);

/// `compile()` (compile_scene, RenderTarget::compile, …) with its InputErrors passed
/// through rethrow_request_error().
template <typename Compile>
auto compile_request_scene(const RequestScene& scene, const Budget& budget, Compile&& compile) -> decltype(compile()) {
  try {
    return compile();
  } catch (const InputError& e) {
    rethrow_request_error(e, scene, budget);
  }
}

}  // namespace implicitizer
