#pragma once
/// \file
/// The accuracy reference of the marchers on scenes that are not one polynomial
/// leaf (where `exact` cannot run): the first sign change of the scene's value
/// along the ray, bracketed by marching with steps bounded by the safe value, then
/// bisected to 1e-12 relative. Test support shared by tests/render/ and the
/// benchmark bench/render_accuracy.cpp (header-only: one short function, unlike the
/// compiled reference distance of tests/sdf/).
///
/// Why the safe value: in safe mode a compiled scene's value v satisfies
/// v(p) > 0 ⇒ v(p) ≤ dist(p, {v ≤ 0}) (compiled_scene.hpp), so a step of v from a
/// point outside never passes a point of the solid: the step lands outside or on
/// the surface, and the surface it lands on is the first one along the ray. A fixed
/// step cannot promise that (a solid thinner than the step is stepped over). But a
/// bound may be far below the distance (near a singular point of a polynomial leaf,
/// or a ray grazing a surface for a long way), and stepping by it alone would
/// never end: below `min_step` the march steps `min_step` instead.
///
/// What it guarantees, where the safe value is a bound of the distance to the solid
/// {v ≤ 0} (every primitive and operator of a safe scene; not at the faces of a
/// polynomial leaf's far-field cube, where the value jumps from the distance to the
/// leaf's box to F's negative bound wherever the solid of an open surface reaches the
/// face: a step may cross a corner of that region, which is why `exact` is the
/// reference on algebraic targets), in exact arithmetic (double rounding adds a few
/// ulps of v to each step, far below min_step):
///  - a reported hit is a true root: the value is > 0 at the bracket's start and
///    ≤ 0 at its end, and the hit lies in a bracket narrower than
///    relative_tolerance·max(t, scale) (a continuous value changes sign inside);
///  - a surface is missed only where the ray crosses a part of the solid shorter
///    than min_step along the ray at a point where v < min_step, or only touches
///    the solid (a tangent ray without a sign change: `exact` reports that as a hit,
///    a double root; this reference as a miss);
///  - a ray starting in the solid (v(t_min) ≤ 0) hits at t_min, as the marchers do.
/// The steps are bounded by max_steps (then `exhausted`: neither hit nor miss is
/// claimed) and the budget is checked every 4096 steps.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/render/camera.hpp"
#include "implicitizer/scene/compiled_scene.hpp"

namespace implicitizer::testing {

/// Where and how the reference marches.
struct BisectionReferenceOptions {
  double t_min = 0;                      ///< the ray's start
  double t_max = 100;                    ///< beyond it the ray misses
  double min_step = 1e-6;                ///< the step where the safe value is smaller (see the file comment)
  double relative_tolerance = 1e-12;     ///< bracket width relative to max(t, scale)
  double scale = 1;                      ///< the length below which the tolerance is absolute
  std::uint64_t max_steps = 10'000'000;  ///< marching steps before giving up (bisection not counted)
};

/// What the reference found on one ray.
struct BisectionReferenceHit {
  bool hit = false;               ///< a sign change (or a start in the solid) in [t_min, t_max]
  double t = 0;                   ///< the first root, when hit
  std::uint64_t steps = 0;        ///< marching steps
  std::uint64_t evaluations = 0;  ///< evaluations of the scene (marching and bisection)
  bool exhausted = false;         ///< max_steps reached: neither hit nor miss is claimed
  bool undefined = false;         ///< the value was NaN somewhere: the march stopped there, no claim
};

/// The scene's value at o + t·d in double.
inline double evaluate_on_ray(const CompiledScene& scene, const Ray& ray, double t) {
  const auto& o = ray.origin;
  const auto& d = ray.direction;
  return scene.evaluate<double>(Vec3<double>{o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]});
}

/// The first root of the scene's value on `ray` (file comment). Precondition:
/// `scene` was compiled in safe mode (std::invalid_argument otherwise: a fast
/// estimate may exceed the distance and step over the surface), options finite with
/// 0 ≤ t_min ≤ t_max, min_step > 0. Throws LimitExceeded when `budget` runs out.
inline BisectionReferenceHit march_bisection_reference(const CompiledScene& scene, const Ray& ray,
                                                       const BisectionReferenceOptions& options,
                                                       const Budget& budget = Budget()) {
  if (scene.mode() != SdfMode::safe) {
    throw std::invalid_argument("march_bisection_reference needs a scene compiled in safe mode");
  }
  if (!(options.min_step > 0) || !(options.t_min >= 0) || !(options.t_max >= options.t_min) ||
      !std::isfinite(options.t_max)) {
    throw std::invalid_argument("march_bisection_reference: bad options");
  }
  BisectionReferenceHit out;
  auto value = [&](double t) {
    ++out.evaluations;
    return evaluate_on_ray(scene, ray, t);
  };
  double t = options.t_min;
  double v = value(t);
  if (std::isnan(v)) {
    out.undefined = true;
    return out;
  }
  if (v <= 0) {
    out.hit = true;
    out.t = t;
    return out;
  }
  // March: v > 0 at t throughout.
  double inside_t = 0;
  for (;;) {
    if (out.steps >= options.max_steps) {
      out.exhausted = true;
      return out;
    }
    if (++out.steps % 4096 == 0) budget.check("bisection reference");
    const double next = t + std::max(v, options.min_step);
    const double limit = std::min(next, options.t_max);
    const double w = value(limit);
    if (std::isnan(w)) {
      out.undefined = true;
      return out;
    }
    if (w <= 0) {
      inside_t = limit;
      break;
    }
    if (limit >= options.t_max) return out;  // a miss up to t_max
    t = limit;
    v = w;
  }
  // Bisect [t, inside_t]: value > 0 at t, ≤ 0 at inside_t.
  double a = t, b = inside_t;
  while (b - a > options.relative_tolerance * std::max(b, options.scale)) {
    const double m = a + (b - a) / 2;
    if (m <= a || m >= b) break;  // adjacent doubles
    const double w = value(m);
    if (std::isnan(w)) {
      out.undefined = true;
      return out;
    }
    (w <= 0 ? b : a) = m;
  }
  out.hit = true;
  out.t = b;
  return out;
}

}  // namespace implicitizer::testing
