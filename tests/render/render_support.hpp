#pragma once
// Helpers shared by the tests of tests/render: targets built from an equation, the
// three surfaces the renderer's agreement tests use, and per-pixel marching.

#include <array>
#include <string>
#include <vector>

#include "implicitizer/render/camera.hpp"
#include "implicitizer/render/march_ray.hpp"
#include "implicitizer/render/render_target.hpp"
#include "implicitizer/scene/compiled_scene.hpp"

namespace implicitizer::test {

// The box [lo, hi]^3, or [lo, hi] per axis.
inline SceneBox cube_box(double lo, double hi) {
  SceneBox box;
  for (std::size_t i = 0; i < 3; ++i) {
    box.lo[i] = Rational(lo);
    box.hi[i] = Rational(hi);
  }
  return box;
}

inline SceneBox axis_box(std::array<double, 3> lo, std::array<double, 3> hi) {
  SceneBox box;
  for (std::size_t i = 0; i < 3; ++i) {
    box.lo[i] = Rational(lo[i]);
    box.hi[i] = Rational(hi[i]);
  }
  return box;
}

// An implicit leaf drawn as the solid F <= 0 in its box: these tests measure the
// marchers on solids (shape auto would make a sheet of every surface that touches
// its box, as the torus of agreement_surfaces() does at (3, 0, 0)).
inline SceneNode implicit_node(const std::string& equation) {
  SceneNode node;
  node.kind = NodeKind::implicit;
  node.leaf.equation = equation;
  node.leaf.shape = SdfShape::solid;
  return node;
}

inline RenderTarget implicit_target(const std::string& equation, const SceneBox& box = SceneBox::default_box(),
                                    SdfMode mode = SdfMode::fast,
                                    EvaluationPrecision precision = EvaluationPrecision::single) {
  return RenderTarget::compile(implicit_node(equation), SceneParams{mode, box, "t", "scene"}, precision);
}

// A named surface with a box that frames it.
struct NamedSurface {
  std::string name;
  std::string equation;
  SceneBox box;
};

// The sphere, the torus of radii 2 and 1 (bench torus_R2_r1) and Steiner's Roman
// surface (bench steiner_roman, which lies in [-1/2, 1/2]^3).
inline std::vector<NamedSurface> agreement_surfaces() {
  return {{"sphere", "x^2+y^2+z^2-1", SceneBox::default_box()},
          {"torus", "(x^2+y^2+z^2+3)^2-16*(x^2+y^2)", axis_box({-3, -3, -1}, {3, 3, 1})},
          {"steiner", "x^2*y^2+y^2*z^2+z^2*x^2-x*y*z", cube_box(-0.5, 0.5)}};
}

// One march per pixel centre of a width×height image seen by `spec`.
inline std::vector<MarchResult> march_pixels(const RenderTarget& target, const CameraSpec& spec, std::size_t width,
                                             std::size_t height, MarchMethod method, const MarchParams& params) {
  const Camera camera(spec, width, height);
  std::vector<MarchResult> out;
  out.reserve(width * height);
  for (std::size_t y = 0; y < height; ++y) {
    for (std::size_t x = 0; x < width; ++x) {
      out.push_back(march_ray(target, camera.ray_through(x + 0.5, y + 0.5), method, params));
    }
  }
  return out;
}

}  // namespace implicitizer::test
