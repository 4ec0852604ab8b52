#include "implicitizer/scene/boolean_operators.hpp"

#include "implicitizer/sdf/polynomial_program.hpp"

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

}  // namespace implicitizer
