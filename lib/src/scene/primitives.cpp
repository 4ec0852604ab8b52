#include "implicitizer/scene/primitives.hpp"

#include <cmath>

#include "implicitizer/sdf/polynomial_program.hpp"
#include "node_operations.hpp"

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

// ---------------------------------------------------------------------------------
// The primitives as scene nodes: their slots are the table's parameters in order
// (scene_node.cpp); the exact distances are 1-Lipschitz and grow outside their box.

namespace {

using V = Vec3<double>;

template <typename T>
T evaluate_sphere(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return sdf_sphere(p, e.slots(n).scalar(0));
}
NodeBox bound_sphere(const NodeCompilation& c) {
  if (c.uniform({0})) return {};
  return {-cube_corner(c.value(0).x), cube_corner(c.value(0).x), true};
}
std::string emit_sphere(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return w.call_primitive(n, p, "sphere", sphere_glsl(w.prefix()), w.scalar(n, 0));
}

template <typename T>
T evaluate_box(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return sdf_box(p, e.slots(n).vector(0));
}
// Box and round box: the size includes the rounding.
NodeBox bound_box(const NodeCompilation& c) {
  if (c.uniform({0})) return {};
  return {-c.value(0), c.value(0), true};
}
std::string emit_box(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return w.call_primitive(n, p, "box", box_glsl(w.prefix()), w.vector(n, 0));
}

template <typename T>
T evaluate_round_box(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const SlotReader<T> s = e.slots(n);
  return sdf_round_box(p, s.vector(0), s.scalar(1));
}
std::string emit_round_box(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return w.call_primitive(n, p, "round_box", round_box_glsl(w.prefix()), w.vector(n, 0) + ", " + w.scalar(n, 1));
}

template <typename T>
T evaluate_torus(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const SlotReader<T> s = e.slots(n);
  return sdf_torus(p, s.scalar(0), s.scalar(1));
}
NodeBox bound_torus(const NodeCompilation& c) {
  if (c.uniform({0, 1})) return {};
  const double r = c.value(1).x, outer = c.value(0).x + r;
  return {{-outer, -outer, -r}, {outer, outer, r}, true};
}
std::string emit_torus(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return w.call_primitive(n, p, "torus", torus_glsl(w.prefix()), w.scalar(n, 0) + ", " + w.scalar(n, 1));
}

// n̂ = n/|n| in double, then rounded: |n̂_float| = 1 within 2^-24, so the value is
// 1-Lipschitz up to that rounding.
void classify_plane(NodeCompilation& c) {
  V n = c.value(0);
  n = n / length(n);
  c.out.slots[0] = baked_slot(n);
  c.out.node_class = NodeClass::lipschitz;
}
template <typename T>
T evaluate_plane(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const SlotReader<T> s = e.slots(n);
  return sdf_plane(p, s.vector(0), s.scalar(1));
}
// A half-space: unbounded, and "outside the box" is empty.
NodeBox bound_plane(const NodeCompilation&) {
  NodeBox box;
  box.grows = true;
  return box;
}
std::string emit_plane(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return w.call_primitive(n, p, "plane", plane_glsl(w.prefix()), w.vector(n, 0) + ", " + w.scalar(n, 1));
}

template <typename T>
T evaluate_capsule(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const SlotReader<T> s = e.slots(n);
  return sdf_capsule(p, s.vector(0), s.vector(1), s.scalar(2));
}
NodeBox bound_capsule(const NodeCompilation& c) {
  if (c.uniform({0, 1, 2})) return {};
  const V a = c.value(0), b = c.value(1);
  const double r = c.value(2).x;
  return {lower_corner(a, b) - cube_corner(r), upper_corner(a, b) + cube_corner(r), true};
}
std::string emit_capsule(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return w.call_primitive(n, p, "capsule", capsule_glsl(w.prefix()),
                          w.vector(n, 0) + ", " + w.vector(n, 1) + ", " + w.scalar(n, 2));
}

// With angle and height baked, q = (h·tan θ, −h) in double, rounded once: slots 2, 3.
void classify_cone(NodeCompilation& c) {
  c.out.node_class = NodeClass::lipschitz;
  if (!c.uniform({0, 1})) {
    const double height = c.value(1).x;
    c.out.slots.push_back(baked_slot(height * std::tan(c.value(0).x)));
    c.out.slots.push_back(baked_slot(-height));
  }
}
template <typename T>
T evaluate_cone(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const SlotReader<T> s = e.slots(n);
  const T height = s.scalar(1);
  if (s.is_uniform(0) || s.is_uniform(1)) return sdf_cone(p, height, height * std::tan(s.scalar(0)), -height);
  return sdf_cone(p, height, s.scalar(2), s.scalar(3));
}
NodeBox bound_cone(const NodeCompilation& c) {
  if (c.uniform({0, 1})) return {};
  const double h = c.value(1).x, r = h * std::tan(c.value(0).x);
  return {{-r, -r, 0}, {r, r, h}, true};
}
std::string emit_cone(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  const std::string height = w.scalar(n, 1);
  if (n.slots[0].uniform >= 0 || n.slots[1].uniform >= 0) {
    return w.call_primitive(n, p, "cone", cone_glsl(w.prefix()),
                            height + ", " + height + " * tan(" + w.scalar(n, 0) + "), -" + height);
  }
  return w.call_primitive(n, p, "cone", cone_glsl(w.prefix()), height + ", " + w.scalar(n, 2) + ", " + w.scalar(n, 3));
}

void classify_ellipsoid(NodeCompilation& c) {
  c.out.node_class = c.safe() ? NodeClass::lipschitz : NodeClass::estimate;
}
template <typename T>
T evaluate_ellipsoid(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return e.safe() ? sdf_ellipsoid_bound(p, e.slots(n).vector(0)) : sdf_ellipsoid_estimate(p, e.slots(n).vector(0));
}
// Both modes have the ellipsoid's sign; neither is at least the box distance.
NodeBox bound_ellipsoid(const NodeCompilation& c) {
  if (c.uniform({0})) return {};
  return {-c.value(0), c.value(0), false};
}
std::string emit_ellipsoid(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return w.call_primitive(n, p, "ellipsoid",
                          w.safe() ? ellipsoid_bound_glsl(w.prefix()) : ellipsoid_estimate_glsl(w.prefix()),
                          w.vector(n, 0));
}

template <typename T>
T evaluate_cylinder(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return sdf_cylinder(p, e.slots(n).scalar(0));
}
NodeBox bound_cylinder(const NodeCompilation& c) {
  if (c.uniform({0})) return {};
  const double r = c.value(0).x, inf = CompiledScene::kUnbounded;
  return {{-r, -r, -inf}, {r, r, inf}, true};
}
std::string emit_cylinder(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return w.call_primitive(n, p, "cylinder", cylinder_glsl(w.prefix()), w.scalar(n, 0));
}

}  // namespace

