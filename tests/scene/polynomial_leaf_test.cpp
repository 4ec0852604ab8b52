// Implicit and parametric leaves: the same surface both ways, and trimming of a
// parametric patch to the box of its domain (C++ and GLSL on llvmpipe).

#include "implicitizer/scene/polynomial_leaf.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

#include "approximation/polytope_support.hpp"
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

SceneNode with_shape(SceneNode node, SdfShape shape) {
  node.leaf.shape = shape;
  return node;
}

CompiledScene compile_curve(const SceneNode& node, SdfMode mode = SdfMode::fast) {
  SceneParams options;
  options.mode = mode;
  options.name = "c";
  options.dimension = 2;
  return compile_scene(node, options);
}

SceneNode parametric_curve(const std::string& x, const std::string& y,
                           std::vector<std::pair<Rational, Rational>> domain = {}) {
  return parametric(x, y, "", std::move(domain));
}

// The code and field of the InputError compiling `node` in `dimension` throws ("" when none).
std::pair<std::string, std::string> compile_error(const SceneNode& node, int dimension = 3) {
  try {
    SceneParams options;
    options.dimension = dimension;
    compile_scene(node, options);
  } catch (const InputError& e) {
    return {e.code(), e.field()};
  }
  return {"", ""};
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
  EXPECT_EQ(scene.leaves().front().shape(), SdfShape::sheet);
  EXPECT_NEAR(scene.evaluate(V{0.5, 0.5, 0.25}), 0, 1e-12);
  EXPECT_GT(scene.evaluate(V{1.5, -1, -1.5}), 0.5);
  // The frame box is fitted to the patch: [0, 1]³ padded by 1e-4.
  const SceneBox& box = scene.leaves().front().frame_box();
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(box.lo[i], Rational(-1, 10000));
    EXPECT_EQ(box.hi[i], Rational(10001, 10000));
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

TEST(PolynomialLeaf, PatchAskedForASolidIsTheUntrimmedSolidInItsBox) {
  // Shape solid: the solid z − x·y <= 0 in the fitted box, not trimmed, the two sides
  // of the surface with opposite signs.
  const CompiledScene solid = testing::compile(with_shape(parametric("s", "t", "s*t"), SdfShape::solid));
  EXPECT_EQ(solid.leaves().front().shape(), SdfShape::solid);
  EXPECT_FALSE(solid.leaves().front().trimmed());
  EXPECT_NE(solid.evaluate(V{0.5, 0.5, 0.5}) < 0, solid.evaluate(V{0.5, 0.5, 0.0}) < 0);
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

// Shape auto (enclosure.hpp) on the box the value is clipped to: a sphere inside its
// box is a solid, a plane and a saddle are sheets, 1 − |p|² is the solid of −F (its
// inside is the ball, where F > 0). Shapes asked for are kept, with reason "asked".
TEST(PolynomialLeaf, ShapeAutoIsDecidedOnTheBox) {
  struct Case {
    const char* equation;
    SdfShape shape;
    bool negated;
  };
  for (const Case& c : {Case{"x^2+y^2+z^2-1", SdfShape::solid, false}, Case{"x+y+z-1/2", SdfShape::sheet, false},
                        Case{"z-x*y", SdfShape::sheet, false}, Case{"1-x^2-y^2-z^2", SdfShape::solid, true}}) {
    for (const SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      const CompiledScene scene = testing::compile(implicit(c.equation), mode);
      const PolynomialLeaf& leaf = scene.leaves().front();
      EXPECT_EQ(leaf.shape(), c.shape) << c.equation << ": " << leaf.shape_reason();
      EXPECT_EQ(leaf.negated(), c.negated) << c.equation;
      EXPECT_EQ(leaf.equation(), testing::parse_xyz(c.equation)) << c.equation;
      // A solid is negative at the centre of its ball; a sheet never is.
      const float centre = scene.evaluate(Vec3<float>{0.01f, 0.02f, 0.03f});
      if (c.shape == SdfShape::solid) {
        EXPECT_LT(centre, 0.0f) << c.equation;
      } else {
        for (const auto& p : testing::random_points(500, -3, 3, 11)) EXPECT_GE(scene.evaluate(p), 0.0f) << c.equation;
      }
    }
  }
  const CompiledScene sheet = testing::compile(with_shape(implicit("x^2+y^2+z^2-1"), SdfShape::sheet));
  EXPECT_EQ(sheet.leaves().front().shape(), SdfShape::sheet);
  EXPECT_EQ(sheet.leaves().front().shape_reason(), "asked");
  EXPECT_GT(sheet.evaluate(V{0.5, 0, 0}), 0.3);  // |F/|∇F|| = 0.75/1 at |p| = 1/2
  EXPECT_NEAR(sheet.evaluate(V{0, 1, 0}), 0, 1e-15);
  // A solid asked of a patch is the untrimmed solid in the patch's box.
  const CompiledScene patch = testing::compile(with_shape(parametric("s", "t", "s*t", unit_square()), SdfShape::solid));
  EXPECT_FALSE(patch.leaves().front().trimmed());
  EXPECT_LT(std::min(patch.evaluate(V{0.5, 0.5, 0.1}), patch.evaluate(V{0.5, 0.5, 0.4})), 0);
  // Under auto a patch with a domain is the trimmed sheet.
  const CompiledScene trimmed = testing::compile(parametric("s", "t", "s*t", unit_square()));
  EXPECT_TRUE(trimmed.leaves().front().trimmed());
  EXPECT_EQ(trimmed.leaves().front().shape(), SdfShape::sheet);
}

// Curves: dimension 2. The circle encloses a disc inside the default square (solid),
// the parabola leaves it (sheet); the value at (x, y) is the planar one.
TEST(PolynomialLeaf, PlaneCurvesAreEvaluatedAtZZero) {
  for (const SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
    const CompiledScene circle = compile_curve(implicit("x^2+y^2-1"), mode);
    EXPECT_EQ(circle.dimension(), 2);
    EXPECT_EQ(circle.leaves().front().shape(), SdfShape::solid) << circle.leaves().front().shape_reason();
    EXPECT_LT(circle.evaluate(V{0.1, 0.2, 0}), 0);
    EXPECT_GT(circle.evaluate(V{1.5, 0, 0}), 0);
    EXPECT_NEAR(circle.evaluate(V{0.6, 0.8, 0}), 0, 1e-12);
    // The frame is the square's: z in [−2, 2].
    EXPECT_EQ(circle.leaves().front().frame_box().lo[2], Rational(-2));
    const CompiledScene parabola = compile_curve(implicit("y-x^2"), mode);
    EXPECT_EQ(parabola.leaves().front().shape(), SdfShape::sheet);
    EXPECT_GT(parabola.evaluate(V{0, 1, 0}), 0);
    EXPECT_GT(parabola.evaluate(V{0, -1, 0}), 0);
    EXPECT_NEAR(parabola.evaluate(V{1, 1, 0}), 0, 1e-12);
  }
  // Fast mode on the circle: (r² − 1)/(2r), the planar estimate.
  EXPECT_NEAR(compile_curve(implicit("x^2+y^2-1")).evaluate(V{1.5, 0, 0}), 1.25 / 3, 1e-12);
  // The rational circle without a domain is the whole circle: a solid; the arc of
  // t in [0, 1] (from (1, 0) to (0, 1)) is a trimmed sheet, > 0 at (−1, 0).
  const CompiledScene whole = compile_curve(parametric_curve("(1-t^2)/(1+t^2)", "2*t/(1+t^2)"));
  EXPECT_EQ(whole.leaves().front().shape(), SdfShape::solid);
  EXPECT_LT(whole.evaluate(V{0, 0, 0}), 0);
  const CompiledScene arc =
      compile_curve(parametric_curve("(1-t^2)/(1+t^2)", "2*t/(1+t^2)", {{Rational(0), Rational(1)}}));
  EXPECT_EQ(arc.leaves().front().shape(), SdfShape::sheet);
  EXPECT_NEAR(arc.evaluate(V{1, 0, 0}), 0, 1e-9);
  EXPECT_NEAR(arc.evaluate(V{0.6, 0.8, 0}), 0, 1e-9);
  EXPECT_GT(arc.evaluate(V{-1, 0, 0}), 0.9);
  EXPECT_GT(arc.evaluate(V{0, -1, 0}), 0.9);
}

TEST(PolynomialLeaf, CurveGlslTakesAVec2AndRunsOnLlvmpipe) {
  const std::vector<std::pair<const char*, SceneNode>> curves = {
      {"circle", implicit("x^2+y^2-1")},
      {"parabola", implicit("y-x^2")},
      {"arc", parametric_curve("(1-t^2)/(1+t^2)", "2*t/(1+t^2)", {{Rational(0), Rational(1)}})}};
  for (const auto& [label, node] : curves) {
    for (const SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      const CompiledScene scene = compile_curve(node, mode);
      EXPECT_NE(scene.to_glsl().find("float c_sdf(vec2 p) {\n  return c_space(vec3(p, 0.0));\n}"), std::string::npos)
          << scene.to_glsl();
      EXPECT_EQ(testing::glslang_both(scene), "") << label;
      const std::string reason = testing::GlesRunner::instance().unavailable();
      if (!reason.empty()) continue;
      std::vector<Vec3<float>> points = testing::random_points(300, -2.5f, 2.5f, 3);
      for (auto& p : points) p.z = 0;
      const testing::GpuComparison r = testing::compare_on_gpu(scene, points, {});
      ASSERT_EQ(r.error, "") << label;
      EXPECT_LE(r.worst_scaled, 64) << label;
      std::cout << label << (mode == SdfMode::safe ? " (safe)" : "") << ": " << r.points << " points, " << r.identical
                << " bit-identical, worst " << r.worst_scaled << " x 2^-24 x scale\n";
    }
  }
}

TEST(PolynomialLeaf, CurveErrorsNameTheField) {
  const auto code_and_field = compile_error;
  EXPECT_EQ(code_and_field(implicit("x^2+y^2+z^2-1"), 2),
            std::make_pair(std::string("unknown_variable"), std::string("scene.equation")));
  EXPECT_EQ(code_and_field(parametric("s", "s^2", "s^3"), 2),
            std::make_pair(std::string("invalid_value"), std::string("scene.z")));
  EXPECT_EQ(code_and_field(implicit("x^2+y^2-1"), 4),
            std::make_pair(std::string("invalid_value"), std::string("dimension")));
  // A parametric curve whose image is a point has no equation.
  EXPECT_EQ(code_and_field(parametric_curve("1", "2"), 2).first, "no_single_equation");
}

// ---------------------------------------------------------------------------------
// Approximated patches (a tolerance): the union of the pieces' trimmed sheets.

// tp_22 of ../shared/bench/surfaces_hard.json (a biquadratic patch, exact degree 8).
SceneNode tp22(std::optional<double> tolerance) {
  SceneNode node = parametric("3-t-2*t^2-3*s-5*s*t+5*s^2-s^2*t+4*s^2*t^2", "-3+5*t-t^2-s+5*s*t-4*s*t^2+2*s^2+5*s^2*t",
                              "-3-3*t-4*t^2-2*s+5*s*t-3*s*t^2+3*s^2+5*s^2*t+2*s^2*t^2", unit_square());
  node.leaf.tolerance = tolerance;
  return node;
}

// tp_33 of ../shared/bench/surfaces_hard.json (a bicubic patch, exact degree 18): within
// 1e-2 a few pieces of degree <= 6 are far shorter GLSL than its exact equation.
SceneNode tp33(std::optional<double> tolerance) {
  SceneNode node = parametric(
      "3+2*t^2+t^3-3*s-5*s*t+s^2-2*s^2*t-3*s^2*t^2-3*s^2*t^3+4*s^3-3*s^3*t+3*s^3*t^2-s^3*t^3",
      "3+t-2*t^2-4*t^3-3*s+s*t+5*s*t^2+2*s*t^3+4*s^2-s^2*t-5*s^2*t^2+s^2*t^3-5*s^3-3*s^3*t-5*s^3*t^2+3*s^3*t^3",
      "-2-2*t-4*t^2-5*t^3+3*s-3*s*t-4*s*t^2-4*s*t^3-s^2+3*s^2*t-3*s^2*t^2-2*s^2*t^3+3*s^3+5*s^3*t-2*s^3*t^2+2*s^3*t^3",
      unit_square());
  node.leaf.tolerance = tolerance;
  return node;
}

std::size_t count_lines(const std::string& text) { return std::size_t(std::count(text.begin(), text.end(), '\n')); }

V tp33_point(double s, double t) {
  const std::array<double, 3> x = testing::tp33_point(s, t);
  return {x[0], x[1], x[2]};
}

TEST(PolynomialLeaf, ApproximatedPatchIsWithinItsBoundOnThePatch) {
  // Safe mode: each piece's value is a lower bound of the distance to its surface,
  // which is within patch_to_surface·diag of every point of its part of the patch.
  const double eps = 1e-2;
  const CompiledScene scene = testing::compile(tp33(eps), SdfMode::safe);
  const PolynomialLeaf& leaf = scene.leaves().front();
  const PatchApproximation* a = leaf.approximation();
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(leaf.piece_count(), a->pieces.size());
  EXPECT_GT(leaf.piece_count(), 1u);
  EXPECT_TRUE(leaf.trimmed());
  EXPECT_EQ(leaf.shape(), SdfShape::sheet);
  EXPECT_EQ(leaf.tolerance(), eps);
  EXPECT_LE(a->patch_to_surface, eps);
  EXPECT_LE(a->surface_to_patch, eps);
  EXPECT_GT(a->diagonal, 0);
  double worst = 0;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) worst = std::max(worst, scene.evaluate(tp33_point(i / 40.0, j / 40.0)));
  }
  EXPECT_LE(worst, a->patch_to_surface * a->diagonal * (1 + 1e-6) + 1e-9 * a->diagonal);
  // Outside the patch's box widened by 0.2·diag every piece's cover is farther than that.
  const SceneBox& box = leaf.frame_box();
  const double far = 0.2 * a->diagonal;
  const V lo{to_mpq(box.lo[0]).get_d() - far, to_mpq(box.lo[1]).get_d() - far, to_mpq(box.lo[2]).get_d() - far};
  const V hi{to_mpq(box.hi[0]).get_d() + far, to_mpq(box.hi[1]).get_d() + far, to_mpq(box.hi[2]).get_d() + far};
  for (const V& p : {lo, hi, V{lo.x, hi.y, lo.z}, V{hi.x, lo.y, hi.z}})
    EXPECT_GT(scene.evaluate(p), 0.19 * a->diagonal);
}

