// Tests of lib/src/render/render_target.cpp: which scenes keep their algebraic
// surface, the length unit, float and double evaluation, and the two normals
// (analytic gradient, tetrahedron) against the sphere's exact normal.

#include "implicitizer/render/render_target.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "render/render_support.hpp"

namespace implicitizer {
namespace {

using test::implicit_target;

double angle_between(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double c = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::acos(std::min(1.0, std::max(-1.0, c)));
}

TEST(RenderTarget, KeepsTheAlgebraicSurfaceOfOnePolynomialLeaf) {
  const RenderTarget sphere = implicit_target("x^2+y^2+z^2-1");
  ASSERT_TRUE(sphere.algebraic().has_value());
  EXPECT_EQ(sphere.algebraic()->equation.total_degree(), 2);
  EXPECT_FALSE(sphere.algebraic()->trimmed);
  // The drawn region is the leaf box, [-2, 2]^3 for the default box.
  EXPECT_EQ(sphere.algebraic()->lo, (std::array<double, 3>{-2, -2, -2}));
  EXPECT_EQ(sphere.algebraic()->hi, (std::array<double, 3>{2, 2, 2}));

  SceneNode parametric;
  parametric.kind = NodeKind::parametric;
  parametric.leaf.coordinates = {"2*s/(s^2+t^2+1)", "2*t/(s^2+t^2+1)", "(s^2+t^2-1)/(s^2+t^2+1)"};
  const RenderTarget patch = RenderTarget::compile(parametric, SceneParams{});
  ASSERT_TRUE(patch.algebraic().has_value());
  EXPECT_EQ(patch.algebraic()->equation.total_degree(), 2);

  const RenderTarget scene = RenderTarget::compile(
      make_node(NodeKind::translate, {{"offset", Vec3<double>{0, 0, 1}}}, {test::implicit_node("x^2+y^2+z^2-1")}),
      SceneParams{});
  EXPECT_FALSE(scene.algebraic().has_value());
}

TEST(RenderTarget, LengthUnitIsHalfTheLargestHalfSide) {
  EXPECT_EQ(implicit_target("z").length_unit(), 1);
  const RenderTarget torus = implicit_target("(x^2+y^2+z^2+3)^2-16*(x^2+y^2)", test::axis_box({-3, -3, -1}, {3, 3, 1}));
  EXPECT_EQ(torus.length_unit(), 1.5);
  EXPECT_EQ(torus.box_centre(), (std::array<double, 3>{0, 0, 0}));
  const RenderTarget shifted = implicit_target("z", test::axis_box({0, 0, 0}, {2, 4, 1}));
  EXPECT_EQ(shifted.length_unit(), 1);
  EXPECT_EQ(shifted.box_centre(), (std::array<double, 3>{1, 2, 0.5}));
}

TEST(RenderTarget, FloatAndDoubleRunsAgree) {
  const RenderTarget single = implicit_target("x^2+y^2+z^2-1");
  const RenderTarget twice =
      implicit_target("x^2+y^2+z^2-1", SceneBox::default_box(), SdfMode::fast, EvaluationPrecision::double_run);
  for (const std::array<double, 3>& p : {std::array<double, 3>{0.5, 0.1, 0.2}, {1.5, -0.3, 0.7}, {0.1, 0.1, 1.1}}) {
    const double d = twice.evaluate(p);
    EXPECT_NEAR(single.evaluate(p), d, 1e-6);
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    EXPECT_NEAR(d, (r * r - 1) / (2 * r), 1e-12);  // F/|∇F| of the sphere
  }
}

TEST(RenderTarget, NormalsMatchTheSpheresNormal) {
  const RenderTarget algebraic = implicit_target("x^2+y^2+z^2-1");
  const RenderTarget primitive = RenderTarget::compile(make_node(NodeKind::sphere, {{"radius", 1.0}}), SceneParams{});
  for (const std::array<double, 3>& n : {std::array<double, 3>{0, 0, 1}, {0.6, 0.8, 0}, {-0.48, 0.6, -0.64}}) {
    std::uint64_t evaluations = 0;
    EXPECT_LT(angle_between(algebraic.normal(n, &evaluations), n), 1e-12);
    EXPECT_EQ(evaluations, 0u) << "the analytic gradient evaluates no scene";
    EXPECT_LT(angle_between(algebraic.tetrahedron_normal(n, &evaluations), n), 1e-3);
    EXPECT_EQ(evaluations, 4u);
    EXPECT_LT(angle_between(primitive.normal(n), n), 1e-3);
  }
}

}  // namespace
}  // namespace implicitizer
