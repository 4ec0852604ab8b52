// Tests of lib/src/render/render_image.cpp: the image and statistics do not depend
// on the number of threads; rays that run out of steps are counted misses drawn as
// background; the budget stops a render and says why; refusals; the PNG of a
// render decodes to the same pixels; the default camera frames the object's box;
// a plane curve is drawn flat (render_curve).

#include "implicitizer/render/render_image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/render/png_codec.hpp"
#include "implicitizer/render/render_curve.hpp"
#include "render/render_support.hpp"

namespace implicitizer {
namespace {

RenderParams settings_for(const RenderTarget& target, std::size_t w, std::size_t h, std::uint32_t aa) {
  RenderParams s;
  s.width = w;
  s.height = h;
  s.antialiasing = aa;
  s.camera = default_camera(target);
  s.march = default_render_march_params(target, s.camera);
  return s;
}

TEST(RenderImage, ThreadsGiveTheSameImage) {
  const RenderTarget target =
      test::implicit_target("(x^2+y^2+z^2+3)^2-16*(x^2+y^2)", test::axis_box({-3, -3, -1}, {3, 3, 1}));
  RenderParams s = settings_for(target, 70, 50, 2);
  s.tile_size = 8;
  s.threads = 1;
  const RenderResult one = render_image(target, s);
  s.threads = 3;
  const RenderResult three = render_image(target, s);
  EXPECT_TRUE(one.image == three.image);
  EXPECT_EQ(one.stats.evaluations, three.stats.evaluations);
  EXPECT_EQ(one.stats.hits, three.stats.hits);
  EXPECT_EQ(one.stats.max_evaluations, three.stats.max_evaluations);
  EXPECT_EQ(one.stats.shading_evaluations, three.stats.shading_evaluations);
  EXPECT_EQ(three.stats.threads, 3u);
  EXPECT_EQ(one.stats.rays, 70u * 50u * 4u);
  EXPECT_GT(one.stats.hits, one.stats.rays / 10);
  EXPECT_LT(one.stats.hits, one.stats.rays);
  EXPECT_GT(one.stats.mean_evaluations(), 1.0);
}

TEST(RenderImage, OutOfStepsRaysAreCountedMissesDrawnAsBackground) {
  const RenderTarget target = test::implicit_target("x^2+y^2+z^2-1");
  RenderParams s = settings_for(target, 40, 40, 1);
  const RenderResult full = render_image(target, s);
  ASSERT_GT(full.stats.hits, 50u);
  EXPECT_EQ(full.stats.out_of_steps, 0u);
  s.march.max_steps = 3;
  const RenderResult starved = render_image(target, s);
  EXPECT_GT(starved.stats.out_of_steps, 0u);
  EXPECT_LT(starved.stats.hits, full.stats.hits);
  std::size_t background = 0;
  for (std::size_t y = 0; y < 40; ++y) {
    for (std::size_t x = 0; x < 40; ++x) {
      if (starved.image.pixel(x, y) == std::array<std::uint8_t, 3>{242, 242, 242}) ++background;
    }
  }
  EXPECT_EQ(background, starved.stats.rays - starved.stats.hits);
  EXPECT_LE(starved.stats.max_evaluations, 3u);
}

TEST(RenderImage, TheBudgetStopsTheRenderAndSaysWhy) {
  const RenderTarget target = test::implicit_target("x^2+y^2+z^2-1");
  const RenderParams s = settings_for(target, 64, 64, 1);
  Budget cancelled;
  cancelled.cancel();
  try {
    render_image(target, s, cancelled);
    ADD_FAILURE() << "rendered under a cancelled budget";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
    EXPECT_NE(std::string(e.what()).find("render stopped after 0 of 16 tiles"), std::string::npos) << e.what();
  }
  const Budget expired = Budget::with_timeout(1e-9);
  try {
    render_image(target, s, expired);
    ADD_FAILURE() << "rendered past its deadline";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
}

TEST(RenderImage, Refusals) {
  const RenderTarget scene = RenderTarget::compile(make_node(NodeKind::sphere, {{"radius", 1.0}}), SceneParams{});
  auto code_of = [&](const RenderParams& s) {
    try {
      render_image(scene, s);
    } catch (const InputError& e) {
      return e.code() + "@" + e.field();
    }
    return std::string("rendered");
  };
  RenderParams s = settings_for(scene, 8, 8, 1);
  EXPECT_EQ(code_of(s), "rendered");
  s.method = MarchMethod::exact;
  EXPECT_EQ(code_of(s), "method_not_applicable@method");
  s = settings_for(scene, 8, 8, 0);
  EXPECT_EQ(code_of(s), "invalid_value@aa");
  s = settings_for(scene, 0, 8, 1);
  EXPECT_EQ(code_of(s), "invalid_size@size");
  s = settings_for(scene, 20000, 8, 1);
  EXPECT_EQ(code_of(s), "invalid_size@size");
}

TEST(RenderImage, ThePngOfARenderDecodesToItsPixels) {
  const RenderTarget target = test::implicit_target("x^2+y^2+z^2-1");
  const RenderResult r = render_image(target, settings_for(target, 33, 17, 1));
  const Image back = decode_png(encode_png(r.image));
  EXPECT_EQ(back.width(), 33u);
  EXPECT_EQ(back.height(), 17u);
  EXPECT_TRUE(back == r.image);
  EXPECT_EQ(back.pixel(0, 0), (std::array<std::uint8_t, 3>{242, 242, 242}));   // the seed's grey 0.95
  EXPECT_NE(back.pixel(16, 8), (std::array<std::uint8_t, 3>{242, 242, 242}));  // the sphere in the middle
}

TEST(DefaultCamera, FramesTheBoxsBoundingSphereFromTheSeedsDirection) {
  // The default box: R = 2·sqrt(3), seen from R / sin(atan(1/2)) = R·sqrt(5) along (3, 3, 5).
  const RenderTarget sphere = test::implicit_target("x^2+y^2+z^2-1");
  const CameraSpec spec = default_camera(sphere);
  const double distance = std::sqrt(spec.eye[0] * spec.eye[0] + spec.eye[1] * spec.eye[1] + spec.eye[2] * spec.eye[2]);
  EXPECT_NEAR(distance, 2 * std::sqrt(3.0) * std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(spec.eye[0] / distance, 3 / std::sqrt(43.0), 1e-12);
  EXPECT_NEAR(spec.eye[2] / distance, 5 / std::sqrt(43.0), 1e-12);
  EXPECT_EQ(spec.target, (std::array<double, 3>{0, 0, 0}));

  // Flat, long and shifted boxes, wide and tall images: every corner of the box is in the picture.
  for (const SceneBox& box : {test::axis_box({-3, -3, -0.01}, {3, 3, 0.01}), test::axis_box({10, -1, -1}, {30, 1, 1}),
                              test::axis_box({-1e-3, 5, 0}, {1e-3, 5.002, 1e-3})}) {
    const RenderTarget target = test::implicit_target("x+y+z-1e9", box);
    for (const auto& [w, h] : {std::pair<std::size_t, std::size_t>{200, 100}, {100, 200}, {64, 64}}) {
      const CameraSpec c = default_camera(target, static_cast<double>(w) / static_cast<double>(h));
      const Camera camera(c, w, h);
      for (int corner = 0; corner < 8; ++corner) {
        std::array<double, 3> q{};
        for (std::size_t i = 0; i < 3; ++i) q[i] = (corner >> i & 1) ? target.box_hi()[i] : target.box_lo()[i];
        std::array<double, 3> v{q[0] - c.eye[0], q[1] - c.eye[1], q[2] - c.eye[2]};
        const auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
          return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        };
        const double depth = dot(v, camera.forward());
        ASSERT_GT(depth, 0);
        // uv on the image plane (height 1 at focal distance 1), then pixels.
        const double px = dot(v, camera.right()) / depth * static_cast<double>(h) + static_cast<double>(w) / 2;
        const double py = static_cast<double>(h) / 2 - dot(v, camera.up()) / depth * static_cast<double>(h);
        EXPECT_GE(px, 0);
        EXPECT_LE(px, static_cast<double>(w));
        EXPECT_GE(py, 0);
        EXPECT_LE(py, static_cast<double>(h));
      }
    }
  }
}

TEST(DefaultCamera, LooksAtTheBoxFittedToAPatch) {
  // A patch without a box: the leaf's box is fitted to it, not the scene box [-2, 2]^3.
  SceneNode node;
  node.kind = NodeKind::parametric;
  node.leaf.coordinates = {"s+10", "t", "s*t"};
  node.leaf.domain = {{Rational(0), Rational(1)}, {Rational(0), Rational(1)}};
  const RenderTarget patch = RenderTarget::compile(node, SceneParams{});
  EXPECT_NEAR(patch.box_centre()[0], 10.5, 0.01);
  EXPECT_NEAR(patch.box_centre()[1], 0.5, 0.01);
  EXPECT_LT(patch.length_unit(), 0.3);
  EXPECT_EQ(default_camera(patch).target, patch.box_centre());
  // And the render sees it: a good share of the pixels hit.
  const RenderResult r = render_image(patch, settings_for(patch, 48, 48, 1));
  EXPECT_GT(r.stats.hits, r.stats.rays / 20);
}

TEST(RenderImage, APlaneCurveIsDrawnFlatByRenderCurve) {
  const RenderTarget circle = RenderTarget::compile(
      test::implicit_node("x^2+y^2-1"), SceneParams{SdfMode::fast, SceneBox::default_box(), "c", "scene", 2});
  ASSERT_EQ(circle.dimension(), 2);
  RenderParams s;
  s.width = 60;
  s.height = 40;
  const RenderResult drawn = render_image(circle, s);
  const RenderResult flat = render_curve(circle, 60, 40);
  EXPECT_TRUE(drawn.image == flat.image);
  EXPECT_EQ(drawn.stats.rays, 60u * 40u);
  EXPECT_EQ(drawn.stats.evaluations, 60u * 40u);
}

}  // namespace
}  // namespace implicitizer
