// Tests of lib/src/render/march_ray.cpp: every method against exact root isolation
// on the sphere, the torus and Steiner's surface (hit masks and depths, pixel by
// pixel); the documented behaviour of single rays (out of steps is a counted miss,
// starting inside, grazing, far away, through a singular point); the overlap
// fallback of enhanced sphere tracing; a sheet's crossings are hits in fast mode; the
// refusals.

#include "implicitizer/render/march_ray.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/render/render_image.hpp"
#include "render/render_support.hpp"

namespace implicitizer {
namespace {

using test::implicit_target;

struct Agreement {
  double iou = 0;        // |hit ∩ hit_exact| / |hit ∪ hit_exact|
  std::size_t both = 0;  // pixels both hit
  double depth_p99 = 0;  // 99th percentile of |t − t_exact| / unit over `both`
  double depth_max = 0;  // worst |t − t_exact| / unit
  double within = 0;     // fraction of `both` with |t − t_exact| ≤ 1e-2·unit
  std::size_t out_of_steps = 0;
  double mean_evaluations = 0;
};

Agreement compare(const std::vector<MarchResult>& a, const std::vector<MarchResult>& exact, double unit) {
  Agreement g;
  std::size_t either = 0;
  std::vector<double> errors;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].out_of_steps) ++g.out_of_steps;
    g.mean_evaluations += a[i].evaluations / static_cast<double>(a.size());
    if (a[i].hit || exact[i].hit) ++either;
    if (a[i].hit && exact[i].hit) errors.push_back(std::abs(a[i].t - exact[i].t) / unit);
  }
  g.both = errors.size();
  g.iou = either ? static_cast<double>(g.both) / static_cast<double>(either) : 1;
  if (!errors.empty()) {
    std::sort(errors.begin(), errors.end());
    g.depth_p99 = errors[std::min(errors.size() - 1, errors.size() * 99 / 100)];
    g.depth_max = errors.back();
    g.within = static_cast<double>(std::upper_bound(errors.begin(), errors.end(), 1e-2) - errors.begin()) /
               static_cast<double>(errors.size());
  }
  return g;
}

// Every method, both modes, against exact, at the pixel centres of a 96×96 view:
// masks agree (IoU ≥ 0.97) and 99% of the common hits are within 1e-2·unit of
// exact's depth (the value-based methods stop where f < ε = 1e-4·unit, about
// ε/cos(angle) before the surface), and few rays run out of steps. Newton and
// forward Newton reach this because their steps are checked
// (MarchParams::check_newton_steps); the unchecked algorithms of the second thesis
// are measured in UncheckedNewtonFindsFartherRoots.
TEST(MarchRay, EveryMethodAgreesWithExactOnSphereTorusSteiner) {
  constexpr std::size_t kSize = 96;
  for (const test::NamedSurface& surface : test::agreement_surfaces()) {
    for (SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      const RenderTarget target = implicit_target(surface.equation, surface.box, mode);
      const CameraSpec camera = seed_camera(target);
      const MarchParams params = default_render_march_params(target, camera);
      const auto exact = test::march_pixels(target, camera, kSize, kSize, MarchMethod::exact, params);
      const auto exact_hits = std::count_if(exact.begin(), exact.end(), [](const MarchResult& r) { return r.hit; });
      ASSERT_GT(exact_hits, static_cast<long>(kSize * kSize / 20)) << surface.name << ": the surface fills the view";
      for (MarchMethod method :
           {MarchMethod::sphere, MarchMethod::enhanced, MarchMethod::newton, MarchMethod::forward_newton}) {
        const auto marched = test::march_pixels(target, camera, kSize, kSize, method, params);
        const Agreement g = compare(marched, exact, target.length_unit());
        std::printf(
            "%-8s %-4s %-14s IoU %.4f  both %5zu  depth p99 %.2e max %.2e within %.4f  out of steps %5zu  "
            "evaluations %.1f\n",
            surface.name.c_str(), mode == SdfMode::safe ? "safe" : "fast", to_string(method), g.iou, g.both,
            g.depth_p99, g.depth_max, g.within, g.out_of_steps, g.mean_evaluations);
        EXPECT_GE(g.iou, 0.97) << surface.name << " " << to_string(method);
        EXPECT_GE(g.within, 0.99) << surface.name << " " << to_string(method);
        EXPECT_LE(g.out_of_steps, kSize * kSize / 1000) << surface.name << " " << to_string(method);
      }
    }
  }
}

