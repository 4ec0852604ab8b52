#pragma once
/// \file
/// The pinhole camera of the first thesis (000, §2.1.2 and its shader): an eye looking
/// at a target, with the view-up vector fixing the image's vertical, and a focal
/// distance between the eye and an image plane whose height is 1. A pixel's centre
/// maps to uv = (pixel − resolution/2) / height, the ray's direction to
/// normalize(uv.x·right + uv.y·up + focal·forward).
///
/// The thesis' text multiplies uv by 2 (an image plane of height 2, a 90° vertical
/// field of view at focal distance 1); its shader does not, and its pictures come
/// from the shader: with focal distance 1 the vertical field of view is
/// 2·atan(1/2) ≈ 53.13°. We follow the shader.

#include <array>
#include <cstddef>

namespace implicitizer {

/// A ray o + t·d, t ≥ 0, with |d| = 1 (so that t is a distance).
struct Ray {
  std::array<double, 3> origin{};     ///< o
  std::array<double, 3> direction{};  ///< d, unit length
};

/// Where the camera is and what it looks at (world coordinates).
struct CameraSpec {
  std::array<double, 3> eye{3, 3, 5};     ///< the seed's eye
  std::array<double, 3> target{0, 0, 0};  ///< the look-at point (the seed's origin)
  std::array<double, 3> up{0, 1, 0};      ///< the view-up vector (need not be unit)
  double focal_distance = 1;              ///< eye to image plane; the plane has height 1
};

/// A camera ready to generate rays: an orthonormal frame and the image size.
class Camera {
 public:
  /// Builds the frame of `spec` for a width×height image. Throws InputError
  /// `invalid_camera` (field "eye", "up" or "focal_distance") when eye == target,
  /// when up is zero or parallel to the viewing direction, when the focal distance
  /// is not positive and finite, or when a coordinate is not finite; and
  /// `invalid_size` (field "size") when width or height is 0.
  Camera(const CameraSpec& spec, std::size_t width, std::size_t height);

  /// The primary ray through the point (px, py) of the image, in pixels: (0, 0) is
  /// the top-left corner of the top-left pixel, (width, height) the bottom-right
  /// corner, so a pixel's centre is (i + 0.5, j + 0.5). Row 0 is the top of the image.
  Ray ray_through(double px, double py) const;

  /// The vertical field of view in degrees: 2·atan(1 / (2·focal)).
  double vertical_fov_degrees() const;

  /// The specification the camera was built from.
  const CameraSpec& spec() const { return spec_; }
  /// Image width in pixels.
  std::size_t width() const { return width_; }
  /// Image height in pixels.
  std::size_t height() const { return height_; }
  /// The unit vectors of the view frame: right, up (on the image), forward.
  const std::array<double, 3>& right() const { return right_; }
  /// See right().
  const std::array<double, 3>& up() const { return up_; }
  /// See right().
  const std::array<double, 3>& forward() const { return forward_; }

 private:
  CameraSpec spec_;
  std::size_t width_, height_;
  std::array<double, 3> right_{}, up_{}, forward_{};
};

}  // namespace implicitizer
