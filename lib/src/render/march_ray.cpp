#include "implicitizer/render/march_ray.hpp"

#include <cmath>
#include <optional>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/render/root_isolation.hpp"

namespace implicitizer {
namespace {

// f(t) = value(o + t·d), counting evaluations.
class RayFunction {
 public:
  RayFunction(const RenderTarget& target, const Ray& ray, MarchResult& result)
      : target_(target), ray_(ray), result_(result) {}

  double operator()(double t) const {
    ++result_.evaluations;
    const auto& o = ray_.origin;
    const auto& d = ray_.direction;
    return target_.evaluate({o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]});
  }

 private:
  const RenderTarget& target_;
  const Ray& ray_;
  MarchResult& result_;
};

void hit_at(MarchResult& r, double t) {
  r.hit = true;
  r.t = t;
}

// Sheets. A sheet's value is >= 0 on both sides of the surface, so the signed hit rule,
// which catches a solid's crossings (a step that lands inside reads f < 0), never sees
// a step that jumps across it: in mode fast (F/|∇F| is not a bound) such steps left
// holes in the picture. With the sheet's side at hand (G, or an approximation's
// SheetSide: RenderTarget::side_value), its sign at the points a march accepts shows
// the jump: the crossing is bisected on G's sign (in double, to
// 1e-3·ε) and is a hit when the scene's value there is below ε, i.e. when it lies on
// the drawn part of the surface (off a trimmed patch the value there is the distance to
// the patch and the march goes on). Two crossings within one step (a thin fold) still
// cancel; in mode safe the steps never cross, and the test is only a cost: one value of
// G per step.
class SheetCrossing {
 public:
  SheetCrossing(const RenderTarget& target, const Ray& ray)
      : target_(target.has_side() ? &target : nullptr), ray_(ray) {}

  // The crossing of the drawn sheet between the last accepted point and t (> it), if
  // any; t becomes the last accepted point. The side may change sign more than once
  // between them (a step may pass the drawn sheet and the side's other zeros: an
  // untrimmed continuation, a change of nearest piece), so the segment is scanned in
  // kScan parts, each change bisected in turn, the first on the drawn sheet a hit.
  std::optional<double> accept(double t, const RayFunction& f, const MarchParams& params) {
    if (!target_) return std::nullopt;
    const int sign = sign_at(t);
    std::optional<double> hit;
    if (sign != 0 && last_sign_ != 0 && sign != last_sign_ && t > last_t_) {
      double a = last_t_;
      int sign_a = last_sign_;
      for (int k = 1; k <= kScan && !hit; ++k) {
        const double b = k == kScan ? t : last_t_ + (t - last_t_) * k / kScan;
        const int sign_b = k == kScan ? sign : sign_at(b);
        if (sign_b == 0) continue;
        if (sign_b != sign_a) hit = bisect(a, b, sign_a, f, params);
        a = b;
        sign_a = sign_b;
      }
    }
    if (sign != 0) {
      last_sign_ = sign;
      last_t_ = t;
    }
    return hit;
  }

 private:
  static constexpr int kScan = 16;

  // The crossing between a (side's sign `sign_a`) and b (the other sign), bisected on
  // the side's sign to 1e-3·ε; a hit when the scene's value there is below ε.
  std::optional<double> bisect(double a, double b, int sign_a, const RayFunction& f, const MarchParams& params) const {
    for (int i = 0; i < 80 && b - a > 1e-3 * params.epsilon; ++i) {
      const double m = 0.5 * (a + b);
      const int s = sign_at(m);
      if (s == 0) {
        a = b = m;
      } else if (s == sign_a) {
        a = m;
      } else {
        b = m;
      }
    }
    const double c = 0.5 * (a + b);
    if (f(c) < params.epsilon) return c;
    return std::nullopt;
  }

  int sign_at(double t) const {
    const auto& o = ray_.origin;
    const auto& d = ray_.direction;
    const double g = target_->side_value({o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]}).value_or(0);
    return g > 0 ? 1 : g < 0 ? -1 : 0;
  }

  const RenderTarget* target_;
  const Ray& ray_;
  int last_sign_ = 0;
  double last_t_ = 0;
};

