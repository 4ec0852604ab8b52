#include "implicitizer/sdf/scene_frame.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "implicitizer/core/errors.hpp"
#include "sdf/sdf_support.hpp"

namespace implicitizer {
namespace {

using testing::box_of;
using testing::parse_xyz;

Rational largest_coefficient(const Polynomial& g) {
  Rational largest(0);
  for (std::size_t i = 0; i < g.num_terms(); ++i) {
    const Rational a = g.coefficient(i) < Rational(0) ? -g.coefficient(i) : g.coefficient(i);
    if (a > largest) largest = a;
  }
  return largest;
}

TEST(SceneFrame, DefaultBoxIsCentredWithScaleOneHalf) {
  const SceneFrame frame = make_scene_frame(SceneBox::default_box());
  for (const Rational& c : frame.centre) EXPECT_EQ(c, Rational(0));
  EXPECT_EQ(frame.scale, Rational(1, 2));
}

TEST(SceneFrame, UsesTheLargestHalfSideOnEveryAxis) {
  const SceneFrame frame = make_scene_frame(box_of("0", "-1", "10", "8", "1", "12"));
  EXPECT_EQ(frame.centre[0], Rational(4));
  EXPECT_EQ(frame.centre[1], Rational(0));
  EXPECT_EQ(frame.centre[2], Rational(11));
  EXPECT_EQ(frame.scale, Rational(1, 4));
}

TEST(SceneFrame, RefusesEmptyAndOutOfRangeBoxes) {
  for (const SceneBox& box : {box_of("1", "0", "0", "1", "1", "1"), box_of("0", "0", "0", "1", "-1", "1"),
                              box_of("0", "0", "0", "1e31", "1", "1"), box_of("0", "0", "0", "1e-31", "1e-31", "1e-31"),
                              box_of("1e31", "0", "0", "1e31+1", "1", "1")}) {
    try {
      (void)make_scene_frame(box);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.code(), "invalid_box");
      EXPECT_EQ(e.field(), "box");
    }
  }
}

TEST(SceneFrame, FramedPolynomialHasCoefficientsAtMostOneAndTheSameSign) {
  // 1e30 · ((x - 5e12)^2 + y^2 + z^2 - 1e24) in the box of that sphere.
  const Polynomial f = parse_xyz("10^30*((x-5*10^12)^2+y^2+z^2-10^24)");
  const SceneFrame frame = make_scene_frame(box_of("4e12", "-1e12", "-1e12", "6e12", "1e12", "1e12"));
  const Polynomial g = frame_polynomial(f, frame);
  EXPECT_EQ(largest_coefficient(g), Rational(1));
  // u = (p - c)·s: p = (5e12, 0, 0) is the centre (inside), p = (7e12, 0, 0) outside.
  const Rational inside[3] = {Rational(0), Rational(0), Rational(0)};
  const Rational outside[3] = {Rational(2), Rational(0), Rational(0)};
  EXPECT_LT(g.evaluate(inside), Rational(0));
  EXPECT_GT(g.evaluate(outside), Rational(0));
}

TEST(SceneFrame, RefusesConstants) {
  try {
    (void)frame_polynomial(parse_xyz("3"), make_scene_frame(SceneBox::default_box()));
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "constant_polynomial");
  }
}

// Why the frame exists: evaluating F itself in fp32 fails at the extremes the
// frame handles (fast_sdf_test.cpp shows the framed evaluation succeeding there).
TEST(SceneFrame, WithoutTheFrameFloatOverflowsOrLosesTheSign) {
  // Coefficients up to 1e30·2.5e25: the constant term alone overflows float.
  const Polynomial big = parse_xyz("10^30*((x-5*10^12)^2+y^2+z^2-10^24)");
  EXPECT_TRUE(std::isinf(testing::naive_float_value(big, 6.1e12f, 0, 0)) ||
              std::isnan(testing::naive_float_value(big, 6.1e12f, 0, 0)));
  // Coefficient 1, same sphere: no overflow, but x^2 - 1e13·x + 2.4e25 cancels
  // catastrophically: within 1e-5 of the radius (1e7) of the surface, the float
  // value has the wrong sign at some of these points.
  const Polynomial unit = parse_xyz("(x-5*10^12)^2+y^2+z^2-10^24");
  int wrong = 0;
  for (int k = -20; k <= 20; ++k) {
    const float x = 6e12f + static_cast<float>(k) * 5e5f;
    const double truth = testing::exact_estimate(unit, x, 0, 0);
    const float naive = testing::naive_float_value(unit, x, 0, 0);
    if (truth != 0 && (naive < 0) != (truth < 0)) ++wrong;
  }
  EXPECT_GT(wrong, 0);
  // 1e-30·(x^2+y^2+z^2-1e-12): every term underflows (1e-42 < 1.2e-38), so with
  // subnormals flushed the value is 0 well inside and well outside: no sign at all.
  const Polynomial tiny = parse_xyz("1e-30*(x^2+y^2+z^2-1e-12)");
  EXPECT_EQ(testing::naive_float_value(tiny, 0.5e-6f, 0, 0), 0.0f);
  EXPECT_EQ(testing::naive_float_value(tiny, 1.5e-6f, 0, 0), 0.0f);
}

}  // namespace
}  // namespace implicitizer