// The second thesis' Newton marching, unchecked: it agrees with exact on the
// sphere, but on the torus and Steiner's surface it converges to a farther root on
// many rays and stalls on misses. The floors pin what was measured (docs/render.md
// §6), so that the benchmark's "unchecked" rows stay what they claim to be; and the
// checked variant must beat it on these surfaces.
TEST(MarchRay, UncheckedNewtonFindsFartherRoots) {
  constexpr std::size_t kSize = 96;
  for (const test::NamedSurface& surface : test::agreement_surfaces()) {
    const RenderTarget target = implicit_target(surface.equation, surface.box, SdfMode::fast);
    const CameraSpec camera = seed_camera(target);
    const MarchParams checked = default_render_march_params(target, camera);
    MarchParams unchecked = checked;
    unchecked.check_newton_steps = false;
    const auto exact = test::march_pixels(target, camera, kSize, kSize, MarchMethod::exact, checked);
    for (MarchMethod method : {MarchMethod::newton, MarchMethod::forward_newton}) {
      const Agreement thesis =
          compare(test::march_pixels(target, camera, kSize, kSize, method, unchecked), exact, target.length_unit());
      const Agreement ours =
          compare(test::march_pixels(target, camera, kSize, kSize, method, checked), exact, target.length_unit());
      std::printf("%-8s unchecked %-14s IoU %.4f within %.4f out of steps %5zu evaluations %.1f\n",
                  surface.name.c_str(), to_string(method), thesis.iou, thesis.within, thesis.out_of_steps,
                  thesis.mean_evaluations);
      EXPECT_GE(thesis.iou, 0.75) << surface.name << " " << to_string(method);
      EXPECT_GE(thesis.within, 0.6) << surface.name << " " << to_string(method);
      EXPECT_LT(ours.mean_evaluations, thesis.mean_evaluations) << surface.name << " " << to_string(method);
      if (surface.name != "sphere") {
        EXPECT_LT(thesis.within, ours.within) << surface.name << " " << to_string(method);
      }
    }
  }
}

// A sheet (the saddle z = s^2 - t^2 over [-1, 1]^2, a trimmed patch) in fast mode: its
// value is >= 0 on both sides and F/|∇F| is not a bound, so steps jump across it;
// without the sign test of G (SheetCrossing) a third of the saddle's middle was holes.
// Every value-based method now agrees with exact (which skips roots off the patch).
TEST(MarchRay, FastMarchesDoNotStepThroughASheet) {
  SceneNode node;
  node.kind = NodeKind::parametric;
  node.leaf.coordinates = {"s", "t", "s^2-t^2"};
  node.leaf.domain = {{Rational(-1), Rational(1)}, {Rational(-1), Rational(1)}};
  const RenderTarget saddle = RenderTarget::compile(node, SceneParams{});
  ASSERT_EQ(saddle.shape(), SdfShape::sheet);
  constexpr std::size_t kSize = 64;
  const CameraSpec camera = default_camera(saddle);
  const MarchParams params = default_render_march_params(saddle, camera);
  const auto exact = test::march_pixels(saddle, camera, kSize, kSize, MarchMethod::exact, params);
  std::size_t exact_hits = 0;
  for (const MarchResult& r : exact) exact_hits += r.hit;
  EXPECT_GT(exact_hits, kSize * kSize / 8);
  for (MarchMethod method : {MarchMethod::sphere, MarchMethod::enhanced, MarchMethod::newton}) {
    const Agreement g =
        compare(test::march_pixels(saddle, camera, kSize, kSize, method, params), exact, saddle.length_unit());
    EXPECT_GE(g.iou, 0.99) << to_string(method);
    EXPECT_GE(g.within, 0.99) << to_string(method);
  }
}

