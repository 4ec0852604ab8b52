#include "implicitizer/sdf/safe_sdf.hpp"

#include <cfloat>
#include <limits>
#include <stdexcept>
#include <vector>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

// The float or double nearest to d on the safe side.
template <typename T>
T round_up(double d) {
  T t = static_cast<T>(d);
  if (static_cast<double>(t) < d) t = std::nextafter(t, std::numeric_limits<T>::infinity());
  return t;
}
template <typename T>
T round_down(double d) {
  T t = static_cast<T>(d);
  if (static_cast<double>(t) > d) t = std::nextafter(t, -std::numeric_limits<T>::infinity());
  return t;
}

// (1 - e)^-k - 1 and 1 - (1 + e)^-k, accurate for tiny e (no cancellation).
double grow(double e, double k) { return std::expm1(-k * std::log1p(-e)); }
double shrink(double e, double k) { return -std::expm1(-k * std::log1p(e)); }
// Higham's γ_k = k·e / (1 - k·e): the relative error of k roundings.
double gamma_of(double e, double k) { return k * e / (1 - k * e); }

Rational abs_of(const Rational& q) { return q < Rational(0) ? -q : q; }

// Everything safe_sdf.hpp's Constants hold that depends on the precision: ε, the
// underflow threshold of the arithmetic. Derivations in docs/sdf.md §6.
template <typename T>
SafeSdf::Constants<T> make_constants(const SceneFrame& frame, double box_half, std::int32_t degree,
                                     std::int32_t full_degree, std::size_t dropped, std::size_t steps,
                                     double radius_cap) {
  // One ulp (not half): GLSL ES leaves the rounding mode undefined. The C++
  // evaluator rounds to nearest, so it is covered twice over.
  const double e = std::ldexp(1.0, -std::numeric_limits<T>::digits + 1);
  const double n = degree, m = 2.0 * degree + 4;  // roundings per term of a pass
  // 1 % on top of every relative constant covers the rounding of this double
  // arithmetic itself.
  const double margin = 1.01;
  SafeSdf::Constants<T> k;
  for (std::size_t i = 0; i < 3; ++i) k.centre[i] = static_cast<T>(to_mpq(frame.centre[i]).get_d());
  const mpq_class scale = to_mpq(frame.scale);
  k.scale = static_cast<T>(scale.get_d());
  // mpq's get_d truncates, so 1/s comes out rounded down already.
  k.half_extent = round_down<T>(mpq_class(1 / scale).get_d());
  k.box_half = round_up<T>(box_half);
  // L: sqrt(3)·L·h stays below 2^122 and L² below 2^120.
  k.box_clamp = round_down<T>(std::min(0x1p60, 0x1p120 / static_cast<double>(k.half_extent)));
  k.u_shrink = round_down<T>(1 - 4 * e);
  k.u_grow = round_up<T>(1 + 4 * e);
  k.box_half_inner = round_down<T>(box_half);
  k.u_error = round_up<T>(3 * e * margin);
  k.gamma_value = round_up<T>((gamma_of(e, m) * (1 + grow(e, m)) + 4 * e) * margin);
  k.gamma_gradient = round_up<T>((gamma_of(e, m) * (1 + grow(e, m + 2)) + 4 * e) * margin);
  k.norm_up = round_up<T>(1 + 16 * e);
  // τ: dropped coefficients (each below FLT_MIN, at |x_i| <= 3) and every flushed
  // subnormal (at most the smallest normal, amplified by at most (n + 1)·3^n by
  // the later steps) of the four passes, twice over.
  const double smallest = std::numeric_limits<T>::min();
  const double power = std::pow(3.0, full_degree);
  k.tau = round_up<T>(2 * (static_cast<double>(dropped) * FLT_MIN * power +
                           8.0 * static_cast<double>(steps) * (full_degree + 1) * power * smallest));
  k.minimum_value = static_cast<T>(SafeSdf::kMinimumValue);
  k.radius_cap = static_cast<T>(radius_cap);
  // Γ_X: the Horner pass of Ĝ at x (2n + 3 roundings), the coefficients' rounding
  // (1) and x = a + r rounded down (n, through the degree), plus 10ε for the seven
  // operations that follow (remainder and φ; their operands are all at most about
  // X). Γ_Y: the pass of Ĝ and ∇Ĝ at a (2n + 4), the sum of the partials (2) and
  // Y = Ĝ(a) + r·ΣĜ_i(a) (2), plus 2ε for its product with K_Y.
  k.majorant_up = round_up<T>(1 + (grow(e, 3 * n + 4) + 10 * e) * margin);
  k.majorant_down = round_down<T>(1 - (shrink(e, 2 * n + 8) + 2 * e) * margin);
  k.root_shrink = round_down<T>(1 - 32 * e);
  k.out_shrink = round_down<T>(1 - 16 * e);
  return k;
}