// Hart's sphere tracing. A NaN value fails every comparison: it is neither a hit
// nor a step, so the ray stops as a miss (counted by the caller as no hit).
void march_sphere(const RayFunction& f, SheetCrossing& crossing, const MarchParams& params, MarchResult& r) {
  double t = params.t_min;
  for (; r.steps < params.max_steps; ++r.steps) {
    const double value = f(t);
    if (value < params.epsilon) return hit_at(r, t);
    if (!(value < HUGE_VAL)) return;  // NaN or +inf: nothing to step by
    if (const auto c = crossing.accept(t, f, params)) return hit_at(r, *c);
    t += value;
    if (t > params.t_max) return;
  }
  r.out_of_steps = true;
}

// Keinert et al. 2014, "Enhanced sphere tracing", with the overlap test of the
// unbounding intervals. The first step has no previous radius: it is relaxed like
// the others and checked at the next point against the start point's radius (the
// Bálint et al. formula the second thesis implements divides 0 by 0 there). Unlike
// Keinert et al., ω is not dropped to 1 for the rest of the ray after a failed
// check: only the corrective step is plain, and the next step is relaxed (and
// checked) again. Every relaxed step is still checked, so the safety argument is
// the same; the first relaxed step into a scene's box nearly always fails (the
// far-field distance to the box is much larger than the value inside it), and
// keeping ω = 1 after it made enhanced cost one evaluation more than sphere on
// every surface measured (docs/render.md).
void march_enhanced(const RayFunction& f, SheetCrossing& crossing, const MarchParams& params, MarchResult& r) {
  const double omega = params.omega;
  double t = params.t_min;
  double previous_t = t, previous_radius = 0;
  bool relaxed = false;  // whether t was reached by a relaxed step (to be checked)
  for (; r.steps < params.max_steps; ++r.steps) {
    const double value = f(t);
    if (relaxed && !(std::abs(value) + previous_radius >= t - previous_t)) {
      // The relaxed step may have jumped over the surface: step back and take the
      // plain sphere step from the previous point (always covered by its interval).
      t = previous_t + previous_radius;
      relaxed = false;
      continue;
    }
    if (value < params.epsilon) return hit_at(r, t);
    if (!(value < HUGE_VAL)) return;
    if (const auto c = crossing.accept(t, f, params)) return hit_at(r, *c);
    previous_t = t;
    previous_radius = value;
    relaxed = omega > 1;
    t += omega * value;
    if (t > params.t_max) {
      // Beyond t_max only if the unrelaxed step is too: the relaxed one is unchecked.
      if (previous_t + value > params.t_max) return;
      relaxed = false;
      t = previous_t + value;
    }
  }
  r.out_of_steps = true;
}

// Newton's method on f(t) (001, Algorithm 5), and on g(t) = f(t)·(t − T)/t with
// T = t_max (001, Algorithm 6: the factor adds a root at T, so that a ray with no
// root drifts forward instead of stalling). Derivatives by a forward difference.
//
// Checked steps (params.check_newton_steps, the default). The slope is the secant
// through the previous point (a forward difference only at the first point): one
// evaluation a step, as sphere tracing. A Newton step shorter than the sphere step
// |f| (a backward step, the seed's "behind the origin", a flat slope, a non-finite
// step) is replaced by the sphere step. A longer one is shortened to what the
// overlap check of enhanced sphere tracing can accept if f keeps its slope σ,
// margin·2f/(1 − σ) (a step that lands on the surface from farther than f can never
// pass it: the check needs |f(t_new)| + f(t) ≥ t_new − t), and at most cap·f; where
// it lands the check is made, and if it fails the ray goes back and takes the
// sphere step. With a bound every accepted segment is covered by balls free of the
// surface, so checked Newton is as safe as sphere tracing, and it never stalls:
// every step advances by at least |f|. It is then a slope-adaptive over-relaxation
// (Bálint and Valasek 2018 take ω from the same secant); Newton's own step shows
// where the estimate is steeper than a distance (fast mode) and when the landing is
// inside (below). Unchecked (the second thesis' algorithm: forward differences, any
// Newton step) Newton converges to some root, often not the first, and stalls at
// local minima of |f| on rays that miss (docs/render.md §6 measures both).
//
// A Newton step that lands inside the solid (f < −ε after f ≥ ε at the previous
// point) has bracketed a root: it is refined in the bracket by regula falsi with
// the Illinois modification (each evaluation keeps a sign change, so it converges
// to a root of the bracket), to |f| < ε or a bracket narrower than ε. The second
// thesis returns the next Newton iterate from the inside point instead, which can
// be anywhere.
void refine_bracket(const RayFunction& f, const MarchParams& params, double a, double fa, double b, double fb,
                    MarchResult& r) {
  int side = 0;  // which end was kept last (Illinois: halve the other's value)
  while (b - a > params.epsilon && r.steps < params.max_steps) {
    ++r.steps;
    double c = b - fb * (b - a) / (fb - fa);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double fc = f(c);
    if (std::abs(fc) < params.epsilon) return hit_at(r, c);
    if (fc > 0) {
      a = c;
      fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    } else {
      b = c;
      fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    }
  }
  hit_at(r, a);  // the outer end: f(a) > 0, within ε of the root (or out of steps)
}

