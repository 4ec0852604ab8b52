// Tests of tests/render/bisection_reference.hpp, the accuracy reference of the
// marchers on scenes that `exact` cannot march: closed-form first roots of spheres
// and unions of spheres on random rays (fixed seed), agreement with exact on an
// implicit leaf, the limit it states (a solid thinner than min_step, approached
// obliquely, can be stepped over), a start in the solid, and its refusals.

#include "render/bisection_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include "implicitizer/render/march_ray.hpp"
#include "render/render_support.hpp"

namespace implicitizer {
namespace {

using testing::BisectionReferenceOptions;
using testing::march_bisection_reference;
using Vec = std::array<double, 3>;

CompiledScene compile_safe(const SceneNode& root) {
  SceneParams options;
  options.mode = SdfMode::safe;
  return compile_scene(root, options);
}

SceneNode sphere_at(const Vec& centre, double radius) {
  return make_node(NodeKind::translate, {{"offset", Vec3<double>{centre[0], centre[1], centre[2]}}},
                   {make_node(NodeKind::sphere, {{"radius", radius}})});
}

// The first t ≥ 0 with |o + t·d − c| = r (d unit), and how close the line passes to
// the sphere's rim (|discriminant|), to skip rays too near tangency to judge.
struct SphereRoot {
  std::optional<double> t;
  double margin = 0;
};
SphereRoot first_sphere_root(const Ray& ray, const Vec& c, double r) {
  Vec oc{};
  for (std::size_t i = 0; i < 3; ++i) oc[i] = ray.origin[i] - c[i];
  const double b = oc[0] * ray.direction[0] + oc[1] * ray.direction[1] + oc[2] * ray.direction[2];
  const double cc = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - r * r;
  const double disc = b * b - cc;
  SphereRoot out;
  out.margin = std::abs(disc);
  if (disc < 0) return out;
  const double s = std::sqrt(disc);
  if (-b - s >= 0) {
    out.t = -b - s;
  } else if (-b + s >= 0) {
    out.t = 0;  // starts inside: the reference hits at t_min
  }
  return out;
}

Ray random_ray(std::mt19937_64& random) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec o{4 * u(random), 4 * u(random), 4 + u(random)};
  const Vec target{1.5 * u(random), 1.5 * u(random), 1.5 * u(random)};
  Vec d{target[0] - o[0], target[1] - o[1], target[2] - o[2]};
  const double n = std::hypot(d[0], d[1], d[2]);
  return Ray{o, {d[0] / n, d[1] / n, d[2] / n}};
}

// Five spheres (as bench/scenes/five_spheres.json, along x): the reference's first
// root is the smallest sphere root, to 1e-12 relative, on 2000 random rays.
TEST(BisectionReference, FindsTheFirstSphereOfAUnion) {
  std::vector<Vec> centres;
  std::vector<SceneNode> children;
  for (int k = 0; k < 5; ++k) {
    centres.push_back({0.9 * (k - 2), 0.2 * (k - 2), -0.75 * (k - 2)});
    children.push_back(sphere_at(centres.back(), 0.45));
  }
  const CompiledScene scene = compile_safe(make_node(NodeKind::csg_union, {}, children));
  BisectionReferenceOptions options;
  std::mt19937_64 random(20240601);
  std::size_t hits = 0, judged = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = random_ray(random);
    std::optional<double> expected;
    double margin = 1;
    for (const Vec& c : centres) {
      const SphereRoot root = first_sphere_root(ray, c, 0.45);
      margin = std::min(margin, root.margin);
      if (root.t && (!expected || *root.t < *expected)) expected = root.t;
    }
    if (margin < 1e-9) continue;  // within 1e-9 of tangency: either answer is right
    ++judged;
    const testing::BisectionReferenceHit hit = march_bisection_reference(scene, ray, options);
    ASSERT_FALSE(hit.exhausted);
    ASSERT_EQ(hit.hit, expected.has_value()) << "ray " << i;
    if (expected) {
      ++hits;
      EXPECT_NEAR(hit.t, *expected, 2e-12 * std::max(1.0, *expected)) << "ray " << i;
    }
  }
  EXPECT_GT(judged, 1990u);
  EXPECT_GT(hits, 200u) << "the rays must reach the spheres";
}

