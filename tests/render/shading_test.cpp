// Tests of lib/src/render/shading.cpp: soft shadows (lit, occluded), ambient
// occlusion (open, occluded), the shaded colour (lit side brighter, values in
// [0, 1]), and the two sides of a sheet (SURFER's colours by the sign of F).

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

// The saddle z = s^2 - t^2 over [-1, 1]^2: a patch, hence a sheet.
RenderTarget saddle_patch() {
  SceneNode node;
  node.kind = NodeKind::parametric;
  node.leaf.coordinates = {"s", "t", "s^2-t^2"};
  node.leaf.domain = {{Rational(-1), Rational(1)}, {Rational(-1), Rational(1)}};
  return RenderTarget::compile(node, SceneParams{});
}

// F at p, exactly as the target's equation says (the test's own reading of the sign).
double equation_at(const RenderTarget& target, const std::array<double, 3>& p) {
  const AlgebraicSurface& a = *target.algebraic();
  return a.program
      .evaluate((p[0] - a.centre[0]) * a.scale, (p[1] - a.centre[1]) * a.scale, (p[2] - a.centre[2]) * a.scale)
      .value;
}

TEST(SurfaceSide, TheSignOfFOnTheViewersSideNamesTheSide) {
  const RenderTarget sheet = saddle_patch();
  ASSERT_EQ(sheet.shape(), SdfShape::sheet);
  for (const std::array<double, 3>& p : {std::array<double, 3>{0, 0, 0}, {0.5, 0.2, 0.21}, {-0.3, 0.6, -0.27}}) {
    for (const std::array<double, 3>& d : {std::array<double, 3>{0, 0, -1}, {0.6, 0, 0.8}, {-0.48, 0.6, -0.64}}) {
      const std::array<double, 3> back{-d[0], -d[1], -d[2]};
      // The viewer sits behind p along the ray: F there says which side it sees.
      const double viewer = equation_at(sheet, {p[0] - 1e-3 * d[0], p[1] - 1e-3 * d[1], p[2] - 1e-3 * d[2]});
      const SurfaceSide seen = surface_side(sheet, p, d);
      EXPECT_EQ(seen, viewer > 0 ? SurfaceSide::front : SurfaceSide::back) << p[0] << " " << p[1] << " " << p[2];
      EXPECT_NE(surface_side(sheet, p, back), seen) << "the ray from the other side sees the other side";
    }
  }
  // A solid has one side: its outside.
  const RenderTarget sphere = test::implicit_target("x^2+y^2+z^2-1", SceneBox::default_box(), SdfMode::fast);
  EXPECT_EQ(sphere.shape(), SdfShape::solid);
  EXPECT_EQ(surface_side(sphere, {0, 0, 1}, {0, 0, -1}), SurfaceSide::front);
  EXPECT_EQ(surface_side(sphere, {0, 0, 1}, {0, 0, 1}), SurfaceSide::front);
}

TEST(ShadeHit, ASheetsTwoSidesHaveTheirOwnColoursAndBothAreLit) {
  const RenderTarget sheet = saddle_patch();
  ShadingParams params;
  params.lights = {DirectionalLight{{0, 0, 1}, {1, 1, 1}, 1.5}};
  params.shadows = false;
  params.occlusion_samples = 0;
  params.gamma = 1;
  params.ambient = {0, 0, 0};
  params.specular = {0, 0, 0};
  // The saddle's centre, from above and from below, with a light on each side: the
  // normal faces the viewer, so each side is lit by the light on its side.
  const Ray down{{0, 0, 3}, {0, 0, -1}};
  const Ray up{{0, 0, -3}, {0, 0, 1}};
  const auto top = shade_hit(sheet, down, 3, params);
  params.lights = {DirectionalLight{{0, 0, -1}, {1, 1, 1}, 1.5}};
  const auto bottom = shade_hit(sheet, up, 3, params);
  const bool top_is_front = surface_side(sheet, {0, 0, 0}, down.direction) == SurfaceSide::front;
  const auto& top_albedo = top_is_front ? params.albedo : params.back_albedo;
  const auto& bottom_albedo = top_is_front ? params.back_albedo : params.albedo;
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(top[c], top_albedo[c], 1e-9);  // n·l = 1: the albedo itself
    EXPECT_NEAR(bottom[c], bottom_albedo[c], 1e-9);
  }
  EXPECT_NE(top, bottom);
}

}  // namespace
}  // namespace implicitizer