// b: the smallest float >= max_i max(hi_i - c_i, c_i - lo_i)·s, so that the box is
// inside |u_i| <= b although c and s are rounded (b = 1 when they are exact).
double box_half_in_frame(const SceneBox& box, const SceneFrame& frame) {
  Rational largest(0);
  for (std::size_t i = 0; i < 3; ++i) {
    for (const Rational& side : {box.hi[i] - frame.centre[i], frame.centre[i] - box.lo[i]}) {
      const Rational r = abs_of(side) * frame.scale;
      if (r > largest) largest = r;
    }
  }
  const double d = to_mpq(largest).get_d();  // truncated: one ulp up covers it
  return Rational(d) == largest ? d : std::nextafter(d, std::numeric_limits<double>::infinity());
}

}  // namespace

SafeSdf SafeSdf::build(const Polynomial& f, const SceneBox& box, const Budget& budget, SdfShape shape) {
  if (shape == SdfShape::automatic) throw std::invalid_argument("SafeSdf::build: decide the shape first");
  SafeSdf sdf;
  sdf.shape_ = shape;
  sdf.frame_ = make_scene_frame(box);
  const Polynomial g = frame_polynomial(f, sdf.frame_, budget);
  std::vector<Polynomial> absolute_terms;
  absolute_terms.reserve(g.num_terms());
  for (std::size_t t = 0; t < g.num_terms(); ++t) {
    absolute_terms.push_back(Polynomial::term(g.ring(), abs_of(g.coefficient(t)), g.exponents(t)));
  }
  budget.check("safe sdf majorant");
  const Polynomial majorant = sum_of(g.ring(), std::move(absolute_terms));
  sdf.program_ = PolynomialProgram::compile(g);
  sdf.majorant_ = PolynomialProgram::compile(majorant);
  sdf.majorant_value_ = PolynomialProgram::compile(majorant, ProgramOutputs::value);

  // r_cap: halve until Ĝ(2 + r_cap) fits (a double evaluation, 0.1 % margin).
  const auto majorant_at = [&](double x) { return sdf.majorant_value_.evaluate(x, x, x).value * 1.001; };
  if (!(majorant_at(kFarField) <= kMajorantLimit)) {
    throw InputError("degree_too_high", "the safe bound evaluates the polynomial's terms at up to " +
                                            std::to_string(static_cast<int>(kFarField)) +
                                            " box half-sides from the centre, where they exceed fp32's safe "
                                            "range (degree " +
                                            std::to_string(g.total_degree()) + "); use mode fast");
  }
  double radius_cap = kRadiusCap;
  while (!(majorant_at(kFarField + radius_cap) <= kMajorantLimit)) radius_cap /= 2;

  const double box_half = box_half_in_frame(box, sdf.frame_);
  const std::size_t steps = sdf.program_.steps().size();
  sdf.constants_float_ = make_constants<float>(sdf.frame_, box_half, sdf.program_.degree(), g.total_degree(),
                                               sdf.program_.dropped_terms(), steps, radius_cap);
  sdf.constants_double_ = make_constants<double>(sdf.frame_, box_half, sdf.program_.degree(), g.total_degree(),
                                                 sdf.program_.dropped_terms(), steps, radius_cap);
  if (!(sdf.constants_float_.tau < 0x1p-24f)) {
    throw InputError("degree_too_high", "degree " + std::to_string(g.total_degree()) +
                                            " is too high for an fp32 bound: underflow alone could hide "
                                            "|F| of 2^-24 of its largest term; use mode fast");
  }
  return sdf;
}

