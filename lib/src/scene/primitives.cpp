#include "implicitizer/scene/primitives.hpp"

#include "implicitizer/sdf/polynomial_program.hpp"

// Each text performs the operations of its twin in primitives.hpp, in the same order:
// dot and length spelled out (glsl_dot, glsl_length), clamp(x, a, b) = min(max(x, a), b)
// as std::clamp computes it for non-NaN x. Local names contain no `_`, so no uniform
// (always NODE_PARAM) can be shadowed.

namespace implicitizer {

std::string glsl_dot(const std::string& a, const std::string& b) {
  return a + ".x * " + b + ".x + " + a + ".y * " + b + ".y + " + a + ".z * " + b + ".z";
}

std::string glsl_length(const std::string& v) { return "sqrt(" + glsl_dot(v, v) + ")"; }

std::string sphere_glsl(const std::string& prefix) {
  return "float " + prefix + "_sphere(vec3 p, float r) {\n  return " + glsl_length("p") + " - r;\n}\n";
}

std::string box_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_box(vec3 p, vec3 b) {\n"
         "  vec3 q = abs(p) - b;\n"
         "  vec3 m = max(q, 0.0);\n"
         "  return " +
         glsl_length("m") +
         " + min(max(q.x, max(q.y, q.z)), 0.0);\n"
         "}\n";
}

std::string round_box_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_round_box(vec3 p, vec3 b, float r) {\n"
         "  vec3 q = abs(p) - b + vec3(r);\n"
         "  vec3 m = max(q, 0.0);\n"
         "  return " +
         glsl_length("m") +
         " + min(max(q.x, max(q.y, q.z)), 0.0) - r;\n"
         "}\n";
}

std::string torus_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_torus(vec3 p, float major, float minor) {\n"
         "  float qx = sqrt(p.x * p.x + p.y * p.y) - major;\n"
         "  return sqrt(qx * qx + p.z * p.z) - minor;\n"
         "}\n";
}

std::string plane_glsl(const std::string& prefix) {
  return "float " + prefix + "_plane(vec3 p, vec3 n, float h) {\n  return " + glsl_dot("p", "n") + " - h;\n}\n";
}

std::string capsule_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_capsule(vec3 p, vec3 a, vec3 b, float r) {\n"
         "  vec3 pa = p - a;\n"
         "  vec3 ba = b - a;\n"
         "  float h = clamp((" +
         glsl_dot("pa", "ba") + ") / max(" + glsl_dot("ba", "ba") + ", " + format_glsl_float(kCapsuleFloor) +
         "), 0.0, 1.0);\n"
         "  vec3 e = pa - ba * h;\n"
         "  return " +
         glsl_length("e") +
         " - r;\n"
         "}\n";
}

std::string cone_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_cone(vec3 p, float h, float qx, float qy) {\n"
         "  float wx = sqrt(p.x * p.x + p.y * p.y);\n"
         "  float wy = p.z - h;\n"
         "  float t = clamp((wx * qx + wy * qy) / (qx * qx + qy * qy), 0.0, 1.0);\n"
         "  float ax = wx - qx * t;\n"
         "  float ay = wy - qy * t;\n"
         "  float bx = wx - qx * clamp(wx / qx, 0.0, 1.0);\n"
         "  float by = wy - qy;\n"
         "  float k = sign(qy);\n"
         "  float d = min(ax * ax + ay * ay, bx * bx + by * by);\n"
         "  float s = max(k * (wx * qy - wy * qx), k * (wy - qy));\n"
         "  return sqrt(d) * sign(s);\n"
         "}\n";
}

std::string ellipsoid_estimate_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_ellipsoid(vec3 p, vec3 r) {\n"
         "  vec3 a = p / r;\n"
         "  vec3 b = p / (r * r);\n"
         "  float k0 = " +
         glsl_length("a") +
         ";\n"
         "  float k1 = " +
         glsl_length("b") +
         ";\n"
         "  return k0 * (k0 - 1.0) / max(k1, " +
         format_glsl_float(kCapsuleFloor) +
         ");\n"
         "}\n";
}

std::string ellipsoid_bound_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_ellipsoid(vec3 p, vec3 r) {\n"
         "  vec3 a = p / r;\n"
         "  return (" +
         glsl_length("a") +
         " - 1.0) * min(r.x, min(r.y, r.z));\n"
         "}\n";
}

std::string cylinder_glsl(const std::string& prefix) {
  return "float " + prefix + "_cylinder(vec3 p, float r) {\n  return sqrt(p.x * p.x + p.y * p.y) - r;\n}\n";
}

}  // namespace implicitizer
