// Tests of lib/src/render/shading.cpp: soft shadows (lit, occluded), ambient
// occlusion (open, occluded), and the shaded colour (lit side brighter, values in
// [0, 1]).

#include "implicitizer/render/shading.hpp"

#include <gtest/gtest.h>

#include "render/render_support.hpp"

namespace implicitizer {
namespace {

RenderTarget unit_sphere() {
  return RenderTarget::compile(make_node(NodeKind::sphere, {{"radius", 1.0}}), SceneParams{});
}

TEST(SoftShadow, NothingInTheWayIsFullyLit) {
  const RenderTarget target = unit_sphere();
  // On top of the sphere, light straight up: f(t) = t along the march, k·f/t ≥ 1.
  EXPECT_DOUBLE_EQ(soft_shadow(target, {0, 1, 0}, {0, 1, 0}, 1.5, ShadingParams{}), 1.0);
}

TEST(SoftShadow, TheSphereShadowsWhatIsBelowIt) {
  const RenderTarget target = unit_sphere();
  std::uint64_t evaluations = 0;
  const double shadow = soft_shadow(target, {0, -1.5, 0}, {0, 1, 0}, 1.5, ShadingParams{}, &evaluations);
  EXPECT_LT(shadow, 0.01);
  EXPECT_GT(evaluations, 0u);
  EXPECT_LE(evaluations, ShadingParams{}.shadow_max_steps);
  // Off to the side the penumbra is partial, and farther off it is lit.
  const double edge = soft_shadow(target, {1.1, -1.5, 0}, {0, 1, 0}, 1.5, ShadingParams{});
  const double off = soft_shadow(target, {2.5, -1.5, 0}, {0, 1, 0}, 1.5, ShadingParams{});
  EXPECT_GT(edge, shadow);
  EXPECT_LT(edge, 1.0);
  EXPECT_GT(off, edge);
}

TEST(AmbientOcclusion, OpenSurfaceIsUnoccludedAndACreviceIsNot) {
  const RenderTarget sphere = unit_sphere();
  // An exact distance with nothing near: f(p + d·n) = d, so nothing is occluded.
  EXPECT_DOUBLE_EQ(ambient_occlusion(sphere, {0, 0, 1}, {0, 0, 1}, 4), 1.0);
  EXPECT_DOUBLE_EQ(ambient_occlusion(sphere, {0, 0, 1}, {0, 0, 1}, 0), 1.0);
  // Between two spheres the samples along the normal come close to the other one.
  const RenderTarget pair =
      RenderTarget::compile(make_node(NodeKind::csg_union, {},
                                      {make_node(NodeKind::sphere, {{"radius", 1.0}}),
                                       make_node(NodeKind::translate, {{"offset", Vec3<double>{0, 0, 2.6}}},
                                                 {make_node(NodeKind::sphere, {{"radius", 1.0}})})}),
                            SceneParams{});
  std::uint64_t evaluations = 0;
  const double ao = ambient_occlusion(pair, {0, 0, 1}, {0, 0, 1}, 4, &evaluations);
  EXPECT_LT(ao, 0.9);
  EXPECT_GE(ao, 0.0);
  EXPECT_EQ(evaluations, 4u);
}

TEST(ShadeHit, LitSideIsBrighterAndColoursAreDisplayValues) {
  const RenderTarget target = unit_sphere();
  ShadingParams params;
  params.lights = {DirectionalLight{{0, 1, 0}, {1, 1, 1}, 1.5}};
  // Looking down at the top (lit) and up at the bottom (unlit) of the sphere.
  const Ray down{{0, 3, 0.001}, {0, -1, 0}};
  const Ray up{{0, -3, 0.001}, {0, 1, 0}};
  const auto top = shade_hit(target, down, 2, params);
  const auto bottom = shade_hit(target, up, 2, params);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_GT(top[c], bottom[c]);
    EXPECT_GE(bottom[c], 0);
    EXPECT_LE(top[c], 1);
  }
}

}  // namespace
}  // namespace implicitizer
