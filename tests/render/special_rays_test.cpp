// Single rays where marching is delicate, for every method (sphere, enhanced,
// newton, forward_newton, exact) in both bound modes: a ray tangent to the unit sphere
// and 1e-6 above and below the tangent, rays through singular points (the handle of
// Whitney's umbrella, the apex of the cone), rays from 10^6 away, and rays starting
// inside. The reference is `exact` (root isolation on the polynomial), itself checked
// against the closed-form first root of each ray. docs/render.md, "Special rays",
// states the same behaviour for users.
//
// What every method must do on every ray (the invariants asserted for all):
//  - terminate within its step bound: steps ≤ max_steps, evaluations ≤ 2·max_steps + 1
//    (Newton spends two per step: f and the forward difference);
//  - return a finite t (no NaN), with t_min ≤ t ≤ t_max when it hits;
//  - never report a hit where the reference misses unless the hit point is within
//    kHitTolerance = 4ε of the surface (true distance, closed form): the hit rule is
//    "value < ε", and a value below the distance stops farther than ε (measured: up
//    to 2.44ε, safe mode across the umbrella's handle);
//  - with a bound (mode safe), sphere and enhanced sphere tracing never stop beyond
//    the reference's first root (they cannot step across the surface).
//
// The documented behaviour, ray by ray (ε = 1e-4, the default hit threshold; the
// numbers in brackets were measured on this build):
//  - Tangent to the unit sphere (o = (−3, 1, 0), d = +x; F along the ray is (t − 3)², a
//    double root at t = 3): exact hits at 3 (the square-free part). The value-based
//    methods hit where the value first drops below ε, up to √(2ε) ≈ 0.014 before the
//    tangent point: sphere and enhanced converge slowly because the value decreases
//    quadratically [sphere 139–141 evaluations, enhanced 115–117]; checked Newton
//    twice as fast [82–84: its step follows the slope, which flattens].
//  - 1e-6 above the tangent: no real root, exact misses. Every value-based method hits
//    (the ray comes within 1e-6 < ε of the surface): a hit within ε of the surface,
//    allowed by the tolerance. This is what a renderer with a hit threshold draws.
//  - 1e-6 below: two roots 2.8e-3 apart; exact hits the first (t = 3 − 1.414e-3);
//    the value-based methods hit within √(2ε) before it, as for the tangent ray.
//  - Whitney's umbrella x² − y²z = 0, a ray across its handle (the negative z-axis,
//    where the surface is a line and ∇F = 0) at z = −1, straight and oblique: the ray
//    only touches the surface (F = x² ≥ 0 on it), a double root; exact finds it; the
//    estimates are a multiple of the distance there (fast |x|/2), so sphere tracing
//    converges geometrically and stops within 2.5ε of the handle [sphere 14–20
//    evaluations, checked Newton 27–40].
//  - The same umbrella with the sign the bench's parametrization implicitizes to,
//    y²z − x²: below z = 0 the value is ≤ 0 everywhere, so the ray starts inside the
//    solid: every method hits at t_min (see "starting inside").
//  - The cone x² + y² − z² = 0 (apex singular, ∇F = 0): a line through the apex lies
//    inside, outside or on the cone, so a ray through it from outside only touches
//    (a double root). At slope 1/2 every method hits within 2.5ε of the apex [sphere
//    26–35 evaluations]; at slope 0.9, close to a generator, the value is small all
//    along and sphere tracing creeps to the apex [sphere 136–145 evaluations, within
//    the 255 steps, checked Newton 80–84; at slope 0.99 they run out of steps: a
//    counted miss, where exact and unchecked Newton find the apex
//    (MissesAreCleanAndStallsAreCounted)]. A ray along a
//    generator lies in the surface (F ≡ 0 on it): exact answers t_min (q ≡ 0), the
//    others hit at t_min too (value 0 < ε).
//  - From 10^6 away (o = (1e6, 0.5, 0), d = −x, t_max 2e6): every method hits the
//    sphere at 1e6 − √0.75 [to 1e-4], in ≤ 15 evaluations: beyond the frame's far
//    field both modes return the distance to the box, so the first step crosses the
//    10^6 at once. A ray from 10^6 that misses by 2 (o = (1e6, 3, 0)): a clean miss;
//    every value-based method leaves through t_max [22–27 evaluations]; unchecked,
//    Newton and forward Newton stall at the closest approach (a local minimum of the
//    value, no root) and run out of steps: a miss, counted as out of steps. With the
//    default t_max (100)
//    the sphere is out of reach: a miss after one step.
//  - Starting inside the unit sphere (o = 0): every method hits at t_min with one
//    evaluation (the signed hit rule, value < ε; exact by the sign of F at the
//    segment's start), not at the exit t = 1 that root isolation alone would give.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>

