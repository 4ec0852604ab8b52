#include "implicitizer/sdf/fast_sdf.hpp"

#include <stdexcept>

namespace implicitizer {

FastSdf FastSdf::build(const Polynomial& f, const SceneBox& box, const Budget& budget, SdfShape shape) {
  if (shape == SdfShape::automatic) throw std::invalid_argument("FastSdf::build: decide the shape first");
  FastSdf sdf;
  sdf.shape_ = shape;
  sdf.frame_ = make_scene_frame(box);
  sdf.program_ = PolynomialProgram::compile(frame_polynomial(f, sdf.frame_, budget));
  // The centre and scale are floats already (SceneFrame's invariant): exact here.
  for (std::size_t i = 0; i < 3; ++i) {
    sdf.centre_[i] = to_mpq(sdf.frame_.centre[i]).get_d();
    sdf.centre_float_[i] = static_cast<float>(sdf.centre_[i]);
  }
  sdf.scale_ = to_mpq(sdf.frame_.scale).get_d();
  sdf.scale_float_ = static_cast<float>(sdf.scale_);
  sdf.half_extent_ = 1 / sdf.scale_;
  sdf.half_extent_float_ = static_cast<float>(sdf.half_extent_);
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
  out += "  float d = g / max(sqrt(gu * gu + gv * gv + gw * gw), " +
         format_glsl_float(static_cast<float>(kGradientFloor)) + ") * " + format_glsl_float(half_extent_float_) + ";\n";
  out += sheet ? "  return max(abs(d), box);\n" : "  return max(d, box);\n";
  out += "}\n";
  return out;
}

}  // namespace implicitizer