// One function longer than a screen on purpose: it is the GLSL function, written top
// to bottom as it reads in the shader; split, one shader function would be spread over
// several C++ ones.
std::string SafeSdf::to_glsl(const std::string& function) const {
  const Constants<float>& k = constants_float_;
  const auto f = [](float x) { return format_glsl_float(x); };
  std::string out;
  out += "// " + function + ": safe distance bound of the degree-" + std::to_string(program_.degree()) +
         " surface F = 0 (never more than the\n";
  const bool sheet = shape_ == SdfShape::sheet;
  out += "// distance to the surface inside the box; 0 within fp32's resolution of it), " +
         std::string(sheet ? "as a sheet\n// (>= 0, 0 on the surface)" : "negative\n// where F < 0") +
         "; evaluated in the frame u = (p - c) * s of the scene box, with\n";
  out += "// |u| <= " + f(static_cast<float>(kFarField)) + " (farther: the distance to the box). See docs/sdf.md.\n";
  out += "float " + function + "(vec3 p) {\n";
  const char* axes[3] = {"x", "y", "z"};
  const char* names[3] = {"u", "v", "w"};
  for (std::size_t i = 0; i < 3; ++i) {
    out +=
        std::string("  float ") + names[i] + " = (p." + axes[i] + " - " + f(k.centre[i]) + ") * " + f(k.scale) + ";\n";
  }
  out += "  float abs_u = abs(u), abs_v = abs(v), abs_w = abs(w);\n";
  for (std::size_t i = 0; i < 3; ++i) {
    out += std::string("  float d") + names[i] + " = min(max(abs_" + names[i] + " * " + f(k.u_shrink) + " - " +
           f(k.box_half) + ", 0.0), " + f(k.box_clamp) + ");\n";
  }
  out += "  float box = sqrt(du * du + dv * dv + dw * dw);\n";
  out += "  if (max(abs_u, max(abs_v, abs_w)) > " + f(static_cast<float>(kFarField)) + ") {\n";
  out += "    return box * " + f(k.half_extent) + " * " + f(k.out_shrink) + ";\n";
  out += "  }\n";
  out += "  float g_value, g_u, g_v, g_w;\n";
  out += "  {\n";
  out += program_.to_glsl("    ");
  out += "    g_value = g;\n    g_u = gu;\n    g_v = gv;\n    g_w = gw;\n";
  out += "  }\n";
  out += "  float m_value, m_sum;\n";
  out += "  {\n";
  out += "    float u = abs_u, v = abs_v, w = abs_w;\n";
  out += majorant_.to_glsl("    ");
  out += "    m_value = g;\n    m_sum = gu + gv + gw;\n";
  out += "  }\n";
  out += "  float lower = (abs(g_value) - " + f(k.gamma_value) + " * m_value) - " + f(k.tau) + ";\n";
  out += "  if (!(lower >= " + f(k.minimum_value) + ")) {\n    return box * " + f(k.half_extent) + " * " +
         f(k.out_shrink) + ";\n  }\n";
  out += "  float slope = sqrt(g_u * g_u + g_v * g_v + g_w * g_w) * " + f(k.norm_up) + " + " + f(k.gamma_gradient) +
         " * m_sum;\n";
  out += "  float r = " + f(k.radius_cap) + " * lower / max(slope * " + f(k.radius_cap) + ", lower);\n";
  out += "  float safe = 0.0, right = 0.0, phi_right = 0.0;\n";
  out += "  for (int iteration = 0; iteration <= " + std::to_string(kChordSteps) + "; ++iteration) {\n";
  out += "    float big;\n";
  out += "    {\n";
  out += "      float u = abs_u + r, v = abs_v + r, w = abs_w + r;\n";
  out += majorant_value_.to_glsl("      ");
  out += "      big = g;\n";
  out += "    }\n";
  out += "    float remainder = big * " + f(k.majorant_up) + " - (m_value + r * m_sum) * " + f(k.majorant_down) + ";\n";
  out += "    float phi = (lower - slope * r) - remainder;\n";
  out += "    if (iteration == 0) {\n";
  out += "      if (phi >= 0.0) {\n        safe = r;\n        break;\n      }\n";
  out += "      right = r;\n      phi_right = phi;\n";
  out += "      float b = slope * r / lower;\n";
  out += "      float c = remainder / lower;\n";
  out += "      float t = min(2.0 / (b + sqrt(b * b + 4.0 * c)), 1.0);\n";
  out += "      safe = t * r * " + f(k.root_shrink) + ";\n";
  out += "    } else {\n";
  out += "      if (phi < 0.0) {\n        break;\n      }\n";
  out += "      safe = max(safe, (safe + phi * (right - safe) / (phi - phi_right)) * " + f(k.root_shrink) + ");\n";
  out += "    }\n";
  out += "    r = safe;\n";
  out += "  }\n";
  out += "  float radius = safe - (abs_u + abs_v + abs_w) * " + f(k.u_error) + ";\n";
  out += "  if (!(radius > 0.0)) {\n    return box * " + f(k.half_extent) + " * " + f(k.out_shrink) + ";\n  }\n";
  if (sheet) {
    // Both terms bound the distance to Z ∩ box from below, whatever F's sign.
    out += "  return max(box, radius) * " + f(k.half_extent) + " * " + f(k.out_shrink) + ";\n}\n";
    return out;
  }
  out += "  if (g_value >= 0.0) {\n    return max(box, radius) * " + f(k.half_extent) + " * " + f(k.out_shrink) +
         ";\n  }\n";
  out += "  if (box > 0.0) {\n    return box * " + f(k.half_extent) + " * " + f(k.out_shrink) + ";\n  }\n";
  out +=
      "  float inner = max(" + f(k.box_half_inner) + " - max(abs_u, max(abs_v, abs_w)) * " + f(k.u_grow) + ", 0.0);\n";
  out += "  return -(min(radius, inner) * " + f(k.half_extent) + " * " + f(k.out_shrink) + ");\n";
  out += "}\n";
  return out;
}

}  // namespace implicitizer
