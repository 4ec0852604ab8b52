#pragma once
/// \file
/// The tiled renderer: one primary ray per sample (AA×AA samples per pixel),
/// marched with the chosen method, shaded (shading.hpp) where it hits, the seed's
/// grey where it misses; tiles of tile_size × tile_size pixels taken from a shared
/// counter by one thread per core. Every pixel is computed from its own rays only,
/// so the image and the statistics do not depend on the number of threads. The
/// budget is checked before every tile: a time limit or a cancellation stops the
/// render and throws LimitExceeded saying how far it got.

#include <cstddef>
#include <cstdint>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/render/camera.hpp"
#include "implicitizer/render/image.hpp"
#include "implicitizer/render/march_ray.hpp"
#include "implicitizer/render/render_target.hpp"
#include "implicitizer/render/shading.hpp"

namespace implicitizer {

/// What and how to render.
struct RenderParams {
  std::size_t width = 256;         ///< pixels
  std::size_t height = 256;        ///< pixels
  std::uint32_t antialiasing = 2;  ///< AA: AA×AA samples per pixel, at (i + 0.5)/AA (the seed recommends 2)
  CameraSpec camera;               ///< see default_camera()
  MarchMethod method = MarchMethod::sphere;
  MarchParams march;  ///< see default_render_march_params()
  ShadingParams shading;
  std::size_t threads = 0;     ///< worker threads; 0: one per core (std::thread::hardware_concurrency)
  std::size_t tile_size = 16;  ///< tile side in pixels
};

/// The camera that frames the target's object box (RenderTarget::box_lo/box_hi): it
/// looks at the box centre from the first thesis' direction (3, 3, 5), up (0, 1, 0),
/// focal distance 1 (the seed's field of view, 2·atan(1/2) = 53.13° vertically), from
/// the distance R / sin(α) at which the box's bounding sphere (radius R, half the
/// box's diagonal) is tangent to the narrower half-angle α of the view: atan(1/2)
/// vertically, atan(aspect/2) across when the image is narrower than tall (aspect =
/// width/height < 1). So any box, flat or long, is seen whole, at any size.
CameraSpec default_camera(const RenderTarget& target, double aspect = 1);

/// The first thesis' camera scaled to the target: eye = centre + (3, 3, 5)·unit, looking
/// at the box centre (for the default box exactly the seed's camera). The fixed view of
/// the method comparisons (docs/render.md §4, §6, §10, bench/render_accuracy.cpp), so
/// that their measurements stay those of the thesis' setting; previews use default_camera().
CameraSpec seed_camera(const RenderTarget& target);

/// default_march_params(target) with t_max measured beyond the eye: t_max =
/// |eye − box centre| + 100·unit, so that moving the eye away does not clip the scene.
MarchParams default_render_march_params(const RenderTarget& target, const CameraSpec& camera);

/// Counts of one render. Rays are primary rays (width·height·AA²); evaluations are
/// the primary marches' (the method's cost), shading_evaluations those of normals,
/// shadows and occlusion.
struct RenderStats {
  std::size_t width = 0, height = 0;
  MarchMethod method = MarchMethod::sphere;
  SdfMode mode = SdfMode::fast;
  std::uint64_t rays = 0;
  std::uint64_t hits = 0;
  std::uint64_t out_of_steps = 0;  ///< rays that used every step: misses, counted here
  std::uint64_t evaluations = 0;   ///< sum over primary rays
  std::uint32_t max_evaluations = 0;
  std::uint64_t shading_evaluations = 0;
  std::size_t threads = 0;  ///< threads used
  double elapsed_ms = 0;    ///< wall time of the render (not of compiling the scene)

  /// evaluations / rays (0 for no rays).
  double mean_evaluations() const { return rays ? static_cast<double>(evaluations) / static_cast<double>(rays) : 0; }
};

/// An image and how it was made.
struct RenderResult {
  Image image;
  RenderStats stats;
};

/// Renders `target`; a plane curve (target.dimension() == 2) is drawn flat by
/// render_curve() (render_curve.hpp) with the default CurveStyle. Throws InputError `invalid_size` (field "size": width
/// or height 0 or above 16384, or more than 2^26 pixels), `invalid_value` (field "aa": antialiasing 0 or above 8; field
/// "tile_size": 0), `invalid_camera` (camera.hpp), `method_not_applicable` (field
/// "method": exact on a scene that is not one polynomial leaf); LimitExceeded when
/// `budget` runs out (checked before each tile and inside exact root isolation),
/// its message saying how many tiles were done.
RenderResult render_image(const RenderTarget& target, const RenderParams& settings, const Budget& budget = Budget());

}  // namespace implicitizer
