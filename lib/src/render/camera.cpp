#include "implicitizer/render/camera.hpp"

#include <cmath>
#include <numbers>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

using V = std::array<double, 3>;

V sub(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V cross(const V& a, const V& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const V& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
V scaled(const V& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
bool is_finite(const V& a) { return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]); }

}  // namespace

Camera::Camera(const CameraSpec& spec, std::size_t width, std::size_t height)
    : spec_(spec), width_(width), height_(height) {
  if (width == 0 || height == 0)
    throw InputError("invalid_size", "the image needs at least one pixel").in_field("size");
  if (!is_finite(spec.eye)) throw InputError("invalid_camera", "the eye must be finite").in_field("eye");
  if (!is_finite(spec.target)) throw InputError("invalid_camera", "the target must be finite").in_field("target");
  if (!is_finite(spec.up)) throw InputError("invalid_camera", "the up vector must be finite").in_field("up");
  if (!(spec.focal_distance > 0) || !std::isfinite(spec.focal_distance)) {
    throw InputError("invalid_camera", "the focal distance must be positive and finite").in_field("focal_distance");
  }
  const V view = sub(spec.target, spec.eye);
  const double view_length = norm(view);
  if (!(view_length > 0) || !std::isfinite(view_length)) {
    throw InputError("invalid_camera", "the eye and the target must be distinct points").in_field("eye");
  }
  forward_ = scaled(view, 1 / view_length);
  // The seed's frame: right = normalize(up × forward) taken with a minus sign so that
  // x grows to the right on screen (its mat3(-cr, cu, -cd) with rd = (u, v, -1)).
  const V side = cross(forward_, spec.up);
  const double side_length = norm(side);
  const double up_length = norm(spec.up);
  // Parallel within 1e-9 radians: the frame would be rounding noise.
  if (!(up_length > 0) || !(side_length > 1e-9 * up_length)) {
    throw InputError("invalid_camera", "the up vector must be nonzero and not parallel to target - eye").in_field("up");
  }
  right_ = scaled(side, 1 / side_length);
  up_ = cross(right_, forward_);
}

Ray Camera::ray_through(double px, double py) const {
  const double h = static_cast<double>(height_);
  const double u = (px - 0.5 * static_cast<double>(width_)) / h;
  const double v = (0.5 * h - py) / h;  // row 0 at the top
  V d{};
  for (int i = 0; i < 3; ++i) d[i] = u * right_[i] + v * up_[i] + spec_.focal_distance * forward_[i];
  Ray ray;
  ray.origin = spec_.eye;
  ray.direction = scaled(d, 1 / norm(d));
  return ray;
}

double Camera::vertical_fov_degrees() const {
  return 2 * std::atan(1 / (2 * spec_.focal_distance)) * 180 / std::numbers::pi;
}

}  // namespace implicitizer
