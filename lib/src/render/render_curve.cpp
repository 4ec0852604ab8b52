#include "implicitizer/render/render_curve.hpp"

#include <algorithm>
#include <cmath>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/stopwatch.hpp"

namespace implicitizer {
namespace {

using Colour = std::array<double, 3>;

// Paints `colour` over `base` with opacity `alpha` in [0, 1].
void blend(Colour& base, const Colour& colour, double alpha) {
  for (std::size_t c = 0; c < 3; ++c) base[c] += alpha * (colour[c] - base[c]);
}

// The coverage of a line `width` pixels wide whose centre is `distance` pixels from
// the pixel's centre, under a one-pixel box filter (exact for a straight line
// parallel to the pixel grid).
double line_coverage(double distance, double width) { return std::clamp(width / 2 + 0.5 - distance, 0.0, 1.0); }

// The distance in pixels from coordinate v to the nearest multiple of `step`.
double grid_distance(double v, double step, double scale) {
  const double k = v / step;
  return std::abs(k - std::round(k)) * step * scale;
}

}  // namespace

double grid_step(double extent) {
  const double target = extent / 10;
  double step = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * step >= target * (1 - 1e-12)) return m * step;
  }
  return 10 * step;
}

CurveView curve_view(const RenderTarget& target, std::size_t width, std::size_t height) {
  const auto& lo = target.box_lo();
  const auto& hi = target.box_hi();
  CurveView view;
  view.centre_x = (lo[0] + hi[0]) / 2;
  view.centre_y = (lo[1] + hi[1]) / 2;
  view.scale = std::min(static_cast<double>(width) / (hi[0] - lo[0]), static_cast<double>(height) / (hi[1] - lo[1]));
  view.grid_step = grid_step(std::max(hi[0] - lo[0], hi[1] - lo[1]));
  return view;
}

RenderResult render_curve(const RenderTarget& target, std::size_t width, std::size_t height, const CurveStyle& style,
                          const Budget& budget) {
  if (width == 0 || height == 0 || width > 16384 || height > 16384 || width * height > (std::size_t{1} << 26)) {
    throw InputError("invalid_size", "1 to 16384 pixels a side and at most 2^26 pixels in all").in_field("size");
  }
  const Stopwatch timer;
  const CurveView view = curve_view(target, width, height);
  const auto& lo = target.box_lo();
  const auto& hi = target.box_hi();
  const bool solid = target.shape() == SdfShape::solid;
  RenderResult result;
  result.image = Image(width, height);
  RenderStats& stats = result.stats;
  for (std::size_t py = 0; py < height; ++py) {
    budget.check("render");
    const double y = view.centre_y - (static_cast<double>(py) + 0.5 - static_cast<double>(height) / 2) / view.scale;
    for (std::size_t px = 0; px < width; ++px) {
      const double x = view.centre_x + (static_cast<double>(px) + 0.5 - static_cast<double>(width) / 2) / view.scale;
      const bool in_box = x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1];
      Colour colour = in_box ? style.paper : style.margin;
      const double value = target.evaluate({x, y, 0});
      ++stats.evaluations;
      // The inside first, under the grid: the tint's edge antialiased like the line's.
      if (solid && std::isfinite(value)) blend(colour, style.inside, std::clamp(0.5 - value * view.scale, 0.0, 1.0));
      if (in_box) {
        const double grid = std::max(line_coverage(grid_distance(x, view.grid_step, view.scale), 1),
                                     line_coverage(grid_distance(y, view.grid_step, view.scale), 1));
        blend(colour, style.grid, grid);
        const double axes =
            std::max(line_coverage(std::abs(x) * view.scale, 1), line_coverage(std::abs(y) * view.scale, 1));
        blend(colour, style.axes, axes);
      }
      const double line = std::isfinite(value) ? line_coverage(std::abs(value) * view.scale, style.line_width) : 0;
      if (line > 0) ++stats.hits;
      blend(colour, style.curve, line);
      result.image.set_pixel(px, py,
                             {to_display_byte(colour[0]), to_display_byte(colour[1]), to_display_byte(colour[2])});
    }
  }
  stats.width = width;
  stats.height = height;
  stats.mode = target.mode();
  stats.rays = static_cast<std::uint64_t>(width) * height;
  stats.max_evaluations = 1;
  stats.threads = 1;
  stats.elapsed_ms = timer.elapsed_ms();
  return result;
}

}  // namespace implicitizer
