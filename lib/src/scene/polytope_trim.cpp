#include "implicitizer/scene/polytope_trim.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "implicitizer/sdf/polynomial_program.hpp"

namespace implicitizer {

PolytopeTrim::PolytopeTrim(const TrimPolytope& polytope, const PatchBounds& box) {
  const std::size_t planes = polytope.normals.size();
  if (planes == 0 || planes > kMaxPlanes || polytope.offsets.size() != planes || box.lo.size() != 3) {
    throw std::invalid_argument("PolytopeTrim: 1 to 12 planes and a box in space expected");
  }
  lo_ = {round_down<float>(box.lo[0]), round_down<float>(box.lo[1]), round_down<float>(box.lo[2])};
  hi_ = {round_up<float>(box.hi[0]), round_up<float>(box.hi[1]), round_up<float>(box.hi[2])};
  centre_ = {lo_.x / 2 + hi_.x / 2, lo_.y / 2 + hi_.y / 2, lo_.z / 2 + hi_.z / 2};
  const std::array<double, 3> c{centre_.x, centre_.y, centre_.z};
  // The box's circumradius about c, rounded up generously (a relative 1e-12).
  const std::array<double, 3> lo{lo_.x, lo_.y, lo_.z}, hi{hi_.x, hi_.y, hi_.z};
  double radius = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double side = std::max(hi[i] - c[i], c[i] - lo[i]);
    radius += side * side;
  }
  radius = std::sqrt(radius) * (1 + 1e-12);
  for (std::size_t i = 0; i < planes; ++i) {
    const std::array<double, 3>& n = polytope.normals[i];
    normals_.push_back({float(n[0]), float(n[1]), float(n[2])});
    const double moved = n[0] * c[0] + n[1] * c[1] + n[2] * c[2];
    const double rounding = std::sqrt((double(normals_[i].x) - n[0]) * (double(normals_[i].x) - n[0]) +
                                      (double(normals_[i].y) - n[1]) * (double(normals_[i].y) - n[1]) +
                                      (double(normals_[i].z) - n[2]) * (double(normals_[i].z) - n[2]));
    const double offset = polytope.offsets[i] - moved + rounding * radius +
                          1e-12 * (std::abs(polytope.offsets[i]) + std::abs(moved) + radius);
    offsets_.push_back(std::nextafter(float(offset), std::numeric_limits<float>::infinity()));
    largest_offset_ = std::max(largest_offset_, std::abs(offsets_[i]));
  }
  while (normals_.size() % 3 != 0) {
    normals_.push_back(normals_.back());
    offsets_.push_back(offsets_.back());
  }
}

namespace {

std::string vec3_text(const Vec3<float>& v) {
  return "vec3(" + format_glsl_float(v.x) + ", " + format_glsl_float(v.y) + ", " + format_glsl_float(v.z) + ")";
}

std::string box_overshoot(const Vec3<float>& lo, const Vec3<float>& hi, const std::string& p, double clamp) {
  return "min(max(max(" + vec3_text(lo) + " - " + p + ", " + p + " - " + vec3_text(hi) + "), 0.0), " +
         format_glsl_float(float(clamp)) + ")";
}

// B(p) in GLSL, scaled by `factor` (kShrink, and for the culling test kHullShrink too).
std::string box_bound_glsl(const Vec3<float>& lo, const Vec3<float>& hi, const std::string& p, double clamp,
                           float factor) {
  const std::string m = box_overshoot(lo, hi, p, clamp);
  return "sqrt(dot(" + m + ", " + m + ")) * " + format_glsl_float(factor);
}

}  // namespace

std::string PolytopeTrim::hull_glsl(const std::string& p) const {
  return box_bound_glsl(lo_, hi_, p, kClamp, float(kShrink) * float(PatchCover::kHullShrink));
}

std::string PolytopeTrim::to_glsl(const std::string& function) const {
  // u * mat3(a, b, c) is (u·a, u·b, u·c): the columns are three of the normals.
  const std::size_t groups = normals_.size() / 3;
  std::string out;
  out += "// The piece trimmed to a polytope of " + std::to_string(groups * 3) +
         " planes and its box (lower bounds of the distances, rounded\n";
  out += "// down; see docs/sdf.md); at least |d|.\n";
  out += "float " + function + "(vec3 p, float d) {\n";
  out += "  vec3 u = p - " + vec3_text(centre_) + ";\n";
  std::string largest;
  for (std::size_t g = 0; g < groups; ++g) {
    std::string line = "  vec3 a" + std::to_string(g) + " = u * mat3(";
    for (std::size_t i = 3 * g; i < 3 * g + 3; ++i) {
      line += format_glsl_float(normals_[i].x) + ", " + format_glsl_float(normals_[i].y) + ", " +
              format_glsl_float(normals_[i].z) + (i + 1 < 3 * g + 3 ? ", " : "");
    }
    out += line + ") - " + vec3_text({offsets_[3 * g], offsets_[3 * g + 1], offsets_[3 * g + 2]}) + ";\n";
    const std::string a = "a" + std::to_string(g);
    const std::string group = "max(max(" + a + ".x, " + a + ".y), " + a + ".z)";
    largest = g == 0 ? group : "max(" + largest + ", " + group + ")";
  }
  out += "  float t = (" + largest + " - " + format_glsl_float(float(kSlack)) +
         " * (abs(u.x) + abs(u.y) + abs(u.z) + " + format_glsl_float(largest_offset_) + ")) * " +
         format_glsl_float(float(kShrink)) + ";\n";
  out += "  return max(abs(d), max(t, " + box_bound_glsl(lo_, hi_, "p", kClamp, float(kShrink)) + "));\n";
  out += "}\n";
  return out;
}

}  // namespace implicitizer
