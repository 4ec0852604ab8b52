// Tests of lib/src/render/camera.cpp: the view frame, the rays through pixels, the
// field of view of the first thesis' shader, and the refusals.

#include "implicitizer/render/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

double dot3(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

TEST(Camera, CentreRayLooksAtTheTarget) {
  const Camera camera(CameraSpec{}, 256, 256);
  const Ray ray = camera.ray_through(128, 128);
  EXPECT_EQ(ray.origin, (std::array<double, 3>{3, 3, 5}));
  const double n = std::sqrt(43.0);
  EXPECT_NEAR(ray.direction[0], -3 / n, 1e-15);
  EXPECT_NEAR(ray.direction[1], -3 / n, 1e-15);
  EXPECT_NEAR(ray.direction[2], -5 / n, 1e-15);
}

TEST(Camera, FrameIsOrthonormalAndUpIsUp) {
  const Camera camera(CameraSpec{}, 320, 200);
  for (const auto* v : {&camera.right(), &camera.up(), &camera.forward()}) EXPECT_NEAR(dot3(*v, *v), 1, 1e-15);
  EXPECT_NEAR(dot3(camera.right(), camera.up()), 0, 1e-15);
  EXPECT_NEAR(dot3(camera.right(), camera.forward()), 0, 1e-15);
  EXPECT_NEAR(dot3(camera.up(), camera.forward()), 0, 1e-15);
  // The image's up has a positive world y (view-up (0, 1, 0)); right is horizontal.
  EXPECT_GT(camera.up()[1], 0);
  EXPECT_NEAR(camera.right()[1], 0, 1e-15);
  // Row 0 is the top: its rays point higher than the bottom row's.
  EXPECT_GT(camera.ray_through(160, 0).direction[1], camera.ray_through(160, 200).direction[1]);
  // Column 0 is the left: the ray of the right edge leans further along right().
  EXPECT_GT(dot3(camera.ray_through(320, 100).direction, camera.right()),
            dot3(camera.ray_through(0, 100).direction, camera.right()));
}

TEST(Camera, FieldOfViewIsTheShaders) {
  // uv = (pixel − res/2)/res.y with focal distance 1: the top edge is at v = 1/2.
  const Camera camera(CameraSpec{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 1}, 100, 100);
  EXPECT_NEAR(camera.vertical_fov_degrees(), 2 * std::atan(0.5) * 180 / M_PI, 1e-12);
  const Ray top = camera.ray_through(50, 0);
  const double angle = std::acos(dot3(top.direction, camera.forward())) * 180 / M_PI;
  EXPECT_NEAR(angle, camera.vertical_fov_degrees() / 2, 1e-9);
  // Wider images keep the vertical field of view (normalised by the height).
  const Camera wide(CameraSpec{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 1}, 300, 100);
  EXPECT_NEAR(std::acos(dot3(wide.ray_through(150, 0).direction, wide.forward())) * 180 / M_PI, angle, 1e-9);
}

TEST(Camera, RefusesDegenerateSpecifications) {
  auto code_of = [](const CameraSpec& spec, std::size_t w, std::size_t h) {
    try {
      Camera camera(spec, w, h);
    } catch (const InputError& e) {
      return e.code() + "@" + e.field();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(code_of(CameraSpec{}, 0, 10), "invalid_size@size");
  EXPECT_EQ(code_of(CameraSpec{{1, 2, 3}, {1, 2, 3}, {0, 1, 0}, 1}, 10, 10), "invalid_camera@eye");
  EXPECT_EQ(code_of(CameraSpec{{0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 1}, 10, 10), "invalid_camera@up");
  EXPECT_EQ(code_of(CameraSpec{{0, 0, 5}, {0, 0, 0}, {0, 0, 0}, 1}, 10, 10), "invalid_camera@up");
  EXPECT_EQ(code_of(CameraSpec{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 0}, 10, 10), "invalid_camera@focal_distance");
  EXPECT_EQ(code_of(CameraSpec{{NAN, 0, 5}, {0, 0, 0}, {0, 1, 0}, 1}, 10, 10), "invalid_camera@eye");
  EXPECT_EQ(code_of(CameraSpec{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 1}, 10, 10), "accepted");
}

}  // namespace
}  // namespace implicitizer