// The Newton target from t (value f(t), slope f'(t)), +inf where the step is not
// defined or not trusted (a slope below the floor, t = 0 for forward Newton).
double newton_target(double t, double value, double slope, bool forward, const MarchParams& params) {
  if (forward) {
    // g = f·(t − T)/t, g' = f'·(t − T)/t + f·T/t² (the thesis prints this last term
    // garbled). At t = 0 g is undefined.
    if (!(t > 0)) return HUGE_VAL;
    const double far = params.t_max;
    const double factor = (t - far) / t;
    const double g = value * factor;
    const double g_slope = slope * factor + value * far / (t * t);
    return std::abs(g_slope) >= params.min_slope ? t - g / g_slope : HUGE_VAL;
  }
  return std::abs(slope) >= params.min_slope ? t - value / slope : HUGE_VAL;
}

void march_newton(const RayFunction& f, SheetCrossing& crossing, const MarchParams& params, bool forward,
                  MarchResult& r) {
  double t = params.t_min;
  const double delta = params.derivative_step;
  double previous_t = t, previous_value = 0;
  bool unchecked_landing = false;  // t was reached by a Newton step longer than |f|
  bool has_previous = false;
  for (; r.steps < params.max_steps; ++r.steps) {
    const double value = f(t);
    if (unchecked_landing && !(std::abs(value) + previous_value >= t - previous_t)) {
      t = previous_t + previous_value;  // the step may have crossed the surface: step back
      unchecked_landing = false;
      continue;
    }
    unchecked_landing = false;
    if (value < params.epsilon) {
      if (r.steps == 0 || value > -params.epsilon) return hit_at(r, t);
      return refine_bracket(f, params, previous_t, previous_value, t, value, r);
    }
    if (!std::isfinite(value)) return;
    if (const auto c = crossing.accept(t, f, params)) return hit_at(r, *c);
    double slope;
    if (params.check_newton_steps && has_previous) {
      slope = (value - previous_value) / (t - previous_t);
    } else {
      slope = (f(t + delta) - value) / delta;
    }
    has_previous = true;
    previous_t = t;
    previous_value = value;
    double next = newton_target(t, value, slope, forward, params);
    const double sphere_next = t + value;
    if (params.check_newton_steps) {
      // The longest step the check can accept if f keeps the slope σ it has here:
      // f(t + s) = f + σ·s ≥ s − f ⇔ s ≤ 2f/(1 − σ).
      if (slope < 1) next = std::min(next, t + params.newton_overlap_margin * 2 * value / (1 - slope));
      next = std::min(next, t + params.newton_step_cap * value);
      unchecked_landing = std::isfinite(next) && next > sphere_next && next <= params.t_max;
      t = unchecked_landing ? next : sphere_next;
    } else {
      t = std::isfinite(next) && next >= params.t_min ? next : sphere_next;
    }
    if (t > params.t_max) return;
  }
  r.out_of_steps = true;
}

