#pragma once
// Shared by the tests of lib/scene: node builders, GLSL compilation in both dialects,
// execution on llvmpipe with uniforms, and the comparison with evaluate<float>.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "implicitizer/scene/compiled_scene.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "sdf/gles_runner.hpp"
#include "sdf/sdf_support.hpp"

namespace implicitizer::testing {

inline SceneNode named(SceneNode node, const std::string& name, std::vector<std::string> uniforms = {}) {
  node.name = name;
  node.uniforms = std::move(uniforms);
  return node;
}

inline SceneNode sphere(double r) { return make_node(NodeKind::sphere, {{"radius", r}}); }
inline SceneNode torus(double major, double minor) {
  return make_node(NodeKind::torus, {{"major", major}, {"minor", minor}});
}
inline SceneNode translate(Vec3<double> offset, SceneNode child) {
  return make_node(NodeKind::translate, {{"offset", offset}}, {std::move(child)});
}
inline SceneNode rotate(Vec3<double> axis, double angle, SceneNode child) {
  return make_node(NodeKind::rotate, {{"axis", axis}, {"angle", angle}}, {std::move(child)});
}
inline SceneNode scale(double factor, SceneNode child) {
  return make_node(NodeKind::scale, {{"factor", factor}}, {std::move(child)});
}
inline SceneNode implicit(const std::string& equation) {
  SceneNode node = make_node(NodeKind::implicit);
  node.leaf.equation = equation;
  return node;
}
inline SceneNode parametric(const std::string& x, const std::string& y, const std::string& z,
                            std::vector<std::pair<Rational, Rational>> domain = {}) {
  SceneNode node = make_node(NodeKind::parametric);
  node.leaf.coordinates = {x, y, z};
  node.leaf.domain = std::move(domain);
  return node;
}

inline CompiledScene compile(const SceneNode& root, SdfMode mode = SdfMode::fast, const std::string& name = "s") {
  SceneParams options;
  options.mode = mode;
  options.name = name;
  return compile_scene(root, options);
}

// The call of the scene's NAME_sdf at a vec3 expression `p`: a plane curve's takes
// the vec2 p.xy (it evaluates at z = 0).
inline std::string sdf_call(const CompiledScene& scene, const std::string& p) {
  return scene.function_name() + (scene.dimension() == 2 ? "(" + p + ".xy)" : "(" + p + ")");
}

// "" when the scene's GLSL compiles with glslangValidator as GLSL ES 3.00 and as 330
// (a curve's through a vec3 wrapper that calls its vec2 NAME_sdf).
inline std::string glslang_both(const CompiledScene& scene) {
  const std::string text =
      scene.to_glsl() + "float glslang_check(vec3 p) {\n  return " + sdf_call(scene, "p") + ";\n}\n";
  for (const char* header : {"#version 300 es\nprecision highp float;", "#version 330"}) {
    const std::string errors = glslang_errors(header, text, "glslang_check");
    if (!errors.empty()) return std::string(header) + ": " + errors + "\n" + scene.to_glsl();
  }
  return "";
}

// The scene's GLSL with its uniforms set to `values`, as a function `float run(vec3 p)`
// GlesRunner can call. GlesRunner sets no uniforms, so each `uniform T NAME;` becomes a
// plain global that run() assigns before calling NAME_sdf, from the value plus
// (gl_FragCoord.y - 0.5), which is exactly 0 on the runner's one-row framebuffer but
// unknown to the compiler: the values arrive at run time, as a uniform's would,
// and no expression using them is constant-folded.
inline std::string gpu_source(const CompiledScene& scene, const UniformValues& values) {
  std::string text = scene.to_glsl();
  std::string assignments = "  float zero = gl_FragCoord.y - 0.5;\n";
  for (std::size_t i = 0; i < scene.uniforms().size(); ++i) {
    const SceneUniform& u = scene.uniforms()[i];
    const bool vector = u.type == ParameterType::vec3;
    const std::string declaration = std::string("uniform ") + (vector ? "vec3 " : "float ") + u.name + ";";
    const std::size_t at = text.find(declaration);
    if (at == std::string::npos) return "missing declaration " + declaration;
    text.replace(at, declaration.size(), std::string(vector ? "vec3 " : "float ") + u.name + ";");
    const Vec3<double>& v = values[i];
    const std::string x = format_glsl_float(static_cast<float>(v.x));
    assignments += "  " + u.name + " = " +
                   (vector ? "vec3(" + x + ", " + format_glsl_float(static_cast<float>(v.y)) + ", " +
                                 format_glsl_float(static_cast<float>(v.z)) + ") + vec3(zero)"
                           : x + " + zero") +
                   ";\n";
  }
  return text + "float run(vec3 p) {\n" + assignments + "  return " + sdf_call(scene, "p") + ";\n}\n";
}

// Points uniform in [lo, hi]^3 (fixed seed).
inline std::vector<Vec3<float>> random_points(std::size_t n, float lo, float hi, unsigned seed = 7) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> coordinate(lo, hi);
  std::vector<Vec3<float>> points;
  for (std::size_t i = 0; i < n; ++i) points.push_back({coordinate(random), coordinate(random), coordinate(random)});
  return points;
}

// The distance between two floats in units in the last place (0 when equal, also for +0/-0).
inline std::int64_t ulps_apart(float a, float b) {
  if (a == b) return 0;
  const auto ordered = [](float x) {
    std::int32_t i;
    std::memcpy(&i, &x, sizeof(i));
    return i < 0 ? static_cast<std::int64_t>(INT32_MIN) - i : static_cast<std::int64_t>(i);
  };
  const std::int64_t d = ordered(a) - ordered(b);
  return d < 0 ? -d : d;
}

// GPU against evaluate<float>.
struct GpuComparison {
  std::string error;  // "" when the GPU ran
  std::size_t points = 0, identical = 0;
  double worst_scaled = 0;  // max |gpu - cpu| / (2^-24 · scale), scale = max(|p|∞, |cpu|, 1)
  std::int64_t worst_ulps = 0;
  std::vector<float> gpu, cpu;
};

inline GpuComparison compare_on_gpu(const CompiledScene& scene, const std::vector<Vec3<float>>& points,
                                    const UniformValues& values) {
  GpuComparison r;
  std::vector<float> xyz;
  for (const auto& p : points) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  r.gpu = GlesRunner::instance().evaluate(gpu_source(scene, values), "run", xyz, r.error);
  if (!r.error.empty()) return r;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float cpu = scene.evaluate(points[i], values);
    r.cpu.push_back(cpu);
    ++r.points;
    if (std::memcmp(&cpu, &r.gpu[i], sizeof(float)) == 0 || cpu == r.gpu[i]) ++r.identical;
    const double scale =
        std::max({1.0, static_cast<double>(std::fabs(cpu)), static_cast<double>(std::fabs(points[i].x)),
                  static_cast<double>(std::fabs(points[i].y)), static_cast<double>(std::fabs(points[i].z))});
    r.worst_scaled =
        std::max(r.worst_scaled, std::fabs(static_cast<double>(r.gpu[i]) - cpu) / (std::ldexp(1.0, -24) * scale));
    r.worst_ulps = std::max(r.worst_ulps, ulps_apart(cpu, r.gpu[i]));
  }
  return r;
}

}  // namespace implicitizer::testing
