#include "implicitizer/scene/affine_transforms.hpp"

#include <cmath>

#include "node_operations.hpp"

namespace implicitizer {

// rotate_point's steps: d, the cross product k × p component by component, then
// p·c − kp·s + k·d from the left.
std::string rotate_glsl(const std::string& prefix) {
  return "vec3 " + prefix +
         "_rotate(vec3 p, vec3 k, float c, float s) {\n"
         "  float d = (k.x * p.x + k.y * p.y + k.z * p.z) * (1.0 - c);\n"
         "  vec3 kp = vec3(k.y * p.z - k.z * p.y, k.z * p.x - k.x * p.z, k.x * p.y - k.y * p.x);\n"
         "  return p * c - kp * s + k * d;\n"
         "}\n";
}

// ---------------------------------------------------------------------------------
// The transforms as scene nodes. Isometries and uniform scaling keep both classes.

namespace {

using V = Vec3<double>;

template <typename T>
T evaluate_translate(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return e.child(n, 0, translate_point(p, e.slots(n).vector(0)));
}
NodeBox bound_translate(const NodeCompilation& c) {
  if (c.uniform({0})) return {};
  return child_grows_box(c, c.child(0).box_lo + c.value(0), c.child(0).box_hi + c.value(0));
}
std::string emit_translate(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return w.child(n, 0, w.point(p + " - " + w.vector(n, 0), SceneGlslWriter::type(n)));
}

// The unit axis k = axis/|axis| in double, then rounded; with the angle baked, its
// cos and sin in double: slots 2, 3.
void classify_rotate(NodeCompilation& c) {
  V k = c.value(0);
  k = k / length(k);
  c.out.slots[0] = baked_slot(k);
  if (!c.uniform({1})) {
    const double angle = c.value(1).x;
    c.out.slots.push_back(baked_slot(std::cos(angle)));
    c.out.slots.push_back(baked_slot(std::sin(angle)));
  }
  c.out.node_class = c.children_class();
}
template <typename T>
T evaluate_rotate(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const SlotReader<T> s = e.slots(n);
  if (s.is_uniform(1)) {
    const T angle = s.scalar(1);
    return e.child(n, 0, rotate_point(p, s.vector(0), T(std::cos(angle)), T(std::sin(angle))));
  }
  return e.child(n, 0, rotate_point(p, s.vector(0), s.scalar(2), s.scalar(3)));
}
// The child's box rotated by θ about the unit axis k (rotate_point(·, k, c, −s) is the
// forward rotation), boxed again; for a uniform angle, the box of the ball around the
// origin through the farthest corner (any angle).
NodeBox bound_rotate(const NodeCompilation& c) {
  const double inf = CompiledScene::kUnbounded;
  const V l = c.child(0).box_lo, h = c.child(0).box_hi;
  const bool finite = std::isfinite(l.x) && std::isfinite(l.y) && std::isfinite(l.z) && std::isfinite(h.x) &&
                      std::isfinite(h.y) && std::isfinite(h.z);
  if (!finite) return {};
  V rl{inf, inf, inf}, rh{-inf, -inf, -inf};
  double reach = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const V q{corner & 1 ? h.x : l.x, corner & 2 ? h.y : l.y, corner & 4 ? h.z : l.z};
    reach = std::max(reach, length(q));
    if (!c.uniform({1})) {
      const V r = rotate_point(q, c.value(0), c.value(2).x, -c.value(3).x);
      rl = lower_corner(rl, r);
      rh = upper_corner(rh, r);
    }
  }
  if (c.uniform({1})) return child_grows_box(c, -cube_corner(reach), cube_corner(reach));
  // cos and sin were rounded to double: widen by a relative 1e-12 of the reach.
  return child_grows_box(c, rl - cube_corner(reach * 1e-12), rh + cube_corner(reach * 1e-12));
}
std::string emit_rotate(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  w.require_helper("rotate", rotate_glsl(w.prefix()));
  const std::string trig = n.slots[1].uniform >= 0 ? "cos(" + w.scalar(n, 1) + "), sin(" + w.scalar(n, 1) + ")"
                                                   : w.scalar(n, 2) + ", " + w.scalar(n, 3);
  return w.child(n, 0, w.point(w.call("rotate", p + ", " + w.vector(n, 0) + ", " + trig), SceneGlslWriter::type(n)));
}

template <typename T>
T evaluate_scale(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const T factor = e.slots(n).scalar(0);
  return e.child(n, 0, scale_point(p, factor)) * factor;
}
NodeBox bound_scale(const NodeCompilation& c) {
  if (c.uniform({0})) return {};
  return child_grows_box(c, c.child(0).box_lo * c.value(0).x, c.child(0).box_hi * c.value(0).x);
}
std::string emit_scale(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  const std::string factor = w.scalar(n, 0);
  const std::string d = w.child(n, 0, w.point(p + " / " + factor, SceneGlslWriter::type(n)));
  return w.value(d + " * " + factor, SceneGlslWriter::type(n));
}

}  // namespace

const NodeOperations kTranslateOperations = {classify_as_children, bound_translate, evaluate_translate<float>,
                                             evaluate_translate<double>, emit_translate};
const NodeOperations kRotateOperations = {classify_rotate, bound_rotate, evaluate_rotate<float>,
                                          evaluate_rotate<double>, emit_rotate};
const NodeOperations kScaleOperations = {classify_as_children, bound_scale, evaluate_scale<float>,
                                         evaluate_scale<double>, emit_scale};

}  // namespace implicitizer
