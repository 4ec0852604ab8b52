// Implicit and parametric leaves: the same surface both ways, and trimming of a
// parametric patch to the box of its domain (C++ and GLSL on llvmpipe).

#include "implicitizer/scene/polynomial_leaf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "implicitizer/core/errors.hpp"
#include "scene/scene_support.hpp"

namespace implicitizer {
namespace {

using testing::implicit;
using testing::parametric;
using V = Vec3<double>;

std::vector<std::pair<Rational, Rational>> unit_square() {
  return {{Rational(0), Rational(1)}, {Rational(0), Rational(1)}};
}

TEST(PolynomialLeaf, ImplicitSphereIsItsDistanceEstimate) {
  const CompiledScene scene = testing::compile(implicit("x^2+y^2+z^2-1"));
  EXPECT_EQ(scene.root_class(), NodeClass::estimate);
  EXPECT_NEAR(scene.evaluate(V{0, 0, 1}), 0, 1e-15);
  // F/|∇F| = (|p|² − 1)/(2|p|): at |p| = 1.5, 1.25/3.
  EXPECT_NEAR(scene.evaluate(V{1.5, 0, 0}), 1.25 / 3, 1e-12);
  EXPECT_LT(scene.evaluate(V{0.2, 0.1, 0}), 0);
}

TEST(PolynomialLeaf, PolynomialPatchWithoutDomainIsTheUnitSquarePatch) {
  // x = s, y = t, z = s·t: no domain means [0, 1]² (a polynomial map is unbounded on
  // the plane), so points of z = x·y far outside [0, 1]² are not hits.
  const CompiledScene scene = testing::compile(parametric("s", "t", "s*t"));
  ASSERT_TRUE(scene.leaves().front().trimmed());
  EXPECT_NEAR(scene.evaluate(V{0.5, 0.5, 0.25}), 0, 1e-12);
  EXPECT_GT(scene.evaluate(V{1.5, -1, -1.5}), 0.5);
  // The frame box is fitted to the patch: [0, 1]³ padded by 1e-3.
  const SceneBox& box = scene.leaves().front().frame_box();
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(box.lo[i], Rational(-1, 1000));
    EXPECT_EQ(box.hi[i], Rational(1001, 1000));
  }
}

TEST(PolynomialLeaf, ClosedRationalSurfaceWithoutDomainIsWhole) {
  // The stereographic sphere is bounded on the whole parameter plane: its default
  // domain is the plane, nothing is trimmed, and the south pole (s = ∞) is a hit.
  const CompiledScene scene =
      testing::compile(parametric("2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(1-s^2-t^2)/(1+s^2+t^2)"));
  EXPECT_FALSE(scene.leaves().front().trimmed());
  EXPECT_NEAR(scene.evaluate(V{0, 0, -1}), 0, 1e-9);
  EXPECT_NEAR(scene.evaluate(V{-1, 0, 0}), 0, 1e-9);
  const SceneBox& box = scene.leaves().front().frame_box();
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_LE(box.lo[i], Rational(-1));
    EXPECT_GE(box.hi[i], Rational(1));
    EXPECT_LT(box.hi[i], Rational(102, 100));
  }
}

TEST(PolynomialLeaf, PatchIsTrimmedToTheBoxOfItsDomain) {
  // The saddle patch x = s, y = t, z = s·t over [0, 1]²: its box is exactly [0, 1]³.
  const CompiledScene scene = testing::compile(parametric("s", "t", "s*t", unit_square()));
  const CompiledScene untrimmed = testing::compile(implicit("z-x*y"));
  // On the patch: 0 (up to the estimate's rounding).
  for (const V& p : {V{0.5, 0.5, 0.25}, V{0.2, 0.9, 0.18}, V{1, 1, 1}, V{0, 0, 0}}) {
    EXPECT_NEAR(scene.evaluate(p), 0, 1e-12);
  }
  // On the algebraic surface but outside the box: the untrimmed leaf says 0, the
  // trimmed one at least the distance to the box.
  for (const V& p : {V{-0.5, 0.5, -0.25}, V{1.5, 1.2, 1.8}, V{-1, -1, 1}, V{0.5, -0.5, -0.25}}) {
    EXPECT_NEAR(untrimmed.evaluate(p), 0, 1e-12);
    const double box_distance =
        std::hypot(std::max({-p.x, p.x - 1, 0.0}), std::max({-p.y, p.y - 1, 0.0}), std::max({-p.z, p.z - 1, 0.0}));
    EXPECT_GT(box_distance, 0.1);
    EXPECT_GE(scene.evaluate(p), box_distance * (1 - 1e-12));
    EXPECT_GT(scene.evaluate(Vec3<float>{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)}),
              0.1f);
  }
  // A sheet: never negative.
  for (const auto& p : testing::random_points(2000, -2, 2, 5)) EXPECT_GE(scene.evaluate(p), 0.0f);
}