TEST(PolynomialLeaf, ApproximatedPatchGlslRunsOnLlvmpipe) {
  const CompiledScene scene = testing::compile(tp33(1e-2));
  const PolynomialLeaf& leaf = scene.leaves().front();
  ASSERT_NE(leaf.approximation(), nullptr);
  EXPECT_EQ(testing::glslang_both(scene), "");
  // One distance and one trimming per piece, and their min; tp_33's pieces are nearly
  // flat, so some are trimmed to their polytope (ten planes) rather than a box cover.
  const std::string glsl = scene.to_glsl();
  std::size_t polytopes = 0;
  for (std::size_t k = 0; k < leaf.piece_count(); ++k) polytopes += leaf.polytope(k) != nullptr ? 1 : 0;
  EXPECT_GT(polytopes, 0u);
  EXPECT_NE(glsl.find("a polytope of "), std::string::npos);
  EXPECT_EQ(leaf.trimming().method.rfind("polytopes", 0), 0u);
  if (leaf.piece_count() > 1) {
    const std::string last = "s_leaf0_piece" + std::to_string(leaf.piece_count() - 1) + "_cover(";
    EXPECT_NE(glsl.find(last), std::string::npos);
    EXPECT_NE(glsl.find("min("), std::string::npos);
  }
  const std::string reason = testing::GlesRunner::instance().unavailable();
  if (!reason.empty()) GTEST_SKIP() << "no headless llvmpipe: " << reason;
  std::vector<Vec3<float>> points;
  for (int i = 0; i <= 12; ++i) {
    for (int j = 0; j <= 12; ++j) {
      const V p = tp33_point(i / 12.0, j / 12.0);
      points.push_back({static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
    }
  }
  const std::vector<Vec3<float>> around = testing::random_points(200, -4.0f, 6.0f, 5);
  points.insert(points.end(), around.begin(), around.end());
  const testing::GpuComparison r = testing::compare_on_gpu(scene, points, {});
  ASSERT_EQ(r.error, "");
  for (float v : r.gpu) EXPECT_GE(v, 0.0f);
  EXPECT_LE(r.worst_scaled, 64);
  std::cout << "tp_33 at 1e-2: " << leaf.piece_count() << " pieces (" << polytopes << " polytopes), " << r.points
            << " points, " << r.identical << " bit-identical, worst " << r.worst_scaled << " x 2^-24 x scale\n";
}

// A tolerance the exact equation answers more cheaply: tp_22's degree-8 equation is
// shorter GLSL than any approximation within 1e-2, so the leaf is exact and says why;
// and no approximation meets 1e-300, which the exact equation does.
TEST(PolynomialLeaf, ToleranceKeepsTheExactEquationWhenItsGlslIsShorter) {
  const CompiledScene scene = testing::compile(tp22(1e-2));
  const PolynomialLeaf& leaf = scene.leaves().front();
  EXPECT_EQ(leaf.approximation(), nullptr);
  EXPECT_EQ(leaf.equation().total_degree(), 8);
  EXPECT_EQ(leaf.piece_count(), 1u);
  EXPECT_TRUE(leaf.trimmed());
  EXPECT_NE(leaf.tolerance_kept_exact().find("shorter"), std::string::npos) << leaf.tolerance_kept_exact();
  EXPECT_EQ(leaf.glsl_lines(), testing::compile(tp22(std::nullopt)).leaves().front().glsl_lines());
  SceneNode tight = parametric("s", "t", "s*t^2", unit_square());
  tight.leaf.tolerance = 1e-300;
  const CompiledScene exact = testing::compile(tight);
  EXPECT_EQ(exact.leaves().front().approximation(), nullptr);
  EXPECT_EQ(exact.leaves().front().equation().total_degree(), 3);
  EXPECT_NEAR(exact.evaluate(V{0.5, 0.5, 0.125}), 0, 1e-9);
}

// The approximation's early stop relies on every piece taking more lines than
// kMinPieceGlslLines; the smallest piece is a plane's, trimmed, in either mode.
TEST(PolynomialLeaf, EveryPieceTakesMoreThanTheMinimumLines) {
  for (SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
    const CompiledScene plane = testing::compile(parametric("s", "t", "s+t", unit_square()), mode);
    ASSERT_TRUE(plane.leaves().front().trimmed());
    EXPECT_GT(plane.leaves().front().glsl_lines(), PolynomialLeaf::kMinPieceGlslLines);
  }
}

// Where the approximation is kept its GLSL is the shorter.
TEST(PolynomialLeaf, AKeptApproximationIsShorterThanTheExactEquation) {
  const CompiledScene approximated = testing::compile(tp33(1e-2));
  const CompiledScene exact = testing::compile(tp33(std::nullopt));
  ASSERT_NE(approximated.leaves().front().approximation(), nullptr);
  EXPECT_EQ(approximated.leaves().front().tolerance_kept_exact(), "");
  EXPECT_LT(approximated.leaves().front().glsl_lines(), exact.leaves().front().glsl_lines());
  EXPECT_LT(count_lines(approximated.to_glsl()), count_lines(exact.to_glsl()));
}

TEST(PolynomialLeaf, ClosedSurfaceWithAToleranceKeepsItsExactEquation) {
  SceneNode sphere = parametric("2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(1-s^2-t^2)/(1+s^2+t^2)");
  sphere.leaf.tolerance = 1e-3;
  const CompiledScene scene = testing::compile(sphere);
  const PolynomialLeaf& leaf = scene.leaves().front();
  EXPECT_EQ(leaf.approximation(), nullptr);
  EXPECT_NE(leaf.tolerance_kept_exact(), "");
  EXPECT_EQ(leaf.equation().total_degree(), 2);
  EXPECT_NEAR(scene.evaluate(V{0, 0, -1}), 0, 1e-9);
}

TEST(PolynomialLeaf, BadTolerancesAreRefusedByName) {
  const auto code_and_field = [](SceneNode node, std::optional<double> tolerance, SdfShape shape = SdfShape::automatic,
                                 int dimension = 3) {
    node.leaf.tolerance = tolerance;
    node.leaf.shape = shape;
    return compile_error(node, dimension);
  };
  const auto refused = std::make_pair(std::string("invalid_tolerance"), std::string("scene.tolerance"));
  const SceneNode saddle = parametric("s", "t", "s*t", unit_square());
  for (double eps : {0.0, -1e-3, 0.6, std::nan(""), HUGE_VAL}) EXPECT_EQ(code_and_field(saddle, eps), refused) << eps;
  EXPECT_EQ(code_and_field(implicit("x^2+y^2+z^2-1"), 1e-3), refused);
  EXPECT_EQ(code_and_field(saddle, 1e-3, SdfShape::solid), refused);
  EXPECT_EQ(code_and_field(parametric_curve("s", "s^2", {{Rational(0), Rational(1)}}), 1e-3, SdfShape::automatic, 2),
            refused);
  // The largest tolerance is allowed.
  EXPECT_EQ(code_and_field(saddle, 0.5).first, "");
}

}  // namespace
}  // namespace implicitizer
