// Translate, rotate, scale: the union of a sphere and a torus, moved, against the
// closed form of the moved shapes.

#include "implicitizer/scene/affine_transforms.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_support.hpp"

namespace implicitizer {
namespace {

using testing::rotate;
using testing::scale;
using testing::sphere;
using testing::torus;
using testing::translate;
using V = Vec3<double>;

double norm(const V& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

TEST(AffineTransforms, RotatePointIsTheInverseRotation) {
  // A quarter turn about z maps x to y; the preimage of (0, 1, 0) is (1, 0, 0).
  const V q = rotate_point(V{0, 1, 0}, V{0, 0, 1}, std::cos(M_PI / 2), std::sin(M_PI / 2));
  EXPECT_NEAR(q.x, 1, 1e-15);
  EXPECT_NEAR(q.y, 0, 1e-15);
  EXPECT_NEAR(q.z, 0, 1e-15);
  // Lengths are kept for any axis.
  const V axis = V{1, 2, -2} / 3.0;
  const V p{0.3, -1.7, 2.2};
  EXPECT_NEAR(norm(rotate_point(p, axis, std::cos(1.1), std::sin(1.1))), norm(p), 1e-14);
}

TEST(AffineTransforms, UnionOfMovedSphereAndTorus) {
  // Sphere of radius 0.5 moved to (1, 2, 3); torus (R = 1, r = 0.25) turned a quarter
  // about x (its ring goes from the xy plane into the xz plane), scaled by 2 (R = 2,
  // r = 0.5) and moved to (−1, 0, 0).
  const SceneNode root = make_node(NodeKind::csg_union, {},
                                   {translate({1, 2, 3}, sphere(0.5)),
                                    translate({-1, 0, 0}, scale(2, rotate({1, 0, 0}, M_PI / 2, torus(1, 0.25))))});
  const CompiledScene scene = testing::compile(root);
  EXPECT_EQ(scene.root_class(), NodeClass::lipschitz);
  for (const auto& pf : testing::random_points(2000, -4, 4, 21)) {
    const V p{pf.x, pf.y, pf.z};
    const double s = norm(p - V{1, 2, 3}) - 0.5;
    const V q = p - V{-1, 0, 0};
    const double t = std::hypot(std::hypot(q.x, q.z) - 2, q.y) - 0.5;
    EXPECT_NEAR(scene.evaluate(p), std::min(s, t), 1e-12) << p.x << " " << p.y << " " << p.z;
    // The float evaluator follows within float rounding of values of size ~10.
    EXPECT_NEAR(scene.evaluate(pf), std::min(s, t), 1e-5);
  }
}

TEST(AffineTransforms, ScaleMultipliesTheDistance) {
  const CompiledScene scene = testing::compile(scale(3, sphere(1)));
  EXPECT_DOUBLE_EQ(scene.evaluate(V{6, 0, 0}), 3.0);
  EXPECT_DOUBLE_EQ(scene.evaluate(V{0, 0, 0}), -3.0);
}

TEST(AffineTransforms, RotationAxisIsNormalisedAndAngleMayBeAUniform) {
  // Axis (0, 0, 5) means z; a torus turned by any angle about its own axis is itself.
  SceneNode r = rotate({0, 0, 5}, 0.7, torus(2, 0.5));
  r.name = "spin";
  r.uniforms = {"angle"};
  const CompiledScene scene = testing::compile(r);
  ASSERT_EQ(scene.uniforms().size(), 1u);
  EXPECT_EQ(scene.uniforms()[0].name, "spin_angle");
  const V p{1.3, -0.4, 0.2};
  EXPECT_NEAR(scene.evaluate(p), std::hypot(std::hypot(p.x, p.y) - 2, p.z) - 0.5, 1e-14);
  // About x instead, a quarter turn by uniform override equals the baked version.
  SceneNode about_x = rotate({2, 0, 0}, 0.0, torus(2, 0.5));
  about_x.name = "tilt";
  about_x.uniforms = {"angle"};
  const CompiledScene tilted = testing::compile(about_x);
  const double turned = tilted.evaluate(p, UniformValues{{M_PI / 2, 0, 0}});
  EXPECT_NEAR(turned, std::hypot(std::hypot(p.x, p.z) - 2, p.y) - 0.5, 1e-14);
  EXPECT_NEAR(tilted.evaluate(p), std::hypot(std::hypot(p.x, p.y) - 2, p.z) - 0.5, 1e-14);
}

}  // namespace
}  // namespace implicitizer