// Shape auto orients a solid so that its inside is the enclosed region: 1 − x² − y² − z²
// is negative on the box's faces, so the leaf's value is that of −F. The exact method
// tests the sign of G where the ray enters the box: G must be −F's, else the whole
// box would read as inside and every ray would hit where it enters (t = 3 here).
TEST(MarchRay, ExactFollowsANegatedSolid) {
  SceneNode node = test::implicit_node("1-x^2-y^2-z^2");
  node.leaf.shape = SdfShape::automatic;
  const RenderTarget ball = RenderTarget::compile(node, SceneParams{});
  ASSERT_EQ(ball.shape(), SdfShape::solid);
  const Ray down{{0, 0, 5}, {0, 0, -1}};
  const MarchParams params = default_march_params(ball);
  const MarchResult exact = march_ray(ball, down, MarchMethod::exact, params);
  ASSERT_TRUE(exact.hit);
  EXPECT_NEAR(exact.t, 4, 1e-9);
  const MarchResult sphere = march_ray(ball, down, MarchMethod::sphere, params);
  ASSERT_TRUE(sphere.hit);
  EXPECT_NEAR(sphere.t, 4, 1e-3);
}

// Enhanced sphere tracing costs no more than sphere tracing on these surfaces.
TEST(MarchRay, EnhancedSpendsNoMoreEvaluationsThanSphere) {
  for (const test::NamedSurface& surface : test::agreement_surfaces()) {
    const RenderTarget target = implicit_target(surface.equation, surface.box);
    const CameraSpec camera = seed_camera(target);
    const MarchParams params = default_render_march_params(target, camera);
    auto total = [&](MarchMethod method) {
      std::uint64_t sum = 0;
      for (const MarchResult& r : test::march_pixels(target, camera, 64, 64, method, params)) sum += r.evaluations;
      return sum;
    };
    EXPECT_LE(total(MarchMethod::enhanced), total(MarchMethod::sphere)) << surface.name;
  }
}

Ray make_ray(std::array<double, 3> origin, std::array<double, 3> direction) {
  const double n = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  return Ray{origin, {direction[0] / n, direction[1] / n, direction[2] / n}};
}

constexpr MarchMethod kAllMethods[] = {MarchMethod::sphere, MarchMethod::enhanced, MarchMethod::newton,
                                       MarchMethod::forward_newton, MarchMethod::exact};

TEST(MarchRay, RunningOutOfStepsIsACountedMiss) {
  const RenderTarget target = implicit_target("x^2+y^2+z^2-1");
  MarchParams params = default_march_params(target);
  const Ray ray = make_ray({0.3, 0.2, 5}, {0, 0, -1});  // hits near t = 4
  ASSERT_TRUE(march_ray(target, ray, MarchMethod::sphere, params).hit);
  params.max_steps = 2;
  for (MarchMethod method : {MarchMethod::sphere, MarchMethod::enhanced, MarchMethod::newton}) {
    const MarchResult r = march_ray(target, ray, method, params);
    EXPECT_FALSE(r.hit) << to_string(method);
    EXPECT_TRUE(r.out_of_steps) << to_string(method);
    EXPECT_EQ(r.steps, 2u) << to_string(method);
  }
}

TEST(MarchRay, ARayStartingInsideHitsWhereItStarts) {
  const RenderTarget target = implicit_target("x^2+y^2+z^2-1");
  const MarchParams params = default_march_params(target);
  for (MarchMethod method : kAllMethods) {
    const MarchResult r = march_ray(target, make_ray({0.1, 0, 0.2}, {1, 2, 3}), method, params);
    EXPECT_TRUE(r.hit) << to_string(method);
    EXPECT_EQ(r.t, 0) << to_string(method);
    EXPECT_LE(r.evaluations, 1u) << to_string(method);
  }
}

TEST(MarchRay, ARayFromAMillionAwayFindsTheSphere) {
  const RenderTarget target = implicit_target("x^2+y^2+z^2-1");
  MarchParams params = default_march_params(target);
  params.t_max = 2e6;
  const Ray ray = make_ray({0, 0, 1e6}, {0, 0, -1});
  for (MarchMethod method : kAllMethods) {
    const MarchResult r = march_ray(target, ray, method, params);
    ASSERT_TRUE(r.hit) << to_string(method);
    EXPECT_NEAR(r.t, 1e6 - 1, 1e-3) << to_string(method);
    EXPECT_LE(r.evaluations, 40u) << to_string(method);
  }
  // With the default t_max (100 from the origin of the ray) it is a miss, not a hit.
  EXPECT_FALSE(march_ray(target, ray, MarchMethod::sphere, default_march_params(target)).hit);
}

