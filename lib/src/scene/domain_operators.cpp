#include "implicitizer/scene/domain_operators.hpp"

#include <cmath>
#include <string>

#include "implicitizer/core/errors.hpp"

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

}  // namespace implicitizer
