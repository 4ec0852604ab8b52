#include "implicitizer/render/shading.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace implicitizer {
namespace {

using V = std::array<double, 3>;

double dot3(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V unit(const V& a) {
  const double n = std::sqrt(dot3(a, a));
  if (!(n > 0)) return {0, 0, 0};
  return {a[0] / n, a[1] / n, a[2] / n};
}
V along(const V& p, const V& d, double t) { return {p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2]}; }

double smoothstep(double edge0, double edge1, double x) {
  const double s = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return s * s * (3 - 2 * s);
}

}  // namespace

double soft_shadow(const RenderTarget& target, const V& p, const V& light, double sharpness,
                   const ShadingParams& params, std::uint64_t* evaluations) {
  const double unit_length = target.length_unit();
  const double t_max = params.shadow_t_max * unit_length;
  const double min_step = 1e-4 * unit_length;  // the hit threshold ε of the primary march
  double t = params.shadow_t_min * unit_length;
  double res = 1;
  std::uint32_t steps = 0;
  while (steps < params.shadow_max_steps && t <= t_max) {
    const double f = target.evaluate(along(p, light, t));
    ++steps;
    if (std::isnan(f)) break;
    res = std::min(res, sharpness * f / t);
    if (res < -1) break;
    t += std::max(std::abs(f), min_step);
  }
  if (evaluations) *evaluations += steps;
  return smoothstep(-1, 1, std::max(res, -1.0));
}

double ambient_occlusion(const RenderTarget& target, const V& p, const V& n, std::uint32_t samples,
                         std::uint64_t* evaluations) {
  if (samples == 0) return 1;
  const double u = target.length_unit();
  double occluded = 0, weight = 0.5;
  for (std::uint32_t i = 1; i <= samples; ++i, weight *= 0.5) {
    const double d = u * i / samples;
    const double f = target.evaluate(along(p, n, d));
    if (std::isfinite(f)) occluded += weight * (d - f) / u;
  }
  if (evaluations) *evaluations += samples;
  return std::clamp(1 - occluded, 0.0, 1.0);
}

SurfaceSide surface_side(const RenderTarget& target, const V& p, const V& direction) {
  if (target.shape() != SdfShape::sheet) return SurfaceSide::front;
  // A sheet's value is >= 0 on both sides: only its side's gradient (F's, or an
  // approximation's nearest piece's) knows which side is which.
  const std::optional<V> g = target.side_gradient(p);
  return g && dot3(*g, direction) > 0 ? SurfaceSide::back : SurfaceSide::front;
}

V shade_hit(const RenderTarget& target, const Ray& ray, double t, const ShadingParams& params,
            std::uint64_t* evaluations) {
  const V p = along(ray.origin, ray.direction, t);
  V n = target.normal(p, evaluations);
  if (dot3(n, ray.direction) > 0) n = {-n[0], -n[1], -n[2]};
  const V& albedo = surface_side(target, p, ray.direction) == SurfaceSide::back ? params.back_albedo : params.albedo;
  const V view = {-ray.direction[0], -ray.direction[1], -ray.direction[2]};
  const double occlusion = ambient_occlusion(target, p, n, params.occlusion_samples, evaluations);
  V colour{};
  for (std::size_t c = 0; c < 3; ++c) colour[c] = params.ambient[c] * albedo[c] * occlusion;
  for (const DirectionalLight& light : params.lights) {
    const V l = unit(light.direction);
    const double diffuse = std::max(0.0, dot3(n, l));
    if (diffuse <= 0) continue;  // facing away: no direct light, no shadow march needed
    const V h = unit({l[0] + view[0], l[1] + view[1], l[2] + view[2]});
    const double fresnel = 0.04 + 0.96 * std::pow(std::clamp(1 - dot3(h, l), 0.0, 1.0), 5.0);
    const double highlight = std::pow(std::max(0.0, dot3(n, h)), params.shininess) * fresnel;
    const double shadow = params.shadows ? soft_shadow(target, p, l, light.sharpness, params, evaluations) : 1;
    for (std::size_t c = 0; c < 3; ++c) {
      colour[c] += light.colour[c] * shadow * diffuse * (albedo[c] + params.specular[c] * highlight);
    }
  }
  for (double& c : colour) c = std::pow(std::clamp(c, 0.0, 1.0), 1 / params.gamma);
  return colour;
}

}  // namespace implicitizer
