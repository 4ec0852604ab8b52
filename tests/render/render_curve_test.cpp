// Tests of lib/src/render/render_curve.cpp: the grid's step, the box's place in the
// image (aspect kept), and the picture of a circle: the line on the curve and only
// near it, 1.5 px wide, the solid's inside tinted, the grid and axes, the margins.

#include "implicitizer/render/render_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "implicitizer/core/errors.hpp"
#include "render/render_support.hpp"

namespace implicitizer {
namespace {

RenderTarget curve_target(const std::string& equation, const SceneBox& box, SdfMode mode = SdfMode::fast) {
  SceneNode node = test::implicit_node(equation);
  node.leaf.shape = SdfShape::solid;
  return RenderTarget::compile(node, SceneParams{mode, box, "c", "scene", 2});
}

// The distance in colour between a pixel and a style colour (largest channel, bytes).
int colour_distance(std::array<std::uint8_t, 3> pixel, const std::array<double, 3>& colour) {
  int d = 0;
  for (std::size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int(pixel[c]) - int(to_display_byte(colour[c]))));
  return d;
}

TEST(GridStep, OneTwoOrFiveTimesAPowerOfTenWithFourToTenLines) {
  EXPECT_DOUBLE_EQ(grid_step(4), 0.5);
  EXPECT_DOUBLE_EQ(grid_step(10), 1);
  EXPECT_DOUBLE_EQ(grid_step(1), 0.1);
  EXPECT_DOUBLE_EQ(grid_step(15), 2);
  EXPECT_DOUBLE_EQ(grid_step(3e-3), 5e-4);
  for (double extent : {0.013, 0.7, 3.3, 8.0, 42.0, 1234.5}) {
    const double lines = extent / grid_step(extent);
    EXPECT_GE(lines, 4 - 1e-9) << extent;
    EXPECT_LE(lines, 10 + 1e-9) << extent;
  }
}

TEST(CurveView, TheBoxFillsTheImageWithItsAspectKept) {
  // [-2, 2] x [-1, 1] in 200 x 200: 50 px per unit, the box 200 x 100 px, centred.
  const RenderTarget t = curve_target("x^2+y^2-1", test::axis_box({-2, -1, -2}, {2, 1, 2}));
  const CurveView v = curve_view(t, 200, 200);
  EXPECT_DOUBLE_EQ(v.scale, 50);
  EXPECT_DOUBLE_EQ(v.centre_x, 0);
  EXPECT_DOUBLE_EQ(v.centre_y, 0);
  EXPECT_DOUBLE_EQ(v.grid_step, 0.5);
}

TEST(RenderCurve, ACircleIsALineOnTheCurveWithItsInsideTinted) {
  const CurveStyle style;
  const RenderTarget circle = curve_target("x^2+y^2-1", test::axis_box({-2, -1.5, -2}, {2, 1.5, 2}));
  const std::size_t w = 240, h = 120;  // 40 px per unit (120 / 3), the box 160 x 120 px
  const RenderResult r = render_curve(circle, w, h);
  const CurveView v = curve_view(circle, w, h);
  ASSERT_DOUBLE_EQ(v.scale, 40);
  const auto pixel_of = [&](double x, double y) {
    return std::pair<std::size_t, std::size_t>{static_cast<std::size_t>(std::floor(w / 2.0 + x * v.scale)),
                                               static_cast<std::size_t>(std::floor(h / 2.0 - y * v.scale))};
  };
  // Every pixel whose centre is within 0.25 px of the circle is (nearly) the line's
  // colour; every pixel more than 1.5 px from it has none of it.
  std::size_t on = 0, near = 0;
  for (std::size_t py = 0; py < h; ++py) {
    for (std::size_t px = 0; px < w; ++px) {
      const double x = (px + 0.5 - w / 2.0) / v.scale, y = (h / 2.0 - py - 0.5) / v.scale;
      const double distance_px = std::abs(std::hypot(x, y) - 1) * v.scale;
      const auto p = r.image.pixel(px, py);
      if (distance_px < 0.25) {
        EXPECT_LE(colour_distance(p, style.curve), 12) << px << "," << py;
        ++on;
      } else if (distance_px > 1.5) {
        // The line's blue would pull red below the paper's, tint's or grid's.
        EXPECT_GE(p[0], to_display_byte(style.axes[0]) - 1) << px << "," << py;
        ++near;
      }
    }
  }
  EXPECT_GT(on, 20u);
  EXPECT_EQ(r.stats.rays, w * h);
  EXPECT_EQ(r.stats.evaluations, w * h);
  // The line's pixels: about its length times its width (2π·40 px · 1.5 px ≈ 377, plus the rims).
  EXPECT_GT(r.stats.hits, 300u);
  EXPECT_LT(r.stats.hits, 1200u);

  // Inside (off the grid): tinted; outside in the box: paper; beyond the box: margin.
  auto [ix, iy] = pixel_of(0.3, 0.3);
  EXPECT_LE(colour_distance(r.image.pixel(ix, iy), style.inside), 1);
  auto [ox, oy] = pixel_of(1.7, 1.2);
  EXPECT_LE(colour_distance(r.image.pixel(ox, oy), style.paper), 1);
  EXPECT_LE(colour_distance(r.image.pixel(3, 60), style.margin), 1);
  // The axes cross the box; the grid line x = 1.5 (step 0.5) is fainter.
  auto [ax, ay] = pixel_of(1.75, 0.0001);
  EXPECT_LE(colour_distance(r.image.pixel(ax, ay), style.axes), 40);
  auto [gx, gy] = pixel_of(1.5001, 1.25);
  EXPECT_LE(colour_distance(r.image.pixel(gx, gy), style.grid), 40);
}

TEST(RenderCurve, AnOpenCurveIsASheetWithNoInside) {
  // The parabola y = x² leaves its box: shape auto makes it a sheet, drawn as a line
  // with nothing tinted on either side.
  SceneNode node = test::implicit_node("y-x^2");
  node.leaf.shape = SdfShape::automatic;
  const RenderTarget parabola =
      RenderTarget::compile(node, SceneParams{SdfMode::fast, SceneBox::default_box(), "c", "scene", 2});
  ASSERT_EQ(parabola.shape(), SdfShape::sheet);
  const CurveStyle style;
  const RenderResult r = render_curve(parabola, 100, 100);
  // (0.3, 1.3) lies above the parabola, (0.3, -1.3) below; both are paper (off the grid).
  const CurveView v = curve_view(parabola, 100, 100);
  for (double y : {1.3, -1.3}) {
    const auto px = static_cast<std::size_t>(50 + 0.3 * v.scale), py = static_cast<std::size_t>(50 - y * v.scale);
    EXPECT_LE(colour_distance(r.image.pixel(px, py), style.paper), 1) << y;
  }
  EXPECT_GT(r.stats.hits, 100u);
}

TEST(RenderCurve, SafeModeDrawsTheSameCurve) {
  // The safe value is a lower bound of the distance: the line can only widen.
  const RenderTarget fast = curve_target("x^2+y^2-1", SceneBox::default_box(), SdfMode::fast);
  const RenderTarget safe = curve_target("x^2+y^2-1", SceneBox::default_box(), SdfMode::safe);
  const RenderResult a = render_curve(fast, 100, 100);
  const RenderResult b = render_curve(safe, 100, 100);
  EXPECT_GE(b.stats.hits, a.stats.hits);
  EXPECT_LT(b.stats.hits, 2 * a.stats.hits);
}

TEST(RenderCurve, RefusalsAndTheBudget) {
  const RenderTarget circle = curve_target("x^2+y^2-1", SceneBox::default_box());
  EXPECT_THROW(render_curve(circle, 0, 10), InputError);
  EXPECT_THROW(render_curve(circle, 20000, 10), InputError);
  Budget cancelled;
  cancelled.cancel();
  EXPECT_THROW(render_curve(circle, 10, 10, CurveStyle{}, cancelled), LimitExceeded);
}

}  // namespace
}  // namespace implicitizer
