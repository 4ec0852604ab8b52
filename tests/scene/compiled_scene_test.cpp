// The compiled scene: uniforms, the GLSL (only the helpers present, both dialects,
// run on llvmpipe against evaluate<float>), validation errors with paths, safe mode.

#include "implicitizer/scene/compiled_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "scene/scene_support.hpp"

namespace implicitizer {
namespace {

using testing::implicit;
using testing::named;
using testing::rotate;
using testing::scale;
using testing::sphere;
using testing::torus;
using testing::translate;
using V = Vec3<double>;

SceneNode leaf(NodeKind kind, std::vector<std::pair<std::string, ParameterValue>> parameters) {
  return make_node(kind, std::move(parameters));
}

// One scene per feature, each with and without uniforms: the test set of the GLSL
// tests below.
struct Example {
  std::string label;
  SceneNode root;
};

std::vector<Example> examples() {
  std::vector<Example> out;
  out.push_back({"sphere", sphere(1)});
  out.push_back({"sphere uniform", named(sphere(1), "ball", {"radius"})});
  out.push_back({"box", leaf(NodeKind::box, {{"size", V{1, 0.5, 0.75}}})});
  out.push_back({"box uniform", named(leaf(NodeKind::box, {{"size", V{1, 0.5, 0.75}}}), "crate", {"size"})});
  out.push_back({"round box", leaf(NodeKind::round_box, {{"size", V{1, 0.5, 0.75}}, {"radius", 0.2}})});
  out.push_back({"round box uniform", named(leaf(NodeKind::round_box, {{"size", V{1, 0.5, 0.75}}, {"radius", 0.2}}),
                                            "pill", {"size", "radius"})});
  out.push_back({"torus", torus(1, 0.25)});
  out.push_back({"torus uniform", named(torus(1, 0.25), "ring", {"major", "minor"})});
  out.push_back({"plane", leaf(NodeKind::plane, {{"normal", V{1, 2, 2}}, {"offset", 0.5}})});
  out.push_back(
      {"plane uniform", named(leaf(NodeKind::plane, {{"normal", V{1, 2, 2}}, {"offset", 0.5}}), "floor", {"offset"})});
  out.push_back({"capsule", leaf(NodeKind::capsule, {{"a", V{-1, 0, 0}}, {"b", V{1, 0.5, 0}}, {"radius", 0.3}})});
  out.push_back(
      {"capsule uniform", named(leaf(NodeKind::capsule, {{"a", V{-1, 0, 0}}, {"b", V{1, 0.5, 0}}, {"radius", 0.3}}),
                                "rod", {"a", "b", "radius"})});
  out.push_back({"cone", leaf(NodeKind::cone, {{"angle", 0.5}, {"height", 1.5}})});
  out.push_back(
      {"cone uniform", named(leaf(NodeKind::cone, {{"angle", 0.5}, {"height", 1.5}}), "hat", {"angle", "height"})});
  out.push_back({"ellipsoid", leaf(NodeKind::ellipsoid, {{"radii", V{1.5, 1, 0.5}}})});
  out.push_back({"ellipsoid uniform", named(leaf(NodeKind::ellipsoid, {{"radii", V{1.5, 1, 0.5}}}), "egg", {"radii"})});
  out.push_back({"cylinder", leaf(NodeKind::cylinder, {{"radius", 0.5}})});
  out.push_back({"cylinder uniform", named(leaf(NodeKind::cylinder, {{"radius", 0.5}}), "pipe", {"radius"})});
  const auto pair = [] { return std::vector<SceneNode>{translate({0.5, 0, 0}, sphere(1)), torus(1, 0.3)}; };
  out.push_back({"union", make_node(NodeKind::csg_union, {}, pair())});
  out.push_back({"intersection", make_node(NodeKind::csg_intersection, {}, pair())});
  out.push_back({"difference", make_node(NodeKind::csg_difference, {}, pair())});
  out.push_back({"smooth union", make_node(NodeKind::smooth_union, {{"k", 0.4}}, pair())});
  out.push_back(
      {"smooth union uniform", named(make_node(NodeKind::smooth_union, {{"k", 0.4}}, pair()), "blend", {"k"})});
  out.push_back(
      {"smooth intersection n=3", make_node(NodeKind::smooth_intersection, {{"k", 0.4}, {"n", 3.0}}, pair())});
  out.push_back({"smooth difference", make_node(NodeKind::smooth_difference, {{"k", 0.3}}, pair())});
  out.push_back({"translate uniform", named(translate({0.2, -0.3, 0.1}, sphere(0.8)), "move", {"offset"})});
  out.push_back({"rotate", rotate({1, 1, 0}, 0.6, torus(1, 0.25))});
  out.push_back({"rotate uniform", named(rotate({1, 1, 0}, 0.6, torus(1, 0.25)), "spin", {"angle"})});
  out.push_back({"scale", scale(1.5, torus(1, 0.25))});
  out.push_back({"scale uniform", named(scale(1.5, torus(1, 0.25)), "grow", {"factor"})});
  out.push_back({"implicit", implicit("x^2+y^2+z^2-1")});
  out.push_back({"implicit in a union", make_node(NodeKind::csg_union, {},
                                                  {implicit("x^2+y^2-z^2-0.25"), translate({1, 1, 1}, sphere(0.5))})});
  // Everything at once, with three levels of nesting and several uniforms.
  out.push_back(
      {"composite",
       make_node(NodeKind::smooth_union, {{"k", 0.25}},
                 {named(translate({0.5, 0, 0}, sphere(0.7)), "a", {"offset"}),
                  make_node(NodeKind::csg_difference, {},
                            {named(rotate({0, 1, 0}, 0.3, torus(1, 0.3)), "b", {"angle"}),
                             named(scale(0.5, leaf(NodeKind::box, {{"size", V{1, 1, 1}}})), "c", {"factor"})})})});
  return out;
}

TEST(CompiledScene, EveryExampleCompilesWithGlslangInBothDialects) {
  for (const Example& e : examples()) {
    const CompiledScene scene = testing::compile(e.root);
    EXPECT_EQ(testing::glslang_both(scene), "") << e.label;
    EXPECT_EQ(scene.to_glsl().find("pow("), std::string::npos) << e.label;
  }
  // Safe mode prints other helpers (the ellipsoid's bound): compile those too.
  for (const Example& e : examples()) {
    EXPECT_EQ(testing::glslang_both(testing::compile(e.root, SdfMode::safe)), "") << e.label;
  }
}

TEST(CompiledScene, EveryExampleRunsOnLlvmpipeLikeTheFloatEvaluator) {
  const std::string reason = testing::GlesRunner::instance().unavailable();
  if (!reason.empty()) GTEST_SKIP() << "no headless llvmpipe: " << reason;
  std::cout << "GL_RENDERER: " << testing::GlesRunner::instance().renderer() << '\n';
  const std::vector<Vec3<float>> points = testing::random_points(500, -2.5f, 2.5f, 11);
  std::size_t total = 0, identical = 0;
  double worst = 0;
  for (const SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
    for (const Example& e : examples()) {
      const CompiledScene scene = testing::compile(e.root, mode);
      // At the defaults, and (with uniforms) at values changed by ~20%.
      std::vector<UniformValues> settings = {scene.default_uniform_values()};
      if (!scene.uniforms().empty()) {
        UniformValues changed = scene.default_uniform_values();
        for (V& v : changed) v = v * 1.2;
        settings.push_back(changed);
      }
      for (const UniformValues& values : settings) {
        const testing::GpuComparison r = testing::compare_on_gpu(scene, points, values);
        ASSERT_EQ(r.error, "") << e.label;
        total += r.points;
        identical += r.identical;
        worst = std::max(worst, r.worst_scaled);
        // The stated tolerance: 16 ulps of max(|p|, |value|, 1); polynomial leaves 64
        // (Horner in u-space; the GPU may fuse multiply-adds).
        const double tolerance = e.label.find("implicit") != std::string::npos ? 64 : 16;
        EXPECT_LE(r.worst_scaled, tolerance) << e.label;
        std::cout << (mode == SdfMode::safe ? "safe " : "fast ") << e.label
                  << (&values == &settings[0] ? "" : " (changed uniforms)") << ": " << r.identical << "/" << r.points
                  << " bit-identical, worst " << r.worst_scaled << " x 2^-24 x scale, worst " << r.worst_ulps
                  << " ulps\n";
      }
    }
  }
  std::cout << "all examples: " << identical << "/" << total << " bit-identical, worst " << worst
            << " x 2^-24 x max(|p|, |value|, 1)\n";
  EXPECT_GT(total, 40000u);
}

TEST(CompiledScene, GlslContainsOnlyTheHelpersOfKindsPresent) {
  const std::string sphere_only = testing::compile(sphere(1)).to_glsl();
  EXPECT_NE(sphere_only.find("float s_sphere(vec3 p, float r)"), std::string::npos);
  for (const char* absent : {"s_torus", "s_box", "s_smin", "s_smax", "s_rotate", "s_leaf", "s_trim", "s_cone",
                             "s_capsule", "s_ellipsoid", "s_plane", "s_cylinder", "s_round_box", "uniform"}) {
    EXPECT_EQ(sphere_only.find(absent), std::string::npos) << absent;
  }
  const std::string both = testing::compile(make_node(NodeKind::smooth_union, {{"k", 0.2}},
                                                      {sphere(1), rotate({0, 0, 1}, 1, torus(1, 0.2))}))
                               .to_glsl();
  for (const char* present : {"float s_sphere(", "float s_torus(", "float s_smin2(", "vec3 s_rotate("}) {
    EXPECT_NE(both.find(present), std::string::npos) << present;
  }
  EXPECT_EQ(both.find("s_smax"), std::string::npos);
  EXPECT_EQ(both.find("s_box"), std::string::npos);
  // One helper per kind however often it occurs.
  const std::string twice =
      testing::compile(make_node(NodeKind::csg_union, {}, {sphere(1), translate({1, 0, 0}, sphere(2))})).to_glsl();
  EXPECT_EQ(twice.find("float s_sphere("), twice.rfind("float s_sphere("));
}

TEST(CompiledScene, TwoScenesShareOneShader) {
  // Different names, so every global identifier differs: the texts concatenate.
  const CompiledScene a =
      testing::compile(make_node(NodeKind::csg_union, {}, {sphere(1), torus(1, 0.2)}), SdfMode::fast, "a");
  const CompiledScene b =
      testing::compile(make_node(NodeKind::csg_union, {}, {sphere(1), torus(2, 0.2)}), SdfMode::fast, "b");
  const std::string both = a.to_glsl() + b.to_glsl() + "float both(vec3 p) { return min(a_sdf(p), b_sdf(p)); }\n";
  EXPECT_EQ(testing::glslang_errors("#version 300 es\nprecision highp float;", both, "both"), "");
}

TEST(CompiledScene, UniformsHaveNamesTypesDefaultsAndOverridesChangeTheValue) {
  SceneNode root = make_node(
      NodeKind::csg_union, {},
      {named(sphere(1), "ball", {"radius"}), named(translate({3, 0, 0}, torus(1, 0.25)), "ring", {"offset"})});
  const CompiledScene scene = testing::compile(root);
  ASSERT_EQ(scene.uniforms().size(), 2u);
  EXPECT_EQ(scene.uniforms()[0].name, "ball_radius");
  EXPECT_EQ(scene.uniforms()[0].type, ParameterType::scalar);
  EXPECT_EQ(scene.uniforms()[0].default_value.x, 1.0);
  EXPECT_EQ(scene.uniforms()[0].field, "scene.children[0].radius");
  EXPECT_EQ(scene.uniforms()[1].name, "ring_offset");
  EXPECT_EQ(scene.uniforms()[1].type, ParameterType::vec3);
  EXPECT_EQ(scene.uniforms()[1].default_value.x, 3.0);
  EXPECT_EQ(scene.find_uniform("ring_offset"), std::optional<std::size_t>(1));
  EXPECT_FALSE(scene.find_uniform("ring_radius"));

  const std::string glsl = scene.to_glsl();
  EXPECT_NE(glsl.find("uniform float ball_radius;\nuniform vec3 ring_offset;\n"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("s_sphere(p, ball_radius)"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("p - ring_offset"), std::string::npos) << glsl;

  EXPECT_DOUBLE_EQ(scene.evaluate(V{0, 0, 0}), -1.0);
  UniformValues values = scene.default_uniform_values();
  values[0].x = 2;
  EXPECT_DOUBLE_EQ(scene.evaluate(V{0, 0, 0}, values), -2.0);
  EXPECT_FLOAT_EQ(scene.evaluate(Vec3<float>{0, 0, 0}, values), -2.0f);
  // Move the torus onto the origin's neighbourhood: at (1, 0, 0) its tube centre.
  values[1] = {0, 0, 0};
  EXPECT_DOUBLE_EQ(scene.evaluate(V{1, 0, 0}, values), -1.0);  // min(sphere 1 − 2, torus −0.25)
  values[0].x = 0.5;
  EXPECT_DOUBLE_EQ(scene.evaluate(V{1, 0, 0}, values), -0.25);
  EXPECT_THROW(scene.evaluate(V{0, 0, 0}, UniformValues{}), std::invalid_argument);
  // The same scene baked: no uniform in the text, the same values at the defaults.
  root.children[0].uniforms.clear();
  root.children[1].uniforms.clear();
  const CompiledScene baked = testing::compile(root);
  EXPECT_EQ(baked.to_glsl().find("uniform"), std::string::npos);
  for (const auto& p : testing::random_points(200, -3, 3, 3)) EXPECT_EQ(baked.evaluate(p), scene.evaluate(p));
}

std::pair<std::string, std::string> failure(const SceneNode& root, SdfMode mode = SdfMode::fast,
                                            const std::string& name = "s") {
  try {
    testing::compile(root, mode, name);
  } catch (const InputError& e) {
    return {e.code(), e.field()};
  }
  return {"", ""};
}

using Failure = std::pair<std::string, std::string>;

TEST(CompiledScene, ValidationErrorsCarryCodesAndPaths) {
  EXPECT_EQ(failure(make_node(NodeKind::sphere)), Failure("missing_parameter", "scene.radius"));
  EXPECT_EQ(failure(sphere(-1)), Failure("invalid_value", "scene.radius"));
  EXPECT_EQ(failure(sphere(std::nan(""))), Failure("invalid_value", "scene.radius"));
  EXPECT_EQ(failure(sphere(1e300)), Failure("invalid_value", "scene.radius"));
  EXPECT_EQ(failure(make_node(NodeKind::sphere, {{"radius", V{1, 1, 1}}})), Failure("invalid_value", "scene.radius"));
  EXPECT_EQ(failure(make_node(NodeKind::sphere, {{"radius", 1.0}, {"radiu", 1.0}})),
            Failure("invalid_scene", "scene.radiu"));
  EXPECT_EQ(failure(leaf(NodeKind::plane, {{"normal", V{0, 0, 0}}})), Failure("invalid_value", "scene.normal"));
  EXPECT_EQ(failure(leaf(NodeKind::cone, {{"angle", 1.6}, {"height", 1.0}})), Failure("invalid_value", "scene.angle"));
  EXPECT_EQ(failure(make_node(NodeKind::smooth_union, {{"k", 0.1}, {"n", 2.5}}, {sphere(1), sphere(2)})),
            Failure("invalid_value", "scene.n"));
  EXPECT_EQ(failure(make_node(NodeKind::smooth_union, {{"k", 0.1}, {"n", 17.0}}, {sphere(1), sphere(2)})),
            Failure("invalid_value", "scene.n"));
  EXPECT_EQ(failure(make_node(NodeKind::smooth_union, {{"k", 0.0}}, {sphere(1), sphere(2)})),
            Failure("invalid_value", "scene.k"));
  EXPECT_EQ(failure(make_node(NodeKind::csg_union, {}, {sphere(1)})), Failure("invalid_scene", "scene.children"));
  EXPECT_EQ(failure(make_node(NodeKind::translate, {{"offset", V{1, 0, 0}}})), Failure("invalid_scene", "scene.child"));
  EXPECT_EQ(failure(make_node(NodeKind::sphere, {{"radius", 1.0}}, {sphere(1)})), Failure("invalid_scene", "scene"));
  // Deep paths.
  EXPECT_EQ(failure(make_node(NodeKind::csg_union, {}, {sphere(1), translate({0, 0, 0}, sphere(-2))})),
            Failure("invalid_value", "scene.children[1].child.radius"));
  // Uniforms.
  EXPECT_EQ(failure(named(sphere(1), "", {"radius"})), Failure("invalid_scene", "scene.uniforms"));
  EXPECT_EQ(failure(named(sphere(1), "ball", {"size"})), Failure("invalid_value", "scene.uniforms[0]"));
  EXPECT_EQ(failure(named(sphere(1), "ball", {"radius", "radius"})), Failure("name_collision", "scene.uniforms[1]"));
  EXPECT_EQ(failure(named(leaf(NodeKind::plane, {{"normal", V{0, 0, 1}}}), "floor", {"normal"})),
            Failure("invalid_value", "scene.uniforms[0]"));
  EXPECT_EQ(failure(named(make_node(NodeKind::smooth_union, {{"k", 0.1}}, {sphere(1), sphere(2)}), "m", {"n"})),
            Failure("invalid_value", "scene.uniforms[0]"));
  EXPECT_EQ(failure(make_node(NodeKind::csg_union, {}, {named(sphere(1), "twin"), named(sphere(2), "twin")})),
            Failure("name_collision", "scene.children[1].name"));
  // The scene's own name.
  EXPECT_EQ(failure(sphere(1), SdfMode::fast, "float"), Failure("invalid_name", "name"));
}

TEST(CompiledScene, InjectionAttemptsAreRefused) {
  for (const char* name : {"a; } void main(){", "gl_X", "x__y", "float", "uniform", "b_", "1a", "a b", "é", ""}) {
    if (std::string(name).empty()) continue;  // empty means "no name", not an error
    EXPECT_EQ(failure(named(sphere(1), name)).first, "invalid_name") << name;
    EXPECT_EQ(failure(named(sphere(1), name)).second, "scene.name") << name;
    EXPECT_EQ(failure(sphere(1), SdfMode::fast, name).first, "invalid_name") << name;
  }
  // Issue 16: "gl" alone is an identifier, but what it derives is reserved: the scene's
  // gl_sdf and gl_sphere, a node's uniform gl_radius. Refused where the name is given.
  EXPECT_EQ(failure(sphere(1), SdfMode::fast, "gl"), Failure("invalid_name", "name"));
  EXPECT_EQ(failure(named(sphere(1), "gl", {"radius"})), Failure("invalid_name", "scene.name"));
  EXPECT_EQ(failure(named(sphere(1), "gl")), Failure("invalid_name", "scene.name"));
  const CompiledScene fine = testing::compile(named(sphere(1), "s", {"radius"}));
  EXPECT_EQ(fine.uniforms()[0].name, "s_radius");
  EXPECT_EQ(testing::glslang_both(fine), "");
  // Names never reach the text except as validated identifiers.
  EXPECT_EQ(fine.to_glsl().find(';', fine.to_glsl().find("uniform float s_radius")),
            fine.to_glsl().find("uniform float s_radius") + std::string("uniform float s_radius").size());
}

TEST(CompiledScene, NamesNextToTheReservedOnesCompileWithGlslang) {
  // The scene's name prefixes every helper: "GL" differs from the refused "gl" only in
  // case, and GL_ is reserved for macros alone.
  for (const Example& e : examples()) {
    EXPECT_EQ(testing::glslang_both(testing::compile(e.root, SdfMode::fast, "GL")), "") << e.label;
  }
  // A node's name prefixes its uniforms.
  for (const char* name : {"GL", "g", "gl0"}) {
    const CompiledScene scene = testing::compile(named(sphere(1), name, {"radius"}), SdfMode::fast, name);
    EXPECT_EQ(testing::glslang_both(scene), "") << name;
  }
}

TEST(CompiledScene, SafeModeRefusesSmoothOperatorsOverPolynomialLeaves) {
  // The class of each kind.
  EXPECT_EQ(testing::compile(sphere(1), SdfMode::safe).root_class(), NodeClass::lipschitz);
  EXPECT_EQ(testing::compile(leaf(NodeKind::ellipsoid, {{"radii", V{1, 2, 3}}}), SdfMode::safe).root_class(),
            NodeClass::lipschitz);
  EXPECT_EQ(testing::compile(leaf(NodeKind::ellipsoid, {{"radii", V{1, 2, 3}}})).root_class(), NodeClass::estimate);
  const SceneNode smooth_spheres =
      make_node(NodeKind::smooth_union, {{"k", 0.3}}, {sphere(1), scale(2, rotate({1, 0, 0}, 1, torus(1, 0.2)))});
  EXPECT_EQ(testing::compile(smooth_spheres, SdfMode::safe).root_class(), NodeClass::lipschitz);
  // Smooth over a polynomial leaf (deep inside a transform) is refused in safe mode,
  // with the smooth node's path; fast mode accepts it as an estimate.
  const SceneNode over_leaf =
      make_node(NodeKind::csg_union, {},
                {sphere(1), make_node(NodeKind::smooth_difference, {{"k", 0.3}},
                                      {sphere(1), translate({1, 0, 0}, implicit("x^2+y^2+z^2-1"))})});
  EXPECT_EQ(testing::compile(over_leaf).root_class(), NodeClass::estimate);
  EXPECT_EQ(failure(over_leaf, SdfMode::safe), Failure("unsafe_operator", "scene.children[1]"));
  // Sharp operators over the same leaf are fine in safe mode: the result is a bound.
  const SceneNode sharp =
      make_node(NodeKind::csg_difference, {}, {sphere(1), translate({1, 0, 0}, implicit("x^2+y^2+z^2-1"))});
  EXPECT_EQ(testing::compile(sharp, SdfMode::safe).root_class(), NodeClass::bound);
  // And a smooth operator over a sharp combination of primitives is 1-Lipschitz.
  EXPECT_EQ(
      testing::compile(make_node(NodeKind::smooth_union, {{"k", 0.2}},
                                 {sphere(1), make_node(NodeKind::csg_difference, {}, {torus(1, 0.2), sphere(0.5)})}),
                       SdfMode::safe)
          .root_class(),
      NodeClass::lipschitz);
  // Smooth over the fast ellipsoid estimate is allowed in fast mode (not a bound anyway).
  EXPECT_EQ(failure(make_node(NodeKind::smooth_union, {{"k", 0.3}},
                              {sphere(1), leaf(NodeKind::ellipsoid, {{"radii", V{1, 2, 3}}})})),
            Failure("", ""));
}

TEST(CompiledScene, SafeSceneOfPrimitivesNeverExceedsTheDistance) {
  // A smooth union is 1-Lipschitz, hence |v| ≤ distance to its zero set: check
  // |v(p) − v(q)| ≤ |p − q| on random pairs, in double.
  const SceneNode root = make_node(
      NodeKind::smooth_union, {{"k", 0.5}, {"n", 3.0}},
      {translate({0.6, 0, 0}, leaf(NodeKind::ellipsoid, {{"radii", V{1, 0.5, 0.3}}})),
       make_node(NodeKind::smooth_difference, {{"k", 0.2}},
                 {leaf(NodeKind::box, {{"size", V{0.5, 0.5, 0.5}}}), leaf(NodeKind::cylinder, {{"radius", 0.3}})})});
  const CompiledScene scene = testing::compile(root, SdfMode::safe);
  ASSERT_EQ(scene.root_class(), NodeClass::lipschitz);
  const auto a = testing::random_points(4000, -2, 2, 1), b = testing::random_points(4000, -2, 2, 2);
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const V p{a[i].x, a[i].y, a[i].z};
    const V q = p + (V{b[i].x, b[i].y, b[i].z} - p) * 0.05;
    const V d = p - q;
    const double distance = std::sqrt(dot(d, d));
    worst = std::max(worst, std::fabs(scene.evaluate(p) - scene.evaluate(q)) / distance);
  }
  EXPECT_LE(worst, 1 + 1e-9);
  std::cout << "safe composite: worst |v(p) - v(q)|/|p - q| = " << worst << '\n';
}

TEST(CompiledScene, TooLargeScenesAreRefused) {
  // Depth: a chain of 70 translates.
  SceneNode deep = sphere(1);
  for (int i = 0; i < 70; ++i) deep = translate({0, 0, 0}, deep);
  const Failure f = failure(deep);
  EXPECT_EQ(f.first, "scene_too_large");
  EXPECT_EQ(f.second.rfind("scene.child.child", 0), 0u);
  // Count: a union of 300 spheres.
  std::vector<SceneNode> many(300, sphere(1));
  EXPECT_EQ(failure(make_node(NodeKind::csg_union, {}, many)).first, "scene_too_large");
  // 255 children + the union fit.
  std::vector<SceneNode> fit(255, sphere(1));
  EXPECT_EQ(failure(make_node(NodeKind::csg_union, {}, fit)), Failure("", ""));
}

TEST(CompiledScene, BudgetStopsCompilation) {
  Budget budget;
  budget.cancel();
  EXPECT_THROW(compile_scene(sphere(1), SceneParams{}, budget), LimitExceeded);
}

}  // namespace
}  // namespace implicitizer