// On an implicit leaf (the unit sphere's safe bound, not a distance) it agrees with
// exact root isolation on hit/miss and to 1e-9 in t.
TEST(BisectionReference, AgreesWithExactOnAnImplicitLeaf) {
  const RenderTarget target = test::implicit_target("x^2+y^2+z^2-1", SceneBox::default_box(), SdfMode::safe);
  const MarchParams params = default_march_params(target);
  BisectionReferenceOptions options;
  options.t_max = params.t_max;
  std::mt19937_64 random(7);
  std::size_t hits = 0;
  for (int i = 0; i < 500; ++i) {
    const Ray ray = random_ray(random);
    const MarchResult exact = march_ray(target, ray, MarchMethod::exact, params);
    const SphereRoot closed = first_sphere_root(ray, {0, 0, 0}, 1);
    if (closed.margin < 1e-9) continue;
    const testing::BisectionReferenceHit hit = march_bisection_reference(target.scene(), ray, options);
    ASSERT_EQ(hit.hit, exact.hit) << "ray " << i;
    if (exact.hit) {
      ++hits;
      EXPECT_NEAR(hit.t, exact.t, 1e-9) << "ray " << i;
    }
  }
  EXPECT_GT(hits, 50u);
}

// The stated limit: a slab 1e-8 thick, approached at 45°, is stepped over with
// min_step 1e-6 (the gap to the slab shrinks by 1 − 1/√2 per step, to 4e-7 after 12;
// the next step, min_step long, moves 7e-7 across and lands 3e-7 beyond the slab) and
// found with min_step 1e-9.
TEST(BisectionReference, ASolidThinnerThanMinStepCanBeSteppedOver) {
  const CompiledScene slab = compile_safe(make_node(NodeKind::box, {{"size", Vec3<double>{10, 10, 5e-9}}}));
  const double s = 1 / std::sqrt(2.0);
  const Ray oblique{{0, 0, 1}, {s, 0, -s}};
  BisectionReferenceOptions coarse;
  coarse.min_step = 1e-6;
  EXPECT_FALSE(march_bisection_reference(slab, oblique, coarse).hit);
  BisectionReferenceOptions fine;
  fine.min_step = 1e-9;
  const testing::BisectionReferenceHit found = march_bisection_reference(slab, oblique, fine);
  ASSERT_TRUE(found.hit);
  EXPECT_NEAR(found.t, (1 - 5e-9) * std::sqrt(2.0), 1e-11);
}

TEST(BisectionReference, AStartInTheSolidHitsAtTMin) {
  const CompiledScene ball = compile_safe(make_node(NodeKind::sphere, {{"radius", 1.0}}));
  BisectionReferenceOptions options;
  options.t_min = 0.25;
  const testing::BisectionReferenceHit hit = march_bisection_reference(ball, Ray{{0, 0, 0}, {1, 0, 0}}, options);
  EXPECT_TRUE(hit.hit);
  EXPECT_EQ(hit.t, 0.25);
  EXPECT_EQ(hit.evaluations, 1u);
}

TEST(BisectionReference, StopsAtMaxStepsWithoutAClaim) {
  // A plane approached at a grazing angle: the safe steps shrink geometrically.
  const CompiledScene floor = compile_safe(make_node(NodeKind::plane, {{"normal", Vec3<double>{0, 0, 1}}}));
  BisectionReferenceOptions options;
  options.max_steps = 3;
  const double a = 0.01;
  const testing::BisectionReferenceHit hit =
      march_bisection_reference(floor, Ray{{0, 0, 1}, {std::sqrt(1 - a * a), 0, -a}}, options);
  EXPECT_TRUE(hit.exhausted);
  EXPECT_FALSE(hit.hit);
  EXPECT_EQ(hit.steps, 3u);
}

TEST(BisectionReference, RefusesAFastScene) {
  const CompiledScene fast = compile_scene(make_node(NodeKind::sphere, {{"radius", 1.0}}), SceneParams{});
  EXPECT_THROW(march_bisection_reference(fast, Ray{{0, 0, 5}, {0, 0, -1}}, BisectionReferenceOptions{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace implicitizer
