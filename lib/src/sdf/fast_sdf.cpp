#include "implicitizer/sdf/fast_sdf.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace implicitizer {

FastSdf FastSdf::build(const Polynomial& f, const SceneBox& box, const Budget& budget, SdfShape shape,
                       FastSheetOptions sheet) {
  if (shape == SdfShape::automatic) throw std::invalid_argument("FastSdf::build: decide the shape first");
  FastSdf sdf;
  sdf.shape_ = shape;
  sdf.frame_ = make_scene_frame(box);
  const Polynomial g = frame_polynomial(f, sdf.frame_, budget);
  sdf.program_ = PolynomialProgram::compile(g);
  // The centre and scale are floats already (SceneFrame's invariant): exact here.
  for (std::size_t i = 0; i < 3; ++i) {
    sdf.centre_[i] = to_mpq(sdf.frame_.centre[i]).get_d();
    sdf.centre_float_[i] = static_cast<float>(sdf.centre_[i]);
  }
  sdf.scale_ = to_mpq(sdf.frame_.scale).get_d();
  sdf.scale_float_ = static_cast<float>(sdf.scale_);
  sdf.half_extent_ = 1 / sdf.scale_;
  sdf.half_extent_float_ = static_cast<float>(sdf.half_extent_);
  if (shape == SdfShape::sheet && sheet.cap > 0) {
    sdf.cap_float_ = static_cast<float>(sheet.cap * sdf.half_extent_);
    sdf.cap_ = sdf.cap_float_;
  }
  if (shape == SdfShape::sheet && sheet.zero_where_untrusted) {
    // The radial majorant: Ĝ(|u|) <= Σ_k S_k·r^k, S_k the sum of |g_α| over the terms of
    // degree k and r = max|u_i| (each monomial of degree k is at most r^k), times
    // kTrustFactor·γ_m so that the program compares |∇G| with it directly; each S_k
    // rounded up, and 2^-10 more for the float evaluation of the majorant itself.
    // The sums run over all of G's terms, also those the program drops as below its
    // resolution (a larger majorant, never a smaller one), so by G's own degree. A sum
    // beyond float's range is stated as the largest float: the estimate is then never
    // trusted there, and the cover stands alone.
    const double m = 2.0 * sdf.program_.degree() + 4, eps = 0x1p-23;
    const double factor = kTrustFactor * m * eps / (1 - m * eps) * (1 + 0x1p-10);
    const auto total_degree = [&](std::size_t t) {
      std::int32_t k = 0;
      for (const std::int32_t e : g.exponents(t)) k += e;
      return static_cast<std::size_t>(k);
    };
    std::size_t degree = 0;
    for (std::size_t t = 0; t < g.num_terms(); ++t) degree = std::max(degree, total_degree(t));
    std::vector<double> sums(degree + 1, 0.0);
    for (std::size_t t = 0; t < g.num_terms(); ++t) {
      sums[total_degree(t)] += std::abs(to_mpq(g.coefficient(t)).get_d()) * (1 + 0x1p-50);
    }
    constexpr float kLargest = std::numeric_limits<float>::max();
    for (const double s : sums) {
      const double scaled = s * factor;
      sdf.trust_float_.push_back(std::isfinite(scaled) && scaled < kLargest
                                     ? std::min(round_up<float>(to_rational(mpq_class(scaled))), kLargest)
                                     : kLargest);
    }
    sdf.trust_.assign(sdf.trust_float_.begin(), sdf.trust_float_.end());
  }
  return sdf;
}

std::string FastSdf::to_glsl(const std::string& function) const {
  const std::string s = format_glsl_float(scale_float_);
  const std::string far = format_glsl_float(static_cast<float>(kFarField));
  const bool sheet = shape_ == SdfShape::sheet;
  std::string out;
  out += "// " + function + ": fast distance estimate F/|grad F| (first order, not a bound) of the\n";
  out += "// degree-" + std::to_string(program_.degree()) + " surface F = 0, " +
         (sheet ? "as a sheet (>= 0, 0 on the surface)" : "negative where F < 0") +
         "; evaluated in the frame u = (p - c) * s\n";
  out += "// of the scene box, with |u| <= " + format_glsl_float(static_cast<float>(kFarField)) +
         " (farther: the distance to the box). See docs/sdf.md.\n";
  out += "float " + function + "(vec3 p) {\n";
  const char* axes[3] = {"x", "y", "z"};
  const char* names[3] = {"u", "v", "w"};
  for (std::size_t i = 0; i < 3; ++i) {
    out += std::string("  float ") + names[i] + " = (p." + axes[i] + " - " + format_glsl_float(centre_float_[i]) +
           ") * " + s + ";\n";
  }
  out += "  float qu = abs(u) - 1.0, qv = abs(v) - 1.0, qw = abs(w) - 1.0;\n";
  out += "  float du = max(qu, 0.0), dv = max(qv, 0.0), dw = max(qw, 0.0);\n";
  out += "  float box = (sqrt(du * du + dv * dv + dw * dw) + min(max(qu, max(qv, qw)), 0.0)) * " +
         format_glsl_float(half_extent_float_) + ";\n";
  out += "  if (max(abs(u), max(abs(v), abs(w))) > " + far + ") {\n";
  out += "    return box;\n";
  out += "  }\n";
  out += program_.to_glsl("  ");
  if (!trust_float_.empty()) {
    // The radial majorant by Horner in r (FastSheetOptions::zero_where_untrusted).
    std::string majorant = format_glsl_float(trust_float_.back());
    for (std::size_t k = trust_float_.size() - 1; k-- > 0;) {
      majorant = "(" + majorant + ") * r + " + format_glsl_float(trust_float_[k]);
    }
    out += "  float r = max(abs(u), max(abs(v), abs(w)));\n";
    out += "  float len = sqrt(gu * gu + gv * gv + gw * gw);\n";
    out += "  float d = len >= " + majorant + " ? g / max(len, " +
           format_glsl_float(static_cast<float>(kGradientFloor)) + ") * " + format_glsl_float(half_extent_float_) +
           " : 0.0;\n";
  } else {
    out += "  float d = g / max(sqrt(gu * gu + gv * gv + gw * gw), " +
           format_glsl_float(static_cast<float>(kGradientFloor)) + ") * " + format_glsl_float(half_extent_float_) +
           ";\n";
  }
  if (!sheet) {
    out += "  return max(d, box);\n";
  } else if (cap_ > 0) {
    out += "  return max(min(abs(d), " + format_glsl_float(cap_float_) + "), box);\n";
  } else {
    out += "  return max(abs(d), box);\n";
  }
  out += "}\n";
  return out;
}

}  // namespace implicitizer
