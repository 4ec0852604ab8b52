// Smooth union, intersection and difference (Def. 1.18) against hand-derived values
// and against the definition's own formula, and the Lipschitz claim.

#include "implicitizer/scene/boolean_operators.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "scene/scene_support.hpp"

namespace implicitizer {
namespace {

// Def. 1.18 as printed: min(a, b) − max(k − |a − b|, 0)^n / (2n·k^(n−1)).
double definition_smin(double a, double b, double k, int n) {
  return std::min(a, b) - std::pow(std::max(k - std::fabs(a - b), 0.0), n) / (2 * n * std::pow(k, n - 1));
}

TEST(BooleanOperators, HandDerivedValues) {
  // a = 0.1, b = 0.3, k = 0.5: k − |a − b| = 0.3.
  //   n = 2: 0.3²/(4·0.5) = 0.045, smin = 0.055, smax = 0.345.
  //   n = 3: 0.3³/(6·0.25) = 0.018, smin = 0.082.
  EXPECT_NEAR(smooth_min(0.1, 0.3, 0.5, 2), 0.055, 1e-15);
  EXPECT_NEAR(smooth_max(0.1, 0.3, 0.5, 2), 0.345, 1e-15);
  EXPECT_NEAR(smooth_min(0.1, 0.3, 0.5, 3), 0.082, 1e-15);
  // n = 1: the blend is (k − |a − b|)/2 = 0.15: smin = −0.05 (a chamfer).
  EXPECT_NEAR(smooth_min(0.1, 0.3, 0.5, 1), -0.05, 1e-15);
  // Equal values: the blend is k/(2n), the largest.
  EXPECT_NEAR(smooth_min(1.0, 1.0, 0.4, 2), 1.0 - 0.1, 1e-15);
  // Farther apart than k: no blend at all, bit for bit.
  EXPECT_EQ(smooth_min(0.1, 0.7, 0.5, 2), 0.1);
  EXPECT_EQ(smooth_max(0.1, 0.7, 0.5, 2), 0.7);
  // Difference = smax(a, −b): a = 0.2, b = −0.1 (inside the subtrahend), k = 0.5:
  // max(0.2, 0.1) + (0.5 − 0.1)²/(4·0.5) = 0.2 + 0.08.
  EXPECT_NEAR(smooth_max(0.2, 0.1, 0.5, 2), 0.28, 1e-15);
}

TEST(BooleanOperators, AgreeWithTheDefinitionAndWithMinusSminOfMinus) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> value(-2, 2), blend(0.01, 1.5);
  for (int i = 0; i < 20000; ++i) {
    const double a = value(random), b = value(random), k = blend(random);
    const int n = 1 + i % 6;
    EXPECT_NEAR(smooth_min(a, b, k, n), definition_smin(a, b, k, n), 1e-14);
    EXPECT_NEAR(smooth_max(a, b, k, n), -definition_smin(-a, -b, k, n), 1e-14);
    // smax(a, b) = −smin(−a, −b) exactly, also in float (negation is exact).
    const float af = static_cast<float>(a), bf = static_cast<float>(b), kf = static_cast<float>(k);
    EXPECT_EQ(smooth_max(af, bf, kf, n), -smooth_min(-af, -bf, kf, n));
    // Never above min / below max: sphere tracing is not misled into overstepping.
    EXPECT_LE(smooth_min(a, b, k, n), std::min(a, b));
    EXPECT_GE(smooth_max(a, b, k, n), std::max(a, b));
  }
}

TEST(BooleanOperators, SmoothMinIsOneLipschitzInTheMaxNorm) {
  // |smin(a, b) − smin(a', b')| ≤ max(|a − a'|, |b − b'|): the step behind "smooth
  // operators keep 1-Lipschitz children 1-Lipschitz".
  std::mt19937 random(5);
  std::uniform_real_distribution<double> value(-1, 1), step(-0.3, 0.3), blend(0.05, 1);
  double worst = 0;
  for (int i = 0; i < 50000; ++i) {
    const double a = value(random), b = value(random), k = blend(random);
    const double da = step(random), db = step(random);
    const int n = 1 + i % 5;
    const double change = std::fabs(smooth_min(a + da, b + db, k, n) - smooth_min(a, b, k, n));
    worst = std::max(worst, change / std::max(std::fabs(da), std::fabs(db)));
  }
  EXPECT_LE(worst, 1 + 1e-9);
  EXPECT_GT(worst, 0.9);  // and the constant 1 is reached (the bound is not loose)
  std::cout << "smin: worst |change| / max(|da|, |db|) = " << worst << '\n';
}

TEST(BooleanOperators, GlslHasNoPowAndSpellsThePower) {
  const std::string text = smooth_min_glsl("s", 3);
  EXPECT_EQ(text.find("pow"), std::string::npos);
  EXPECT_NE(text.find("float s_smin3(float a, float b, float k)"), std::string::npos);
  EXPECT_NE(text.find("h * h * h * k / 6.00000000e+00"), std::string::npos) << text;
  EXPECT_NE(smooth_max_glsl("s", 2).find("return max(a, b) + w;"), std::string::npos);
}

TEST(BooleanOperators, SmoothUnionOfTwoSpheresInAScene) {
  // Spheres of radius 1 at x = ±1.2, k = 0.5, n = 2, at the origin: both values are
  // 0.2, the blend is k/(2n) = 0.125, so the value is 0.075; sharp union: 0.2.
  using testing::sphere;
  using testing::translate;
  SceneNode blend = make_node(NodeKind::smooth_union, {{"k", 0.5}},
                              {translate({1.2, 0, 0}, sphere(1)), translate({-1.2, 0, 0}, sphere(1))});
  const CompiledScene scene = testing::compile(blend);
  EXPECT_NEAR(scene.evaluate(Vec3<double>{0, 0, 0}), 0.075, 1e-15);
  EXPECT_NEAR(scene.evaluate(Vec3<float>{0, 0, 0}), 0.075f, 1e-7);
  // Far from the seam the blend vanishes: at (3, 0, 0), a = 0.8 and b = 3.2.
  EXPECT_DOUBLE_EQ(scene.evaluate(Vec3<double>{3, 0, 0}), 0.8);
  SceneNode sharp =
      make_node(NodeKind::csg_union, {}, {translate({1.2, 0, 0}, sphere(1)), translate({-1.2, 0, 0}, sphere(1))});
  EXPECT_NEAR(testing::compile(sharp).evaluate(Vec3<double>{0, 0, 0}), 0.2, 1e-15);

  // Smooth intersection of the same: max(0.2, 0.2) + 0.125; difference a − b at the
  // origin: smax(0.2, −0.2) with |a − (−b)| = 0.4 < k: 0.2 + 0.1²/(4·0.5) = 0.205.
  blend.kind = NodeKind::smooth_intersection;
  EXPECT_NEAR(testing::compile(blend).evaluate(Vec3<double>{0, 0, 0}), 0.325, 1e-15);
  blend.kind = NodeKind::smooth_difference;
  EXPECT_NEAR(testing::compile(blend).evaluate(Vec3<double>{0, 0, 0}), 0.205, 1e-15);
  // n = 3 in the scene: blend k/(2n) = 0.5/6 at equal values.
  blend.kind = NodeKind::smooth_union;
  blend.set("n", 3.0);
  EXPECT_NEAR(testing::compile(blend).evaluate(Vec3<double>{0, 0, 0}), 0.2 - 0.5 / 6, 1e-15);
}

}  // namespace
}  // namespace implicitizer