// The first zero of the scene's value on the ray, for an algebraic target: the
// ray is clipped to [lo, hi] (outside, the value is positive) and the first root of
// G in the clipped segment is isolated (root_isolation.hpp) on the ray moved to
// the frame, u = (o − c)·s + t·(d·s), which keeps t. Where the clipped segment
// starts inside the solid (G < 0: the box cuts the solid, or the eye is inside), the
// scene's value changes sign there, and the value-based methods stop there: so does
// this one (not for a sheet, which has no inside). On a sheet a root is a hit only
// where the scene's value is below ε: a trimmed patch draws part of F = 0 in its box,
// so roots off the patch are passed and the next one is sought.
void march_exact(const RenderTarget& target, const Ray& ray, const MarchParams& params, const Budget& budget,
                 MarchResult& r) {
  const AlgebraicSurface& a = *target.algebraic();
  double t0 = params.t_min, t1 = params.t_max;
  for (std::size_t i = 0; i < 3; ++i) {
    const double o = ray.origin[i], d = ray.direction[i];
    if (d == 0) {
      if (o < a.lo[i] || o > a.hi[i]) return;
      continue;
    }
    double enter = (a.lo[i] - o) / d, leave = (a.hi[i] - o) / d;
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
  }
  if (!(t0 <= t1)) return;
  std::array<double, 3> origin{}, direction{};
  for (std::size_t i = 0; i < 3; ++i) {
    origin[i] = (ray.origin[i] - a.centre[i]) * a.scale;
    direction[i] = ray.direction[i] * a.scale;
  }
  ++r.evaluations;  // the sign of G where the segment starts
  const bool sheet = target.shape() == SdfShape::sheet;
  if (!sheet) {
    const ValueAndGradient<double> start =
        a.program.evaluate(origin[0] + t0 * direction[0], origin[1] + t0 * direction[1], origin[2] + t0 * direction[2]);
    if (start.value < 0) return hit_at(r, t0);
  }
  RootIsolationParams options;
  options.scale = target.length_unit();
  // At most max_steps roots are tried on a sheet (each costs a root isolation).
  for (std::uint32_t tried = 0; tried < params.max_steps && t0 <= t1; ++tried) {
    const std::optional<RayRoot> root =
        first_ray_root(*a.ray_context, origin, direction, t0, t1, options, nullptr, budget);
    if (!root) return;
    r.steps += static_cast<std::uint32_t>(root->subdivisions);
    if (!sheet) return hit_at(r, root->t);
    const auto& o = ray.origin;
    const auto& d = ray.direction;
    ++r.evaluations;
    const double t = root->t;
    if (target.evaluate({o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]}) < params.epsilon) return hit_at(r, t);
    // Past this root by the root isolation's tolerance, so that it is not found again.
    t0 = t + 2 * options.relative_tolerance * std::max(options.scale, t) + params.epsilon * 1e-3;
  }
}

}  // namespace

const char* to_string(MarchMethod method) {
  switch (method) {
    case MarchMethod::sphere:
      return "sphere";
    case MarchMethod::enhanced:
      return "enhanced";
    case MarchMethod::newton:
      return "newton";
    case MarchMethod::forward_newton:
      return "forward_newton";
    case MarchMethod::exact:
      return "exact";
  }
  return "sphere";
}

MarchMethod parse_march_method(const std::string& name) {
  for (MarchMethod m : {MarchMethod::sphere, MarchMethod::enhanced, MarchMethod::newton, MarchMethod::forward_newton,
                        MarchMethod::exact}) {
    if (name == to_string(m)) return m;
  }
  throw InputError("invalid_value",
                   "unknown method '" + name + "' (expected sphere, enhanced, newton, forward_newton or exact)")
      .in_field("method");
}

bool is_method_applicable(MarchMethod method, const RenderTarget& target) {
  return method != MarchMethod::exact || target.algebraic().has_value();
}

MarchParams default_march_params(const RenderTarget& target) {
  MarchParams params;
  const double unit = target.length_unit();
  params.t_max *= unit;
  params.epsilon *= unit;
  params.derivative_step *= unit;
  return params;
}

MarchResult march_ray(const RenderTarget& target, const Ray& ray, MarchMethod method, const MarchParams& params,
                      const Budget& budget) {
  MarchResult result;
  const RayFunction f(target, ray, result);
  SheetCrossing crossing(target, ray);
  switch (method) {
    case MarchMethod::sphere:
      march_sphere(f, crossing, params, result);
      return result;
    case MarchMethod::enhanced:
      march_enhanced(f, crossing, params, result);
      return result;
    case MarchMethod::newton:
      march_newton(f, crossing, params, false, result);
      return result;
    case MarchMethod::forward_newton:
      march_newton(f, crossing, params, true, result);
      return result;
    case MarchMethod::exact:
      break;
  }
  if (!target.algebraic()) {
    throw InputError("method_not_applicable",
                     "method 'exact' needs an algebraic surface: an implicit equation, a parametric surface, or a "
                     "scene that is one polynomial leaf")
        .in_field("method");
  }
  march_exact(target, ray, params, budget, result);
  return result;
}

}  // namespace implicitizer
