#include "implicitizer/scene/domain_operators.hpp"

#include <cmath>
#include <string>

#include "implicitizer/core/errors.hpp"
#include "node_operations.hpp"

// Each text below performs the operations of its C++ twin in domain_operators.hpp in
// the same order and association (GLSL evaluates a + b * c * d as a + ((b * c) * d),
// as C++ does), so a float run of the twin predicts the GPU.

namespace implicitizer {
namespace {

constexpr const char* kAxisLetters[3] = {"x", "y", "z"};

// The statements of one repeated axis in a cell function: the own cell c, the local
// coordinate u, the move to the neighbour when bit `bit` of `cell` is set. `finite`
// clamps the cell index to [−l, l].
std::string cell_axis_statements(int axis, int bit, bool finite, bool first) {
  const std::string a = kAxisLetters[axis];
  const std::string own = "floor(p." + a + " / s." + a + " + 0.5)";
  std::string out;
  out += std::string("  ") + (first ? "float " : "") +
         "c = " + (finite ? "clamp(" + own + ", -l." + a + ", l." + a + ")" : own) + ";\n";
  out += std::string("  ") + (first ? "float " : "") + "u = p." + a + " - s." + a + " * c;\n";
  const std::string moved = "c + (u >= 0.0 ? 1.0 : -1.0)";
  out += "  if ((cell & " + std::to_string(bit) +
         ") != 0) c = " + (finite ? "clamp(" + moved + ", -l." + a + ", l." + a + ")" : moved) + ";\n";
  out += "  q." + a + " = p." + a + " - s." + a + " * c;\n";
  return out;
}

// The statements of one repeated axis in a rest function: the squared slab distances
// to the copies 2σ ahead and σ behind (finite: only those that exist).
std::string rest_axis_statements(int axis, bool finite) {
  const std::string a = kAxisLetters[axis];
  const std::string own = "floor(p." + a + " / s." + a + " + 0.5)";
  std::string out;
  out += "  c = " + (finite ? "clamp(" + own + ", -l." + a + ", l." + a + ")" : own) + ";\n";
  out += "  u = p." + a + " - s." + a + " * c;\n";
  out += "  g = u >= 0.0 ? 1.0 : -1.0;\n";
  out += "  e = max(max(lo." + a + " + 2.0 * g * s." + a + " - u, u - (hi." + a + " + 2.0 * g * s." + a + ")), 0.0);\n";
  out += std::string("  ") + (finite ? "if (abs(c + 2.0 * g) <= l." + a + ") " : "") + "r = min(r, e * e);\n";
  out += "  e = max(max(lo." + a + " - g * s." + a + " - u, u - (hi." + a + " - g * s." + a + ")), 0.0);\n";
  out += std::string("  ") + (finite ? "if (abs(c - g) <= l." + a + ") " : "") + "r = min(r, e * e);\n";
  return out;
}

std::string repeat_point_text(const std::string& function, AxisSet axes, bool finite) {
  std::string out = "vec3 " + function + "(vec3 p, vec3 s" + (finite ? ", vec3 l" : "") + ") {\n  vec3 q = p;\n";
  for (int i = 0; i < 3; ++i) {
    if (!axes.has(i)) continue;
    const std::string a = kAxisLetters[i];
    const std::string own = "floor(p." + a + " / s." + a + " + 0.5)";
    out += "  q." + a + " = p." + a + " - s." + a + " * " +
           (finite ? "clamp(" + own + ", -l." + a + ", l." + a + ")" : own) + ";\n";
  }
  return out + "  return q;\n}\n";
}

std::string repeat_safe_text(const std::string& base, AxisSet axes, bool finite) {
  const std::string limits = finite ? ", vec3 l" : "";
  std::string out = "vec3 " + base + "_cell(vec3 p, vec3 s" + limits + ", int cell) {\n  vec3 q = p;\n";
  int bit = 1;
  for (int i = 0; i < 3; ++i) {
    if (!axes.has(i)) continue;
    out += cell_axis_statements(i, bit, finite, bit == 1);
    bit *= 2;
  }
  out += "  return q;\n}\n";
  out += "float " + base + "_rest(vec3 p, vec3 s" + limits +
         ", vec3 lo, vec3 hi) {\n"
         "  float n = 0.0, e = 0.0, r = 3.40282347e+38, c = 0.0, u = 0.0, g = 0.0;\n";
  for (int i = 0; i < 3; ++i) {
    if (axes.has(i)) continue;
    const std::string a = kAxisLetters[i];
    out += "  e = max(max(lo." + a + " - p." + a + ", p." + a + " - hi." + a + "), 0.0);\n  n = n + e * e;\n";
  }
  for (int i = 0; i < 3; ++i) {
    if (axes.has(i)) out += rest_axis_statements(i, finite);
  }
  return out + "  return sqrt(r + n);\n}\n";
}

}  // namespace

std::string AxisSet::letters() const {
  std::string out;
  for (int i = 0; i < 3; ++i) {
    if (has(i)) out += kAxisLetters[i];
  }
  return out;
}

AxisSet axes_of(const Vec3<double>& v) { return AxisSet{v.x != 0, v.y != 0, v.z != 0}; }

std::string twist_glsl(const std::string& prefix) {
  return "vec3 " + prefix +
         "_twist(vec3 p, float k) {\n"
         "  float a = k * p.y;\n"
         "  float c = cos(a);\n"
         "  float s = sin(a);\n"
         "  return vec3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);\n"
         "}\n";
}

std::string twist_bound_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_twist_bound(vec3 p, float k, float d) {\n"
         "  float m = abs(k) * sqrt(p.x * p.x + p.z * p.z);\n"
         "  return 2.0 * d / (m + sqrt(m * m + 4.0 + 4.0 * abs(k) * abs(d)));\n"
         "}\n";
}

std::string bend_glsl(const std::string& prefix) {
  return "vec3 " + prefix +
         "_bend(vec3 p, float k) {\n"
         "  float a = k * p.x;\n"
         "  float c = cos(a);\n"
         "  float s = sin(a);\n"
         "  return vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);\n"
         "}\n";
}

std::string bend_bound_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_bend_bound(vec3 p, float k, float d) {\n"
         "  float m = 1.0 + abs(k) * sqrt(p.x * p.x + p.y * p.y);\n"
         "  return 2.0 * d / (m + sqrt(m * m + 4.0 * abs(k) * abs(d)));\n"
         "}\n";
}

std::string round_glsl(const std::string& prefix) {
  return "float " + prefix + "_round(float d, float r) {\n  return d - r;\n}\n";
}

std::string elongate_glsl(const std::string& prefix) {
  return "vec3 " + prefix + "_elongate(vec3 p, vec3 h) {\n  return p - clamp(p, -h, h);\n}\n";
}

std::string elongate_bound_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_elongate_bound(vec3 p, vec3 h, float d) {\n"
         "  vec3 q = abs(p) - h;\n"
         "  return d < 0.0 ? d + min(max(q.x, max(q.y, q.z)), 0.0) : d;\n"
         "}\n";
}

std::string symmetry_glsl(const std::string& prefix, AxisSet axes) {
  std::string out = "vec3 " + prefix + "_symmetry_" + axes.letters() + "(vec3 p) {\n  return vec3(";
  for (int i = 0; i < 3; ++i) {
    const std::string c = std::string("p.") + kAxisLetters[i];
    out += (i > 0 ? ", " : "") + (axes.has(i) ? "abs(" + c + ")" : c);
  }
  return out + ");\n}\n";
}

std::string repeat_glsl(const std::string& prefix, AxisSet axes) {
  return repeat_point_text(prefix + "_repeat_" + axes.letters(), axes, false);
}

std::string repeat_safe_glsl(const std::string& prefix, AxisSet axes) {
  return repeat_safe_text(prefix + "_repeat_" + axes.letters(), axes, false);
}

std::string repeat_finite_glsl(const std::string& prefix, AxisSet axes) {
  return repeat_point_text(prefix + "_repeat_finite_" + axes.letters(), axes, true);
}

std::string repeat_finite_safe_glsl(const std::string& prefix, AxisSet axes) {
  return repeat_safe_text(prefix + "_repeat_finite_" + axes.letters(), axes, true);
}

void check_repetition_box(const Vec3<double>& lo, const Vec3<double>& hi, const Vec3<double>& period, AxisSet axes,
                          const std::string& field) {
  using domain_detail::component;
  for (int i = 0; i < 3; ++i) {
    if (!axes.has(i)) continue;
    const double a = component(lo, i), b = component(hi, i), s = component(period, i);
    const std::string axis = kAxisLetters[i];
    if (!std::isfinite(a) || !std::isfinite(b)) {
      throw InputError("unbounded_child", "safe repetition along " + axis + " needs a child bounded along " + axis +
                                              " (its copies are kept apart by their bounding boxes); this one is "
                                              "unbounded there, or its box depends on a uniform")
          .in_field(field);
    }
    if (!(-s < a && b < s)) {
      throw InputError("repetition_overlap",
                       "safe repetition along " + axis + ": the child's bounding box [" + std::to_string(a) + ", " +
                           std::to_string(b) + "] must lie inside (-period, period) = (" + std::to_string(-s) + ", " +
                           std::to_string(s) + "), or copies beyond the neighbour cell could contain a point")
          .in_field(field);
    }
  }
}

std::string displace_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_displace(vec3 p, float a, float w, float d) {\n"
         "  return d + a * sin(w * p.x) * sin(w * p.y) * sin(w * p.z);\n"
         "}\n";
}

std::string displace_bound_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_displace_bound(vec3 p, float a, float w, float d) {\n"
         "  return (d + a * sin(w * p.x) * sin(w * p.y) * sin(w * p.z)) / (1.0 + abs(a * w));\n"
         "}\n";
}

// ---------------------------------------------------------------------------------
// The domain operators as scene nodes (the proofs are in domain_operators.hpp).

namespace {

using V = Vec3<double>;

// Twist and bend. Safe: the child's value over the local Lipschitz constant of the
// warp, a bound (not 1-Lipschitz); fast: the child at the warped point, which can
// overshoot by that constant.
void classify_warp(NodeCompilation& c) { c.out.node_class = bound_or_weaker(c); }

// The warp keeps the coordinate along its axis (twist: y, bend: z) and the distance ρ
// to that axis: the solid lies within the largest ρ of the child's box, for any k.
// The value is the child's at the warped point (fast: at least the distance to the
// rotation-invariant box; safe: divided by L ≥ 1, so not).
NodeBox bound_warp(const NodeCompilation& c, bool twist) {
  const V l = c.child(0).box_lo, h = c.child(0).box_hi;
  const double a = std::max(l.x * l.x, h.x * h.x);
  const double b = twist ? std::max(l.z * l.z, h.z * h.z) : std::max(l.y * l.y, h.y * h.y);
  const double rho = std::sqrt(a + b);
  const bool g = !c.safe() && c.child(0).box_grows;
  if (twist) return {{-rho, l.y, -rho}, {rho, h.y, rho}, g};
  return {{-rho, -rho, l.z}, {rho, rho, h.z}, g};
}

// The GLSL of twist and bend: the child at the warped point, in safe mode over the
// local Lipschitz constant.
std::string emit_warp(SceneGlslWriter& w, const CompiledNode& n, const std::string& p, const std::string& id,
                      const std::string& text, const std::string& bound_text) {
  w.require_helper(id, text);
  const std::string k = w.scalar(n, 0);
  const std::string d = w.child(n, 0, w.point(w.call(id, p + ", " + k), SceneGlslWriter::type(n)));
  if (!w.safe()) return d;
  w.require_helper(id + "_bound", bound_text);
  return w.value(w.call(id + "_bound", p + ", " + k + ", " + d),
                 SceneGlslWriter::type(n) + ": over the local Lipschitz constant");
}

template <typename T>
T evaluate_twist(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const T k = e.slots(n).scalar(0);
  const T d = e.child(n, 0, twist_point(p, k));
  return e.safe() ? twist_bound(p, k, d) : d;
}
NodeBox bound_twist(const NodeCompilation& c) { return bound_warp(c, true); }
std::string emit_twist(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_warp(w, n, p, "twist", twist_glsl(w.prefix()), twist_bound_glsl(w.prefix()));
}

template <typename T>
T evaluate_bend(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const T k = e.slots(n).scalar(0);
  const T d = e.child(n, 0, bend_point(p, k));
  return e.safe() ? bend_bound(p, k, d) : d;
}
NodeBox bound_bend(const NodeCompilation& c) { return bound_warp(c, false); }
std::string emit_bend(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_warp(w, n, p, "bend", bend_glsl(w.prefix()), bend_bound_glsl(w.prefix()));
}

// Round and displace: f − r and (f + δ)/(1 + |aω|) are 1-Lipschitz over a 1-Lipschitz
// child; over a mere bound they bound nothing (a bound's level sets are not offsets).
void classify_offset(NodeCompilation& c, const std::string& name) {
  c.out.node_class = c.children_class();
  if (c.out.node_class == NodeClass::lipschitz) return;
  if (c.safe()) {
    throw InputError("unsafe_operator",
                     "in mode safe " + name +
                         " needs a 1-Lipschitz child (primitives, their transforms and sharp or smooth "
                         "combinations); " +
                         c.path +
                         ".child is only a distance bound (it is or uses an "
                         "implicit or parametric leaf, a twist, a bend or a repetition)")
        .in_field(c.path + ".child");
  }
  c.out.node_class = NodeClass::estimate;
}

void classify_round(NodeCompilation& c) { classify_offset(c, "round"); }
template <typename T>
T evaluate_round(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return round_value(e.child(n, 0, p), e.slots(n).scalar(0));
}
std::string emit_round(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  w.require_helper("round", round_glsl(w.prefix()));
  const std::string d = w.child(n, 0, p);
  return w.value(w.call("round", d + ", " + w.scalar(n, 0)), SceneGlslWriter::type(n));
}

void classify_displace(NodeCompilation& c) {
  classify_offset(c, "displace");
  if (!c.safe()) c.out.node_class = NodeClass::estimate;  // f + δ overshoots by up to 1 + |aω|
}
template <typename T>
T evaluate_displace(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const SlotReader<T> s = e.slots(n);
  const T d = e.child(n, 0, p);
  return e.safe() ? displace_bound(p, s.scalar(0), s.scalar(1), d) : displace_value(p, s.scalar(0), s.scalar(1), d);
}
// f + δ ≤ 0 only where f ≤ |a|; fast f + δ ≥ dist − |a| grows, safe divides.
NodeBox bound_displace(const NodeCompilation& c) {
  if (!c.child(0).box_grows || c.uniform({0})) return {};
  const double a = std::abs(c.value(0).x);
  return {c.child(0).box_lo - cube_corner(a), c.child(0).box_hi + cube_corner(a), !c.safe()};
}
std::string emit_displace(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  const std::string id = w.safe() ? "displace_bound" : "displace";
  w.require_helper(id, w.safe() ? displace_bound_glsl(w.prefix()) : displace_glsl(w.prefix()));
  const std::string d = w.child(n, 0, p);
  return w.value(w.call(id, p + ", " + w.scalar(n, 0) + ", " + w.scalar(n, 1) + ", " + d), SceneGlslWriter::type(n));
}

// A 1-Lipschitz warp keeps both classes.
void classify_elongate(NodeCompilation& c) {
  const V& h = c.value(0);
  if (!(h.x >= 0 && h.y >= 0 && h.z >= 0)) {
    throw InputError("invalid_value", "size must be at least 0 on every axis (GLSL's clamp(p, -h, h) needs h >= 0)")
        .in_field(c.path + ".size");
  }
  c.out.node_class = c.children_class();
}
template <typename T>
T evaluate_elongate(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  const Vec3<T> h = e.slots(n).vector(0);
  const T d = e.child(n, 0, elongate_point(p, h));
  return e.safe() ? elongate_bound(p, h, d) : d;
}
// p = e(p) + clamp(p, −h, h): the child's box plus [−h, h]; and
// dist(p, box ⊕ [−h, h]) ≤ dist(e(p), box).
NodeBox bound_elongate(const NodeCompilation& c) {
  if (c.uniform({0})) return {};
  return child_grows_box(c, c.child(0).box_lo - c.value(0), c.child(0).box_hi + c.value(0));
}
std::string emit_elongate(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  w.require_helper("elongate", elongate_glsl(w.prefix()));
  const std::string h = w.vector(n, 0);
  const std::string d = w.child(n, 0, w.point(w.call("elongate", p + ", " + h), SceneGlslWriter::type(n)));
  if (!w.safe()) return d;
  w.require_helper("elongate_bound", elongate_bound_glsl(w.prefix()));
  return w.value(w.call("elongate_bound", p + ", " + h + ", " + d),
                 SceneGlslWriter::type(n) + ": deeper inside the core box");
}

// |x| is 1-Lipschitz: both classes kept.
void classify_symmetry(NodeCompilation& c) {
  const V& a = c.value(0);
  for (double x : {a.x, a.y, a.z}) {
    if (x != 0 && x != 1) {
      throw InputError("invalid_value", "axes must be 0 or 1 on every axis (1: mirror that axis)")
          .in_field(c.path + ".axes");
    }
  }
  c.out.node_class = c.children_class();
}
template <typename T>
T evaluate_symmetry(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return e.child(n, 0, mirror_point(p, axes_of(n.slots[0].value)));
}
// |p_i| in the child's range: within the larger of |lo_i|, |hi_i|.
NodeBox bound_symmetry(const NodeCompilation& c) {
  const V l = c.child(0).box_lo, h = c.child(0).box_hi, s = c.value(0);
  const double m[3] = {std::max(-l.x, h.x), std::max(-l.y, h.y), std::max(-l.z, h.z)};
  const V mirrored_lo{s.x != 0 ? -m[0] : l.x, s.y != 0 ? -m[1] : l.y, s.z != 0 ? -m[2] : l.z};
  const V mirrored_hi{s.x != 0 ? m[0] : h.x, s.y != 0 ? m[1] : h.y, s.z != 0 ? m[2] : h.z};
  return child_grows_box(c, mirrored_lo, mirrored_hi);
}
std::string emit_symmetry(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  const AxisSet axes = axes_of(n.slots[0].value);
  const std::string id = "symmetry_" + axes.letters();
  w.require_helper(id, symmetry_glsl(w.prefix(), axes));
  return w.child(n, 0, w.point(w.call(id, p), SceneGlslWriter::type(n)));
}

// Repetition. The copies beyond the evaluated cells are kept apart by the child's box
// in safe mode, checked against the period's default (a uniform's later value is the
// caller's business: where it breaks the condition the value reads 0).
void classify_repetition(NodeCompilation& c, bool finite) {
  const V& period = c.value(0);
  if (!(period.x >= 0 && period.y >= 0 && period.z >= 0)) {
    throw InputError("invalid_value", "period must be at least 0 on every axis (0: not repeated)")
        .in_field(c.path + ".period");
  }
  if (finite) {
    const V& limit = c.value(1);
    for (double x : {limit.x, limit.y, limit.z}) {
      if (!(x >= 0 && x <= kMaxRepeatLimit && x == std::floor(x))) {
        throw InputError("invalid_value", "limit must be an integer from 0 to " +
                                              std::to_string(static_cast<int>(kMaxRepeatLimit)) +
                                              " on every axis (copies -limit..limit)")
            .in_field(c.path + ".limit");
      }
    }
  }
  if (c.safe()) {
    // The box the GLSL states (rounded outwards), with its unbounded sides kept
    // infinite so that they are reported as such.
    const CompiledNode& child = c.child(0);
    const auto stated = [](const V& exact, const Vec3<float>& rounded) {
      const auto pick = [](double e, float r) { return std::isinf(e) ? e : static_cast<double>(r); };
      return V{pick(exact.x, rounded.x), pick(exact.y, rounded.y), pick(exact.z, rounded.z)};
    };
    check_repetition_box(stated(child.box_lo, child.box_lo_float), stated(child.box_hi, child.box_hi_float), period,
                         axes_of(period), c.path + ".child");
  }
  c.out.node_class = bound_or_weaker(c);
}

template <typename T>
T evaluate_repetition(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p, bool finite) {
  const SlotReader<T> s = e.slots(n);
  const AxisSet axes = axes_of(n.slots[0].value);  // structural: from the default
  const Vec3<T> period = s.vector(0);
  if (!e.safe()) {
    return e.child(n, 0, finite ? repeat_finite_point(p, period, s.vector(1), axes) : repeat_point(p, period, axes));
  }
  const CompiledNode& c = e.child_node(n, 0);
  const Vec3<T> lo{c.box_lo_float.x, c.box_lo_float.y, c.box_lo_float.z};
  const Vec3<T> hi{c.box_hi_float.x, c.box_hi_float.y, c.box_hi_float.z};
  const auto inner = [&](const Vec3<T>& q) { return e.child(n, 0, q); };
  return finite ? repeat_finite_bound(p, period, s.vector(1), axes, lo, hi, inner)
                : repeat_bound(p, period, axes, lo, hi, inner);
}

// Fast: the child at the point moved into its cell. Safe: the rest bound, then the
// child in each of the 2^m cells inside one loop, so the child's code is written once
// whatever m.
std::string emit_repetition(SceneGlslWriter& w, const CompiledNode& n, const std::string& p, bool finite) {
  const std::string type = SceneGlslWriter::type(n);
  const AxisSet axes = axes_of(n.slots[0].value);
  const std::string base = (finite ? "repeat_finite_" : "repeat_") + axes.letters();
  const std::string arguments = p + ", " + w.vector(n, 0) + (finite ? ", " + w.vector(n, 1) : "");
  if (!w.safe()) {
    w.require_helper(base, finite ? repeat_finite_glsl(w.prefix(), axes) : repeat_glsl(w.prefix(), axes));
    return w.child(n, 0, w.point(w.call(base, arguments), type));
  }
  w.require_helper(base + "_cell",
                   finite ? repeat_finite_safe_glsl(w.prefix(), axes) : repeat_safe_glsl(w.prefix(), axes));
  w.require_helper(base + "_rest", "");  // defined by the same text
  const CompiledNode& c = w.child_node(n, 0);
  const std::string v =
      w.value(w.call(base + "_rest", arguments + ", " + glsl_vec3(c.box_lo_float) + ", " + glsl_vec3(c.box_hi_float)),
              type + ": the copies beyond the evaluated cells");
  const std::string cell = w.counter();
  w.statement("  for (int " + cell + " = 0; " + cell + " < " + std::to_string(1 << axes.size()) + "; ++" + cell +
              ") {\n");
  const std::string d = w.child(n, 0, w.point(w.call(base + "_cell", arguments + ", " + cell), type));
  w.statement("  " + v + " = min(" + v + ", " + d + ");\n  }\n");
  return v;
}

void classify_repeat(NodeCompilation& c) { classify_repetition(c, false); }
template <typename T>
T evaluate_repeat(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return evaluate_repetition(e, n, p, false);
}
// Unbounded along the repeated axes; every term of both modes is at least the
// distance to that box.
NodeBox bound_repeat(const NodeCompilation& c) {
  const double inf = CompiledScene::kUnbounded;
  const V l = c.child(0).box_lo, h = c.child(0).box_hi, s = c.value(0);
  return child_grows_box(c, {s.x != 0 ? -inf : l.x, s.y != 0 ? -inf : l.y, s.z != 0 ? -inf : l.z},
                         {s.x != 0 ? inf : h.x, s.y != 0 ? inf : h.y, s.z != 0 ? inf : h.z});
}
std::string emit_repeat(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_repetition(w, n, p, false);
}

void classify_repeat_finite(NodeCompilation& c) { classify_repetition(c, true); }
template <typename T>
T evaluate_repeat_finite(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return evaluate_repetition(e, n, p, true);
}
// The child's box swept over the copies −l..l.
NodeBox bound_repeat_finite(const NodeCompilation& c) {
  if (c.uniform({0})) return {};
  const V reach = c.value(0) * c.value(1);
  return child_grows_box(c, c.child(0).box_lo - reach, c.child(0).box_hi + reach);
}
std::string emit_repeat_finite(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  return emit_repetition(w, n, p, true);
}

}  // namespace

const NodeOperations kTwistOperations = {classify_warp, bound_twist, evaluate_twist<float>, evaluate_twist<double>,
                                         emit_twist};
const NodeOperations kBendOperations = {classify_warp, bound_bend, evaluate_bend<float>, evaluate_bend<double>,
                                        emit_bend};
const NodeOperations kRoundOperations = {classify_round, offset_child_box, evaluate_round<float>,
                                         evaluate_round<double>, emit_round};
const NodeOperations kElongateOperations = {classify_elongate, bound_elongate, evaluate_elongate<float>,
                                            evaluate_elongate<double>, emit_elongate};
const NodeOperations kSymmetryOperations = {classify_symmetry, bound_symmetry, evaluate_symmetry<float>,
                                            evaluate_symmetry<double>, emit_symmetry};
const NodeOperations kRepeatOperations = {classify_repeat, bound_repeat, evaluate_repeat<float>,
                                          evaluate_repeat<double>, emit_repeat};
const NodeOperations kRepeatFiniteOperations = {classify_repeat_finite, bound_repeat_finite,
                                                evaluate_repeat_finite<float>, evaluate_repeat_finite<double>,
                                                emit_repeat_finite};
const NodeOperations kDisplaceOperations = {classify_displace, bound_displace, evaluate_displace<float>,
                                            evaluate_displace<double>, emit_displace};

}  // namespace implicitizer
