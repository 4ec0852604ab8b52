#include "implicitizer/scene/boolean_operators.hpp"

#include "implicitizer/core/errors.hpp"
#include "implicitizer/sdf/polynomial_program.hpp"
#include "node_operations.hpp"

namespace implicitizer {
namespace {

// max(k − |a − b|, 0)/k, its n-th power from the left, ·k, /(2n): smooth_blend's steps.
std::string blend_glsl(std::int32_t n) {
  std::string power = "h";
  for (std::int32_t i = 1; i < n; ++i) power += " * h";
  return "  float h = max(k - abs(a - b), 0.0) / k;\n" + std::string("  float w = ") + power + " * k / " +
         format_glsl_float(static_cast<float>(2 * n)) + ";\n";
}

}  // namespace

std::string smooth_min_glsl(const std::string& prefix, std::int32_t n) {
  return "float " + prefix + "_smin" + std::to_string(n) + "(float a, float b, float k) {\n" + blend_glsl(n) +
         "  return min(a, b) - w;\n}\n";
}

std::string smooth_max_glsl(const std::string& prefix, std::int32_t n) {
  return "float " + prefix + "_smax" + std::to_string(n) + "(float a, float b, float k) {\n" + blend_glsl(n) +
         "  return max(a, b) + w;\n}\n";
}

// ---------------------------------------------------------------------------------
// The operators as scene nodes: n ≥ 2 children combined from the left; the smooth
// ones read k from slot 0 and n from the node's count.

namespace {

using V = Vec3<double>;

template <typename T, typename Combine>
T fold_children(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p, Combine combine) {
  T d = e.child(n, 0, p);
  for (std::size_t i = 1; i < n.children.size(); ++i) d = combine(d, e.child(n, i, p));
  return d;
}

// The GLSL of fold_children: helper `id` (if any) is required after the first child,
// where the switch this replaced required it, so the helpers keep their order.
template <typename Combine>
std::string fold_children_glsl(SceneGlslWriter& w, const CompiledNode& n, const std::string& p, const std::string& id,
                               const std::string& text, Combine combine) {
  std::string d = w.child(n, 0, p);
  if (!id.empty()) w.require_helper(id, text);
  for (std::size_t i = 1; i < n.children.size(); ++i) {
    const std::string e = w.child(n, i, p);
    d = w.value(combine(d, e), SceneGlslWriter::type(n));
  }
  return d;
}

// The blend is 1-Lipschitz in (a, b) for the max-norm (boolean_operators.hpp), so it
// keeps 1-Lipschitz children 1-Lipschitz; over mere bounds it can overshoot the
// distance (two planes-like bounds scaled by 1/10 blend by k regardless of the true
// distances), so safe mode refuses.
void classify_smooth(NodeCompilation& c) {
  c.out.node_class = c.children_class();
  if (!c.safe() || c.out.node_class == NodeClass::lipschitz) return;
  for (std::size_t i = 0; i < c.out.children.size(); ++i) {
    if (c.child(i).node_class != NodeClass::lipschitz) {
      throw InputError("unsafe_operator",
                       "in mode safe a smooth operator needs 1-Lipschitz children (primitives, their "
                       "transforms and sharp combinations); " +
                           child_field(c.path, NodeArity::nary, i) +
                           " is only a distance bound (an implicit or parametric leaf, or uses one)")
          .in_field(c.path);
    }
  }
}

// max(a, −b) uses b's claim inside b (where −b > 0): an outer bound has none, so safe
// mode refuses one as a subtrahend. The minuend and the result keep the weakest class.
void classify_difference(NodeCompilation& c) {
  c.out.node_class = c.children_class();
  if (!c.safe()) return;
  for (std::size_t i = 1; i < c.out.children.size(); ++i) {
    if (c.child(i).node_class == NodeClass::outer_bound) {
      throw InputError("unsafe_operator",
                       "in mode safe a difference cannot subtract " + child_field(c.path, NodeArity::nary, i) +
                           ": it is only bounded outside (a shell over a polynomial leaf or another mere bound), "
                           "and the difference needs its distance inside")
          .in_field(child_field(c.path, NodeArity::nary, i));
    }
  }
}

// {min ≤ 0} is the union of the solids: the hull of the children's boxes, growing
// where every child grows.
NodeBox bound_union(const NodeCompilation& c) {
  V l = c.child(0).box_lo, h = c.child(0).box_hi;
  bool g = true;
  for (std::size_t i = 0; i < c.out.children.size(); ++i) {
    l = lower_corner(l, c.child(i).box_lo);
    h = upper_corner(h, c.child(i).box_hi);
    g = g && c.child(i).box_grows;
  }
  return {l, h, g};
}

// smin ≥ min − k/(2n), so where every child grows the blend stays within k/(2n) of
// the union's hull.
NodeBox bound_smooth_union(const NodeCompilation& c) {
  const NodeBox hull = bound_union(c);
  if (!hull.grows || c.uniform({0})) return {};
  const double margin = c.value(0).x / (2.0 * c.out.count);
  return {hull.lo - cube_corner(margin), hull.hi + cube_corner(margin), true};
}

// smax ≥ max: the solid lies in every child's solid.
NodeBox bound_intersection(const NodeCompilation& c) {
  V l = c.child(0).box_lo, h = c.child(0).box_hi;
  for (std::size_t i = 1; i < c.out.children.size(); ++i) {
    l = upper_corner(l, c.child(i).box_lo);
    h = lower_corner(h, c.child(i).box_hi);
  }
  return {l, h, false};
}

// max(a, −b) and smax(a, −b) are ≥ a.
NodeBox bound_difference(const NodeCompilation& c) { return child_grows_box(c, c.child(0).box_lo, c.child(0).box_hi); }

// The GLSL of the sharp operators: FUNCTION(d, SIGN e) from the left.
std::string emit_sharp(SceneGlslWriter& w, const CompiledNode& n, const std::string& p, const std::string& function,
                       const std::string& sign) {
  return fold_children_glsl(w, n, p, "", "", [&](const std::string& d, const std::string& e) {
    return function + "(" + d + ", " + sign + e + ")";
  });
}

// The GLSL of the smooth operators: PREFIX_smin<n> or PREFIX_smax<n>(d, SIGN e, k).
std::string emit_smooth(SceneGlslWriter& w, const CompiledNode& n, const std::string& p, const std::string& blend,
                        const std::string& sign) {
  const std::string id = blend + std::to_string(n.count), k = w.scalar(n, 0);
  const std::string text =
      blend == "smin" ? smooth_min_glsl(w.prefix(), n.count) : smooth_max_glsl(w.prefix(), n.count);
  return fold_children_glsl(w, n, p, id, text, [&](const std::string& d, const std::string& e) {
    return w.call(id, d + ", " + sign + e + ", " + k);
  });
}

template <typename T>
T evaluate_union(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return fold_children(e, n, p, [](T d, T f) { return std::min(d, f); });
}
std::string emit_union(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_sharp(w, n, p, "min", "");
}

template <typename T>
T evaluate_intersection(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return fold_children(e, n, p, [](T d, T f) { return std::max(d, f); });
}
std::string emit_intersection(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_sharp(w, n, p, "max", "");
}

template <typename T>
T evaluate_difference(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return fold_children(e, n, p, [](T d, T f) { return std::max(d, -f); });
}
std::string emit_difference(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_sharp(w, n, p, "max", "-");
}

template <typename T>
T evaluate_smooth_union(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const T k = e.slots(n).scalar(0);
  return fold_children(e, n, p, [&](T d, T f) { return smooth_min(d, f, k, n.count); });
}
std::string emit_smooth_union(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_smooth(w, n, p, "smin", "");
}

template <typename T>
T evaluate_smooth_intersection(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const T k = e.slots(n).scalar(0);
  return fold_children(e, n, p, [&](T d, T f) { return smooth_max(d, f, k, n.count); });
}
std::string emit_smooth_intersection(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_smooth(w, n, p, "smax", "");
}

template <typename T>
T evaluate_smooth_difference(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const T k = e.slots(n).scalar(0);
  return fold_children(e, n, p, [&](T d, T f) { return smooth_max(d, -f, k, n.count); });
}
std::string emit_smooth_difference(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_smooth(w, n, p, "smax", "-");
}

}  // namespace

const NodeOperations kUnionOperations = {classify_as_children, bound_union, evaluate_union<float>,
                                         evaluate_union<double>, emit_union};
const NodeOperations kIntersectionOperations = {classify_as_children, bound_intersection, evaluate_intersection<float>,
                                                evaluate_intersection<double>, emit_intersection};
const NodeOperations kDifferenceOperations = {classify_difference, bound_difference, evaluate_difference<float>,
                                              evaluate_difference<double>, emit_difference};
const NodeOperations kSmoothUnionOperations = {classify_smooth, bound_smooth_union, evaluate_smooth_union<float>,
                                               evaluate_smooth_union<double>, emit_smooth_union};
const NodeOperations kSmoothIntersectionOperations = {classify_smooth, bound_intersection,
                                                      evaluate_smooth_intersection<float>,
                                                      evaluate_smooth_intersection<double>, emit_smooth_intersection};
const NodeOperations kSmoothDifferenceOperations = {classify_smooth, bound_difference,
                                                    evaluate_smooth_difference<float>,
                                                    evaluate_smooth_difference<double>, emit_smooth_difference};

}  // namespace implicitizer
