// Tests of an approximated patch as the renderer draws it (lib/src/render/
// render_target.cpp's side of an approximation, march_ray.cpp's sheet crossings,
// shading.cpp's sides): every example of the page with a domain, at the page's
// default tolerance (1e-3), traced by the default method at the CLI's defaults
// (256×256, one ray a pixel), hits the pixels the exact equation's first root on the
// patch hits (IoU >= 0.98), in both modes, and tells the sides apart as the exact
// sheet does.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "implicitizer/render/march_ray.hpp"
#include "implicitizer/render/render_image.hpp"
#include "implicitizer/render/shading.hpp"
#include "render/render_support.hpp"

namespace implicitizer {
namespace {

struct PageExample {
  std::string name;
  std::array<std::string, 3> xyz;
  std::vector<std::string> parameters;
  std::array<double, 4> domain;
  std::array<double, 6> box;
};

// clients/web/examples.json, the examples with a domain.
const std::vector<PageExample>& page_examples() {
  static const std::vector<PageExample> examples = {
      {"elliptic_paraboloid", {"s^2+t^2", "t", "s"}, {}, {-1, 1, -1, 1}, {-2, -2, -2, 2, 2, 2}},
      {"hyperbolic_paraboloid", {"t", "s", "t^2-s^2"}, {}, {-1, 1, -1, 1}, {-2, -2, -2, 2, 2, 2}},
      {"whitney_umbrella", {"s*t", "s", "t^2"}, {}, {-1, 1, -1, 1}, {-2, -2, -2, 2, 2, 2}},
      {"cylinder_rational", {"(1-s^2)/(1+s^2)", "2*s/(1+s^2)", "t"}, {}, {-2, 2, -1, 1}, {-2, -2, -2, 2, 2, 2}},
      {"cone_rational", {"t*(1-s^2)/(1+s^2)", "t*2*s/(1+s^2)", "t"}, {}, {-2, 2, -1, 1}, {-2, -2, -2, 2, 2, 2}},
      {"enneper", {"s-s^3/3+s*t^2", "t-t^3/3+t*s^2", "s^2-t^2"}, {}, {-1.5, 1.5, -1.5, 1.5}, {-4, -4, -4, 4, 4, 4}},
      {"bicubic_graph", {"s", "t", "s^3*t^3-2*s^2*t+t^3-s"}, {}, {-1, 1, -1, 1}, {-2, -2, -2, 2, 2, 2}},
      {"bicubic_patch", {"s*(1+t^2)/2", "t", "s^3*t-s*t^3"}, {}, {-1, 1, -1, 1}, {-1, -1, -1, 1, 1, 1}},
      {"hyperboloid_cosh",
       {"cosh(u)*cos(v)", "cosh(u)*sin(v)", "sinh(u)"},
       {"u", "v"},
       {-1, 1, -2.5, 2.5},
       {-2, -2, -2, 2, 2, 2}},
  };
  return examples;
}

RenderTarget target_of(const PageExample& e, SdfMode mode, std::optional<double> tolerance) {
  SceneNode node;
  node.kind = NodeKind::parametric;
  node.leaf.coordinates = e.xyz;
  if (!e.parameters.empty()) node.leaf.parameter_names = e.parameters;
  node.leaf.domain = {{Rational(e.domain[0]), Rational(e.domain[1])}, {Rational(e.domain[2]), Rational(e.domain[3])}};
  node.leaf.tolerance = tolerance;
  const SceneBox box = test::axis_box({e.box[0], e.box[1], e.box[2]}, {e.box[3], e.box[4], e.box[5]});
  node.leaf.box = box;
  return RenderTarget::compile(node, SceneParams{mode, box, "t", "scene"});
}

TEST(ApproximatedSheet, PageExamplesAtTheDefaultToleranceHitWhatTheExactEquationHits) {
  constexpr std::size_t kSize = 256;  // the CLI's default size, --aa 1
  for (const PageExample& e : page_examples()) {
    for (const SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      const RenderTarget exact = target_of(e, mode, std::nullopt);
      const RenderTarget approximated = target_of(e, mode, 1e-3);
      const bool is_approximation = approximated.scene().leaves().front().approximation() != nullptr;
      const CameraSpec camera = default_camera(exact);
      const auto reference = test::march_pixels(exact, camera, kSize, kSize, MarchMethod::exact,
                                                default_render_march_params(exact, camera));
      const auto traced = test::march_pixels(approximated, camera, kSize, kSize, MarchMethod::sphere,
                                             default_render_march_params(approximated, camera));
      std::size_t both = 0, either = 0, sides_differ = 0, sides_agree = 0;
      const Camera rays(camera, kSize, kSize);
      for (std::size_t i = 0; i < traced.size(); ++i) {
        if (traced[i].hit || reference[i].hit) ++either;
        if (!(traced[i].hit && reference[i].hit)) continue;
        ++both;
        const Ray ray = rays.ray_through(i % kSize + 0.5, i / kSize + 0.5);
        const auto at = [&](double t) {
          return std::array<double, 3>{ray.origin[0] + t * ray.direction[0], ray.origin[1] + t * ray.direction[1],
                                       ray.origin[2] + t * ray.direction[2]};
        };
        if (surface_side(approximated, at(traced[i].t), ray.direction) !=
            surface_side(exact, at(reference[i].t), ray.direction)) {
          ++sides_differ;
        } else {
          ++sides_agree;
        }
      }
      const double iou = either ? static_cast<double>(both) / static_cast<double>(either) : 1;
      // The sides agree with the exact sheet's up to one flip for the whole picture (q's
      // orientation follows X_s × X_t, F's its implicitization).
      const std::size_t odd = std::min(sides_differ, sides_agree);
      std::printf("%-22s %s: %s, IoU %.4f (%zu of %zu pixels), %zu hits coloured unlike the rest\n", e.name.c_str(),
                  mode == SdfMode::safe ? "safe" : "fast", is_approximation ? "approximated" : "exact kept", iou, both,
                  either, odd);
      EXPECT_GE(iou, 0.98) << e.name << (mode == SdfMode::safe ? " safe" : " fast");
      // Where the pieces leave the exact surface by up to the tolerance, a grazing ray
      // may meet the other side first: a few pixels, not a one-sided picture.
      EXPECT_LE(odd, both / 50) << e.name;
    }
  }
}

}  // namespace
}  // namespace implicitizer