TEST(PolynomialLeaf, UnitSpherePatchIsTrimmed) {
  // Stereographic patch over [0, 1]²: the part of the unit sphere with x, y ≥ 0 and
  // z ≥ −1/3 (s = t = 1 gives (2/3, 2/3, −1/3)), inside the box [0, 1]×[0, 1]×[−1/3, 1]
  // (or a slightly larger one: bound_patch only promises containment).
  const CompiledScene scene =
      testing::compile(parametric("2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(1-s^2-t^2)/(1+s^2+t^2)", unit_square()));
  EXPECT_NEAR(scene.evaluate(V{0, 0, 1}), 0, 1e-9);                     // s = t = 0
  EXPECT_NEAR(scene.evaluate(V{2.0 / 3, 2.0 / 3, -1.0 / 3}), 0, 1e-9);  // s = t = 1
  // Points of the sphere far from the patch: the south pole, and (−1, 0, 0).
  EXPECT_GT(scene.evaluate(V{0, 0, -1}), 0.5);
  EXPECT_GT(scene.evaluate(V{-1, 0, 0}), 0.5);
  EXPECT_GT(scene.evaluate(Vec3<float>{0, 0, -1}), 0.5f);
  EXPECT_GT(scene.evaluate(Vec3<float>{-1, 0, 0}), 0.5f);
  // Their untrimmed values are 0.
  const CompiledScene whole = testing::compile(implicit("x^2+y^2+z^2-1"));
  EXPECT_NEAR(whole.evaluate(V{0, 0, -1}), 0, 1e-12);
}

TEST(PolynomialLeaf, TrimmedPatchesOnLlvmpipe) {
  const std::string reason = testing::GlesRunner::instance().unavailable();
  if (!reason.empty()) GTEST_SKIP() << "no headless llvmpipe: " << reason;
  struct Case {
    const char* label;
    SceneNode node;
    std::vector<Vec3<float>> outside;  // on the algebraic surface, outside the box
  };
  const std::vector<Case> cases = {
      {"saddle", parametric("s", "t", "s*t", unit_square()), {{-0.5f, 0.5f, -0.25f}, {1.5f, 1.2f, 1.8f}, {-1, -1, 1}}},
      {"sphere patch",
       parametric("2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(1-s^2-t^2)/(1+s^2+t^2)", unit_square()),
       {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}}},
  };
  for (const Case& c : cases) {
    const CompiledScene scene = testing::compile(c.node);
    EXPECT_EQ(testing::glslang_both(scene), "") << c.label;
    std::vector<Vec3<float>> points = testing::random_points(300, -1.5f, 1.5f, 9);
    points.insert(points.end(), c.outside.begin(), c.outside.end());
    const testing::GpuComparison r = testing::compare_on_gpu(scene, points, {});
    ASSERT_EQ(r.error, "") << c.label;
    for (std::size_t i = points.size() - c.outside.size(); i < points.size(); ++i) {
      EXPECT_GT(r.gpu[i], 0.5f) << c.label << " point " << i;
      EXPECT_GT(r.cpu[i], 0.5f) << c.label << " point " << i;
    }
    for (float v : r.gpu) EXPECT_GE(v, 0.0f) << c.label;
    // Polynomial leaves: Horner in u-space may fuse multiply-adds on the GPU; the
    // values agree to a few ulps of the scale (see docs/sdf.md, "Scenes").
    EXPECT_LE(r.worst_scaled, 64) << c.label;
    std::cout << c.label << ": " << r.points << " points, " << r.identical << " bit-identical, worst " << r.worst_scaled
              << " x 2^-24 x scale\n";
  }
}

TEST(PolynomialLeaf, ErrorsNameTheLeafField) {
  const auto code_and_field = [](const SceneNode& node) -> std::pair<std::string, std::string> {
    try {
      testing::compile(node);
    } catch (const InputError& e) {
      return {e.code(), e.field()};
    }
    return {"", ""};
  };
  EXPECT_EQ(code_and_field(implicit("x^2+")).second, "scene.equation");
  EXPECT_EQ(code_and_field(implicit("x^2+w")),
            std::make_pair(std::string("unknown_variable"), std::string("scene.equation")));
  EXPECT_EQ(code_and_field(implicit("3")),
            std::make_pair(std::string("constant_polynomial"), std::string("scene.equation")));
  EXPECT_EQ(code_and_field(parametric("s", "t", "s*t", {{Rational(0), Rational(1)}})).first, "invalid_domain");
  EXPECT_EQ(code_and_field(parametric("s", "t", "s*t", {{Rational(0), Rational(1)}})).second, "scene.domain");
  // The image is a curve: no single equation.
  EXPECT_EQ(code_and_field(parametric("s", "s^2", "s^3")).first, "no_single_equation");
  // A patch whose box leaves float's range (found by fuzz/request_fuzzer: rounding the
  // box to float met infinity and GMP raised SIGFPE).
  EXPECT_EQ(code_and_field(parametric("s", "t", "888888888888888888888888888888888888888888888888888888*s*t",
                                      {{Rational(0), Rational(1)}, {Rational(0), Rational(1)}})),
            std::make_pair(std::string("invalid_domain"), std::string("scene.domain")));
  // Empty and reversed intervals.
  for (const auto& bad : std::vector<std::vector<std::pair<Rational, Rational>>>{
           {{Rational(1), Rational(1)}, {Rational(0), Rational(1)}},
           {{Rational(0), Rational(1)}, {Rational(2), Rational(-1)}}}) {
    EXPECT_EQ(code_and_field(parametric("s", "t", "s*t", bad)),
              std::make_pair(std::string("invalid_domain"), std::string("scene.domain")));
  }
  // A denominator vanishing in the domain.
  EXPECT_EQ(
      code_and_field(parametric("1/s", "t", "s*t", {{Rational(-1), Rational(1)}, {Rational(0), Rational(1)}})).first,
      "unbounded_patch");
}

}  // namespace
}  // namespace implicitizer
