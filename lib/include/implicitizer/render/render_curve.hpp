#pragma once
/// \file
/// The preview of a plane curve (a target of dimension 2, RenderTarget::dimension()):
/// a flat 2-D picture, not a ray-traced one. The object box's [x0, x1]×[y0, y1] fills
/// the image with its aspect kept (centred, the margins outside the box a darker
/// grey), y upwards; a faint grid at a round step (1, 2 or 5 times a power of ten, 4 to
/// 10 lines across the box's larger side) with the axes x = 0 and y = 0 darker; the
/// curve drawn as a line of `line_width` pixels; a solid curve's inside (value < 0)
/// lightly tinted.
///
/// Each pixel evaluates the scene once, at its centre (x, y, 0), in the target's
/// precision: the same value `float NAME_sdf(vec2 p)` gives a shader. The line is
/// antialiased from that value alone: |value|·(pixels per unit) is the pixel centre's
/// distance to the curve in pixels (fast mode: to first order; safe mode: a lower
/// bound, so the line can only look wider where the bound is loose), and the pixel's
/// coverage is clamp(line_width/2 + 1/2 − distance, 0, 1), the share of a one-pixel
/// box filter that the line covers where the curve is straight. The grid lines and the
/// inside's edge are antialiased the same way. The web page's 2-D preview
/// (clients/web/preview.js) runs the same formulas in a fragment shader.

#include <array>
#include <cstddef>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/render/image.hpp"
#include "implicitizer/render/render_image.hpp"
#include "implicitizer/render/render_target.hpp"

namespace implicitizer {

/// The look of a curve preview (display values in [0, 1]).
struct CurveStyle {
  std::array<double, 3> paper{0.98, 0.98, 0.97};   ///< inside the box
  std::array<double, 3> margin{0.90, 0.90, 0.89};  ///< the image outside the box
  std::array<double, 3> grid{0.86, 0.87, 0.89};    ///< the grid lines
  std::array<double, 3> axes{0.62, 0.64, 0.68};    ///< x = 0 and y = 0
  std::array<double, 3> inside{0.99, 0.87, 0.72};  ///< a solid curve's inside
  std::array<double, 3> curve{0.09, 0.20, 0.55};   ///< the curve
  double line_width = 1.5;                         ///< the curve's width in pixels
};

/// Where the box lands in the image: pixel (px, py) (row 0 at the top, (0, 0) the
/// top-left corner) shows the point (centre_x + (px − width/2)/scale,
/// centre_y − (py − height/2)/scale).
struct CurveView {
  double centre_x = 0, centre_y = 0;  ///< the box's centre
  double scale = 1;                   ///< pixels per unit: min(width/(x1 − x0), height/(y1 − y0))
  double grid_step = 1;               ///< the grid's step in units
};

/// The view of the target's object box in a width×height image. Precondition: both > 0.
CurveView curve_view(const RenderTarget& target, std::size_t width, std::size_t height);

/// The grid step for a box whose larger side is `extent` (> 0): the smallest of
/// 1, 2, 5 × 10^k that is at least extent/10 (so 4 to 10 lines across).
double grid_step(double extent);

/// Draws the curve of `target` (dimension 2) into a width × height image, on one
/// thread (a curve costs one evaluation per pixel, far less than a 3-D render; the
/// antialiasing comes from the distance, so there is no supersampling). Statistics:
/// rays and evaluations are the pixels, hits the pixels the line touches, method
/// `sphere` (none applies). Throws InputError `invalid_size` (field "size") as
/// render_image(); LimitExceeded when `budget` runs out (checked before each row).
RenderResult render_curve(const RenderTarget& target, std::size_t width, std::size_t height,
                          const CurveStyle& style = {}, const Budget& budget = Budget());

}  // namespace implicitizer
