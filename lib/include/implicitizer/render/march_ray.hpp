#pragma once
/// \file
/// Finding where a ray first meets the surface of a RenderTarget: sphere tracing,
/// enhanced (over-relaxed) sphere tracing, Newton marching and forward Newton
/// marching on the scene's value f(t) = value(o + t·d), and exact root isolation on
/// the algebraic surface. One public function per ray, so that a benchmark can
/// compare the methods pixel by pixel (docs/render.md has the methods with their
/// conditions of correctness and the speed–accuracy measurements).
///
/// The hit rule, common to the value-based methods: the ray hits at t when
/// f(t) < ε (signed, as the first thesis' shader: a point inside the solid also
/// counts, so a ray that starts inside hits at t_min and a step that lands inside
/// stops there). Newton marching, whose steps can land deep inside, refines such a
/// landing in the bracket it closes, to |f| < ε. A ray misses when t exceeds t_max, and
/// also when it runs out of steps: then `out_of_steps` is set and the ray is
/// counted, never shaded as a hit (the first thesis' shader shaded it as one).
///
/// Conditions of correctness, in short (exact arithmetic; float adds a few ulps):
///  - sphere: with a bound (mode safe: |f(p)| ≤ distance to the surface) every
///    step stays on the near side of the surface, so the hit found is within ε of
///    the first intersection, or the ray truly misses up to t_max. With mode fast
///    (F/|∇F|, not a bound) a step can cross a thin part of the surface.
///  - enhanced: as safe as sphere with a bound: a relaxed step ω·f is kept only
///    when the unbounding intervals [t_prev − r_prev, t_prev + r_prev] and
///    [t − r, t + r] overlap (r_prev + r ≥ t − t_prev), i.e. when they cover the
///    segment stepped over; otherwise it steps back to the previous point and takes
///    the plain step r_prev (then relaxes again).
///  - newton, forward_newton: Newton steps, each kept only when longer than the
///    sphere step and checked like enhanced's relaxed steps, so with a bound they
///    are as safe as sphere; they need f differentiable along the ray to gain
///    anything. Unchecked (MarchParams::check_newton_steps = false, the second
///    thesis' algorithms) they are root finders: they may return a root behind the
///    first (or none) and stall on a local minimum of |f| (out of steps).
///  - exact: the first root of F in the drawn part of the ray, isolated by the
///    root isolation of the algebraic surface (not available for other scenes).

#include <cstdint>
#include <optional>
#include <string>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/render/camera.hpp"
#include "implicitizer/render/render_target.hpp"

namespace implicitizer {

/// The marching methods.
enum class MarchMethod : std::uint8_t {
  sphere,          ///< Hart's sphere tracing: t += f
  enhanced,        ///< Keinert et al.'s over-relaxed sphere tracing: t += ω·f, checked
  newton,          ///< Newton's method on f(t), checked steps, sphere-step fallback (001, Alg. 5)
  forward_newton,  ///< Newton's method on f(t)·(t − t_max)/t (001, Alg. 6, derivative corrected)
  exact,           ///< first root of the polynomial on the ray (algebraic surfaces only)
};

/// "sphere", "enhanced", "newton", "forward_newton", "exact".
const char* to_string(MarchMethod method);
/// The method named `name`. Throws InputError `invalid_value` (field "method") for
/// any other name.
MarchMethod parse_march_method(const std::string& name);
/// Whether `method` can march `target`: exact needs an algebraic surface.
bool is_method_applicable(MarchMethod method, const RenderTarget& target);

/// The numbers of a march. default_march_params() scales the first thesis' values
/// by the target's length unit.
struct MarchParams {
  double t_min = 0;               ///< where the ray starts
  double t_max = 100;             ///< beyond it the ray misses (the seed's 100)
  double epsilon = 1e-4;          ///< the hit threshold ε on f (the seed's 1e-4)
  std::uint32_t max_steps = 255;  ///< marching steps before out_of_steps (the seed's 255)
  /// Enhanced: the over-relaxation factor ω ∈ [1, 2). Approaching a plane at an
  /// angle θ the distance shrinks by (1 − ω·sin θ) per step instead of (1 − sin θ),
  /// and the overlap check holds while ω ≤ 2/(1 + sin θ). 1.2 spent the fewest
  /// evaluations of 1.2, 1.4, 1.6, 1.8, 1.95 on the sphere, the torus and Steiner's
  /// surface (docs/render.md).
  double omega = 1.2;
  /// Newton: the forward difference step δ of f'(t) ≈ (f(t + δ) − f(t))/δ.
  double derivative_step = 1e-3;
  /// Newton: below this |f'| the Newton step (f/f', longer than f/|f'| ≥ 1000·f) is
  /// not trusted and a sphere step |f| is taken instead (the seed gave up: a miss).
  double min_slope = 1e-3;
  /// Newton and forward Newton: checked steps (march_ray.cpp): the slope from the
  /// secant through the previous point, a Newton step kept only when longer than the
  /// sphere step |f|, shortened to what the overlap check of enhanced sphere tracing
  /// can accept, and checked where it lands (back to the sphere step if it fails).
  /// With a bound this makes them as safe as sphere tracing, and they never stall.
  /// false gives the second thesis' algorithms (forward differences, any Newton
  /// step, no check), kept for the speed–accuracy benchmark.
  bool check_newton_steps = true;
  /// Checked Newton: the fraction of the overlap-feasible step 2f/(1 − σ) taken (σ the
  /// slope). Below 1 it leaves room for curvature: mean evaluations per ray on the
  /// sphere, torus and Steiner's surface, fast mode, 1 → 13.0, 17.8, 20.5; 0.9 →
  /// 13.1, 16.1, 17.9; 0.8 → 13.6, 16.6, 18.3 (docs/render.md §4.3).
  double newton_overlap_margin = 0.9;
  /// Checked Newton: the longest step, in units of the sphere step |f| (where the
  /// slope is near 1 the feasible step has no useful bound).
  double newton_step_cap = 4;
};

/// The defaults for `target`: t_max 100, ε 1e-4 and δ 1e-3 times its length unit;
/// 255 steps, ω 1.2, slope floor 1e-3.
MarchParams default_march_params(const RenderTarget& target);

/// What one ray found.
struct MarchResult {
  bool hit = false;               ///< the ray met the surface at t
  double t = 0;                   ///< the distance along the ray (|d| = 1) of the hit
  std::uint32_t evaluations = 0;  ///< scene evaluations spent (exact: 1 if the ray enters the drawn region)
  std::uint32_t steps = 0;        ///< marching iterations (exact: the root isolation's subdivisions)
  bool out_of_steps = false;      ///< the ray used max_steps without deciding: a miss
};

/// Marches `ray` through `target` with `method`. Throws InputError
/// `method_not_applicable` (field "method") when the method cannot march the
/// target (exact on a scene that is not a single polynomial leaf), and
/// LimitExceeded when `budget` runs out inside exact root isolation (the
/// value-based methods take bounded steps and never check it).
MarchResult march_ray(const RenderTarget& target, const Ray& ray, MarchMethod method, const MarchParams& params,
                      const Budget& budget = Budget());

}  // namespace implicitizer
