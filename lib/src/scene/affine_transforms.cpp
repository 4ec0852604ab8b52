#include "implicitizer/scene/affine_transforms.hpp"

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

}  // namespace implicitizer