#include "implicitizer/render/march_ray.hpp"
#include "render/render_support.hpp"

namespace implicitizer {
namespace {

using Vec = std::array<double, 3>;

constexpr double kEpsilon = 1e-4;  // default_march_params' ε for the default box
// How far from the surface a hit point may be: the hit rule is value < ε, and where
// the value is below the distance the point may be farther. On these rays the safe
// bound is at worst 2.44 times below the distance (across the umbrella's handle,
// where ∇F = 0), elsewhere at most 1.4 times.
constexpr double kHitTolerance = 4 * kEpsilon;

constexpr MarchMethod kValueMethods[] = {MarchMethod::sphere, MarchMethod::enhanced, MarchMethod::newton,
                                         MarchMethod::forward_newton};

Ray make_ray(const Vec& origin, const Vec& direction) {
  const double n = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  return Ray{origin, {direction[0] / n, direction[1] / n, direction[2] / n}};
}

Vec point_at(const Ray& ray, double t) {
  return {ray.origin[0] + t * ray.direction[0], ray.origin[1] + t * ray.direction[1],
          ray.origin[2] + t * ray.direction[2]};
}

// True distances to the surfaces, in closed form near the rays used.
double distance_to_unit_sphere(const Vec& p) { return std::abs(std::hypot(p[0], p[1], p[2]) - 1); }
// The cone x² + y² = z²: the nearest point lies on the generator in p's half-plane.
double distance_to_cone(const Vec& p) { return std::abs(std::hypot(p[0], p[1]) - std::abs(p[2])) / std::sqrt(2.0); }
// Near the handle (z < 0, far from the sheets x² = y²z of z > 0): the distance to the z-axis.
double distance_to_handle(const Vec& p) { return std::hypot(p[0], p[1]); }

struct SpecialRay {
  const char* name;
  const char* equation;
  Ray ray;
  double t_max;                      // 0: default_march_params' t_max
  std::optional<double> first_root;  // the closed-form first root in [0, t_max], if any
  bool hits_at_start;                // F ≤ 0 at the origin: every method hits at t_min
  std::function<double(const Vec&)> distance;
};

std::vector<SpecialRay> special_rays() {
  const double below = 1 - 1e-6, above = 1 + 1e-6;
  const double sqrt5 = std::sqrt(5.0);
  return {
      {"tangent", "x^2+y^2+z^2-1", make_ray({-3, 1, 0}, {1, 0, 0}), 0, 3.0, false, distance_to_unit_sphere},
      {"1e-6 above the tangent", "x^2+y^2+z^2-1", make_ray({-3, above, 0}, {1, 0, 0}), 0, std::nullopt, false,
       distance_to_unit_sphere},
      {"1e-6 below the tangent", "x^2+y^2+z^2-1", make_ray({-3, below, 0}, {1, 0, 0}), 0,
       3 - std::sqrt(1 - below * below), false, distance_to_unit_sphere},
      {"across the umbrella's handle", "x^2-y^2*z", make_ray({1, 0, -1}, {-1, 0, 0}), 0, 1.0, false,
       distance_to_handle},
      {"across the handle, oblique", "x^2-y^2*z", make_ray({1, 0.5, -1}, {-1, -0.5, 0}), 0, std::hypot(1, 0.5), false,
       distance_to_handle},
      {"handle, the bench's sign", "y^2*z-x^2", make_ray({1, 0, -1}, {-1, 0, 0}), 0, 0.0, true, distance_to_handle},
      {"touching the cone's apex", "x^2+y^2-z^2", make_ray({-2, 0, -1}, {2, 0, 1}), 0, sqrt5, false, distance_to_cone},
      {"through the apex, near a generator", "x^2+y^2-z^2", make_ray({-2, 0, -1.8}, {1, 0, 0.9}), 0, std::hypot(2, 1.8),
       false, distance_to_cone},
      {"along a generator", "x^2+y^2-z^2", make_ray({-2, 0, -2}, {1, 0, 1}), 0, 0.0, true, distance_to_cone},
      {"from 1e6, hitting", "x^2+y^2+z^2-1", make_ray({1e6, 0.5, 0}, {-1, 0, 0}), 2e6, 1e6 - std::sqrt(0.75), false,
       distance_to_unit_sphere},
      {"from 1e6, missing", "x^2+y^2+z^2-1", make_ray({1e6, 3, 0}, {-1, 0, 0}), 2e6, std::nullopt, false,
       distance_to_unit_sphere},
      {"from 1e6, default t_max", "x^2+y^2+z^2-1", make_ray({1e6, 0.5, 0}, {-1, 0, 0}), 0, std::nullopt, false,
       distance_to_unit_sphere},
      {"starting inside", "x^2+y^2+z^2-1", make_ray({0, 0, 0}, {1, 0.3, 0.2}), 0, 0.0, true, distance_to_unit_sphere},
  };
}

// The reference itself: exact agrees with the closed-form first root (1e-9 relative:
// root isolation promises 1e-12).
TEST(SpecialRays, ExactFindsTheClosedFormFirstRoot) {
  for (const SpecialRay& c : special_rays()) {
    for (SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      const RenderTarget target = test::implicit_target(c.equation, SceneBox::default_box(), mode);
      MarchParams params = default_march_params(target);
      if (c.t_max > 0) params.t_max = c.t_max;
      const MarchResult r = march_ray(target, c.ray, MarchMethod::exact, params);
      ASSERT_EQ(r.hit, c.first_root.has_value()) << c.name;
      if (c.first_root) {
        EXPECT_NEAR(r.t, *c.first_root, 1e-9 * std::max(1.0, *c.first_root)) << c.name;
      }
    }
  }
}

// The invariants of the file comment, and the per-ray outcomes it documents.
TEST(SpecialRays, EveryMarcherTerminatesAndNeverHitsFarFromTheSurface) {
  for (const SpecialRay& c : special_rays()) {
    for (SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      const RenderTarget target = test::implicit_target(c.equation, SceneBox::default_box(), mode);
      MarchParams params = default_march_params(target);
      ASSERT_EQ(params.epsilon, kEpsilon);
      if (c.t_max > 0) params.t_max = c.t_max;
      const MarchResult reference = march_ray(target, c.ray, MarchMethod::exact, params);
      for (MarchMethod method : kValueMethods) {
        const std::string what =
            std::string(c.name) + ", " + to_string(method) + ", " + (mode == SdfMode::safe ? "safe" : "fast");
        const MarchResult r = march_ray(target, c.ray, method, params);
        std::printf("[measure] %-30s %-15s %s: hit %d t %.9g evaluations %u out_of_steps %d distance %.3g\n", c.name,
                    to_string(method), mode == SdfMode::safe ? "safe" : "fast", r.hit, r.t, r.evaluations,
                    r.out_of_steps, r.hit ? c.distance(point_at(c.ray, r.t)) : -1.0);
        EXPECT_LE(r.steps, params.max_steps) << what;
        EXPECT_LE(r.evaluations, 2 * params.max_steps + 1) << what;
        EXPECT_TRUE(std::isfinite(r.t)) << what;
        EXPECT_FALSE(r.hit && r.out_of_steps) << what << ": out of steps is a miss";
        if (c.hits_at_start) {
          // The signed hit rule: a start in the solid is a hit at t_min, at once.
          EXPECT_TRUE(r.hit) << what;
          EXPECT_EQ(r.t, params.t_min) << what;
          EXPECT_EQ(r.evaluations, 1u) << what;
          continue;
        }
        if (r.hit) {
          EXPECT_GE(r.t, params.t_min) << what;
          EXPECT_LE(r.t, params.t_max) << what;
          // A hit where exact misses, or anywhere: within the tolerance of the surface.
          EXPECT_LE(c.distance(point_at(c.ray, r.t)), kHitTolerance) << what;
        }
        if (reference.hit && std::string(c.name) != "through the apex, near a generator") {
          // Every ray here that has a root is found by every method (none is a
          // stall: the roots are isolated and the value leads to them), but the one
          // near a generator, where the value-based methods creep (the next test).
          EXPECT_TRUE(r.hit) << what;
          EXPECT_FALSE(r.out_of_steps) << what;
          // Before the root, at most √(2ε·R) (R = 1: the tangent rays) ...
          EXPECT_NEAR(r.t, reference.t, 1.5 * std::sqrt(2 * kEpsilon)) << what;
          // ... and with a bound, sphere and enhanced sphere tracing never beyond it.
          if (mode == SdfMode::safe && (method == MarchMethod::sphere || method == MarchMethod::enhanced)) {
            EXPECT_LE(r.t, reference.t + 1e-9 * std::max(1.0, reference.t)) << what;
          }
        }
      }
    }
  }
}

// The misses of the file comment, one by one: exact misses every ray without a
// root; the value-based methods hit the ray 1e-6 above the tangent (within ε), miss
// the far rays cleanly (unchecked, Newton's two variants stall on the far miss: out
// of steps, a counted miss); the value-based methods run out of steps on a ray
// through the cone's apex close to a generator, which unchecked Newton finds.
TEST(SpecialRays, MissesAreCleanAndStallsAreCounted) {
  const auto rays = special_rays();
  const auto find = [&](const std::string& name) {
    return *std::find_if(rays.begin(), rays.end(), [&](const SpecialRay& c) { return c.name == name; });
  };
  for (SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
    const RenderTarget sphere = test::implicit_target("x^2+y^2+z^2-1", SceneBox::default_box(), mode);
    MarchParams params = default_march_params(sphere);

    const SpecialRay above = find("1e-6 above the tangent");
    EXPECT_FALSE(march_ray(sphere, above.ray, MarchMethod::exact, params).hit);
    for (MarchMethod method : kValueMethods) {
      const MarchResult r = march_ray(sphere, above.ray, method, params);
      EXPECT_TRUE(r.hit) << to_string(method) << ": the ray passes within 1e-6 < ε";
    }

    const SpecialRay beyond_reach = find("from 1e6, default t_max");
    for (MarchMethod method : {MarchMethod::sphere, MarchMethod::enhanced, MarchMethod::newton,
                               MarchMethod::forward_newton, MarchMethod::exact}) {
      const MarchResult r = march_ray(sphere, beyond_reach.ray, method, params);
      EXPECT_FALSE(r.hit) << to_string(method);
      EXPECT_FALSE(r.out_of_steps) << to_string(method);
      EXPECT_LE(r.evaluations, 2u) << to_string(method) << ": the first step passes t_max";
    }

    params.t_max = 2e6;
    MarchParams unchecked = params;
    unchecked.check_newton_steps = false;
    const SpecialRay far_miss = find("from 1e6, missing");
    for (MarchMethod method : kValueMethods) {
      const MarchResult r = march_ray(sphere, far_miss.ray, method, params);
      EXPECT_FALSE(r.hit) << to_string(method);
      EXPECT_FALSE(r.out_of_steps) << to_string(method) << ": leaves through t_max";
      EXPECT_LE(r.evaluations, 40u) << to_string(method);
    }
    for (MarchMethod method : {MarchMethod::newton, MarchMethod::forward_newton}) {
      const MarchResult r = march_ray(sphere, far_miss.ray, method, unchecked);
      EXPECT_FALSE(r.hit) << to_string(method);
      EXPECT_TRUE(r.out_of_steps) << to_string(method) << ", unchecked: stalls at the closest approach";
      EXPECT_EQ(r.steps, params.max_steps) << to_string(method);
    }
    EXPECT_FALSE(march_ray(sphere, far_miss.ray, MarchMethod::exact, params).hit);

    // Through the cone's apex at slope 0.99, almost along a generator: the value is
    // about 0.007 times the distance to the apex all along, so sphere, enhanced and
    // checked Newton creep and run out of steps (a counted miss: drawn as
    // background, never as a hit), where exact and unchecked Newton find the apex.
    const RenderTarget cone = test::implicit_target("x^2+y^2-z^2", SceneBox::default_box(), mode);
    const MarchParams cone_params = default_march_params(cone);
    MarchParams cone_unchecked = cone_params;
    cone_unchecked.check_newton_steps = false;
    const Ray creeping = make_ray({-2, 0, -1.98}, {1, 0, 0.99});
    const double apex = std::hypot(2, 1.98);
    for (MarchMethod method : kValueMethods) {
      const MarchResult r = march_ray(cone, creeping, method, cone_params);
      EXPECT_FALSE(r.hit) << to_string(method);
      EXPECT_TRUE(r.out_of_steps) << to_string(method);
    }
    const MarchResult exact = march_ray(cone, creeping, MarchMethod::exact, cone_params);
    const MarchResult newton = march_ray(cone, creeping, MarchMethod::newton, cone_unchecked);
    ASSERT_TRUE(exact.hit && newton.hit);
    EXPECT_NEAR(exact.t, apex, 1e-3);
    EXPECT_NEAR(newton.t, apex, 1e-3);
  }
}

}  // namespace
}  // namespace implicitizer