const NodeOperations kSphereOperations = {classify_lipschitz, bound_sphere, evaluate_sphere<float>,
                                          evaluate_sphere<double>, emit_sphere};
const NodeOperations kBoxOperations = {classify_lipschitz, bound_box, evaluate_box<float>, evaluate_box<double>,
                                       emit_box};
const NodeOperations kRoundBoxOperations = {classify_lipschitz, bound_box, evaluate_round_box<float>,
                                            evaluate_round_box<double>, emit_round_box};
const NodeOperations kTorusOperations = {classify_lipschitz, bound_torus, evaluate_torus<float>, evaluate_torus<double>,
                                         emit_torus};
const NodeOperations kPlaneOperations = {classify_plane, bound_plane, evaluate_plane<float>, evaluate_plane<double>,
                                         emit_plane};
const NodeOperations kCapsuleOperations = {classify_lipschitz, bound_capsule, evaluate_capsule<float>,
                                           evaluate_capsule<double>, emit_capsule};
const NodeOperations kConeOperations = {classify_cone, bound_cone, evaluate_cone<float>, evaluate_cone<double>,
                                        emit_cone};
const NodeOperations kEllipsoidOperations = {classify_ellipsoid, bound_ellipsoid, evaluate_ellipsoid<float>,
                                             evaluate_ellipsoid<double>, emit_ellipsoid};
const NodeOperations kCylinderOperations = {classify_lipschitz, bound_cylinder, evaluate_cylinder<float>,
                                            evaluate_cylinder<double>, emit_cylinder};

}  // namespace implicitizer