// A ray passing 1e-6 outside the unit sphere: sphere tracing counts it a hit (it
// comes within ε of the surface), exact does not (no real root); a ray tangent to
// the sphere is a double root, which exact isolates (square-free part).
TEST(MarchRay, GrazingRays) {
  const RenderTarget target = implicit_target("x^2+y^2+z^2-1");
  const MarchParams params = default_march_params(target);
  const Ray near_miss = make_ray({1 + 1e-6, 0, 3}, {0, 0, -1});
  const MarchResult traced = march_ray(target, near_miss, MarchMethod::sphere, params);
  EXPECT_TRUE(traced.hit);
  EXPECT_NEAR(traced.t, 3, 0.05);
  EXPECT_FALSE(march_ray(target, near_miss, MarchMethod::exact, params).hit);
  const MarchResult tangent = march_ray(target, make_ray({1, 0, 3}, {0, 0, -1}), MarchMethod::exact, params);
  ASSERT_TRUE(tangent.hit);
  EXPECT_NEAR(tangent.t, 3, 1e-9);
}

// Rays through singular points: the cone's apex (a double root of the ray) and the
// handle of Whitney's umbrella x² − y²z = 0 (the z-axis below 0, where the ray
// only touches the surface). The fast estimate behaves like a multiple of the
// distance there, so sphere tracing converges geometrically; exact isolates the
// double root.
TEST(MarchRay, RaysThroughSingularPoints) {
  struct Case {
    const char* equation;
    Ray ray;
    double t;
  };
  const Case cases[] = {{"x^2+y^2-z^2", make_ray({3, 0, 1}, {-3, 0, -1}), std::sqrt(10.0)},
                        {"x^2-y^2*z", make_ray({1, 0, -1}, {-1, 0, 0}), 1}};
  for (const Case& c : cases) {
    const RenderTarget target = implicit_target(c.equation);
    const MarchParams params = default_march_params(target);
    for (MarchMethod method : {MarchMethod::sphere, MarchMethod::enhanced, MarchMethod::exact}) {
      const MarchResult r = march_ray(target, c.ray, method, params);
      ASSERT_TRUE(r.hit) << c.equation << " " << to_string(method);
      EXPECT_NEAR(r.t, c.t, 1e-3) << c.equation << " " << to_string(method);
      EXPECT_FALSE(r.out_of_steps);
    }
  }
}

// The overlap check: with ω = 1.9 the first relaxed step from z = 5 towards the
// unit sphere (an exact distance: the `sphere` primitive) lands at z = −2.6,
// beyond the sphere; the check sees that the two unbounding intervals leave a gap
// and steps back, so the ray still hits the near side.
TEST(MarchRay, EnhancedStepsBackWhenARelaxedStepJumpsTheSurface) {
  const RenderTarget target = RenderTarget::compile(make_node(NodeKind::sphere, {{"radius", 1.0}}), SceneParams{});
  MarchParams params = default_march_params(target);
  params.omega = 1.9;
  const MarchResult r = march_ray(target, make_ray({0, 0, 5}, {0, 0, -1}), MarchMethod::enhanced, params);
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.t, 4, 1e-3);
}

TEST(MarchRay, ExactNeedsAnAlgebraicSurface) {
  const RenderTarget scene = RenderTarget::compile(
      make_node(NodeKind::csg_union, {}, {make_node(NodeKind::sphere, {{"radius", 1.0}}), test::implicit_node("z")}),
      SceneParams{});
  EXPECT_FALSE(is_method_applicable(MarchMethod::exact, scene));
  EXPECT_TRUE(is_method_applicable(MarchMethod::sphere, scene));
  try {
    march_ray(scene, make_ray({0, 0, 5}, {0, 0, -1}), MarchMethod::exact, default_march_params(scene));
    ADD_FAILURE() << "exact marched a union";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "method_not_applicable");
    EXPECT_EQ(e.field(), "method");
  }
  EXPECT_TRUE(march_ray(scene, make_ray({0, 0, 5}, {0, 0, -1}), MarchMethod::sphere, default_march_params(scene)).hit);
}

TEST(MarchRay, MethodNames) {
  for (MarchMethod method : kAllMethods) EXPECT_EQ(parse_march_method(to_string(method)), method);
  try {
    parse_march_method("bisection");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "invalid_value");
    EXPECT_EQ(e.field(), "method");
  }
}

}  // namespace
}  // namespace implicitizer
