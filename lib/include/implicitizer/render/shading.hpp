#pragma once
/// \file
/// The colour of a surface point, as in the first thesis (000, §2.2 and its
/// shader): Blinn-Phong with Schlick's Fresnel term on the highlight, the improved
/// soft shadows (a march towards the light that may enter the solid, mapped by
/// smoothstep(−1, 1, ·)), ambient occlusion sampled along the normal, and a gamma
/// to display values. Distances the thesis gives (shadow march from 0.02 to 2.5,
/// occlusion samples at i/M) are in its scene's units and are multiplied by the
/// target's length unit (render_target.hpp).
///
/// The shadow and occlusion rays evaluate the same target (same precision, same
/// mode) as the primary ray, with bounded steps. The penumbra estimate min k·f/t
/// needs a march that steps by |f|, so the shadow march is that one whatever the
/// primary method; the methods' images then differ only where their hits differ.
///
/// Two-sided sheets (SURFER's convention): where the target is a sheet the side the
/// viewer sees is coloured by the sign of F there: `albedo` (warm) where F > 0 faces the
/// viewer, i.e. ∇F points towards the eye, `back_albedo` (blue) where F < 0 does. The
/// normal is ∇F turned to face the viewer on both sides, so the light falls on each
/// side as on a solid's surface. Solids, and scenes that are not one polynomial leaf,
/// keep the single `albedo` (render_target.hpp says why scenes have no sides).

#include <array>
#include <cstdint>
#include <vector>

#include "implicitizer/render/camera.hpp"
#include "implicitizer/render/render_target.hpp"

namespace implicitizer {

/// A light at infinity (the thesis' lights are directional).
struct DirectionalLight {
  std::array<double, 3> direction{-0.5, 0.8, 0.35};  ///< towards the light (normalised when used)
  std::array<double, 3> colour{1.0, 0.96, 0.9};      ///< radiance S_i
  /// k: the penumbra's sharpness, the inverse of the light's size (the thesis: 1.5
  /// for its sun, 10 for a lamp).
  double sharpness = 1.5;
};

/// The shading model's numbers.
struct ShadingParams {
  std::array<double, 3> background{0.95, 0.95, 0.95};        ///< display value of a miss (the seed's grey)
  std::array<double, 3> albedo{0.80, 0.52, 0.30};            ///< diffuse reflectance R_D (a sheet's F > 0 side)
  std::array<double, 3> back_albedo{0.25, 0.42, 0.80};       ///< a sheet's F < 0 side
  std::array<double, 3> specular{0.5, 0.5, 0.5};             ///< specular reflectance R_E
  double shininess = 32;                                     ///< Blinn-Phong exponent α
  std::array<double, 3> ambient{0.20, 0.22, 0.26};           ///< ambient radiance times reflectance, L_A·R_A
  std::vector<DirectionalLight> lights{DirectionalLight{}};  ///< default: one sun
  bool shadows = true;                                       ///< the improved soft shadows
  double shadow_t_min = 0.02;                                ///< where the shadow march starts (thesis units)
  double shadow_t_max = 2.5;                                 ///< where it stops (thesis units)
  std::uint32_t shadow_max_steps = 64;                       ///< bound on the shadow march
  std::uint32_t occlusion_samples = 4;                       ///< M (0: no ambient occlusion)
  double gamma = 2.2;                                        ///< display value = linear^(1/gamma)
};

/// Which side of a surface a ray sees.
enum class SurfaceSide : std::uint8_t {
  front,  ///< a solid's outside, or the side of a sheet where F > 0 (∇F points to the viewer)
  back,   ///< the side of a sheet where F < 0
};

/// The side of the surface at p that a ray of unit direction `direction` sees: back
/// when the target is a sheet and ∇F at p points away from the viewer
/// (∇F·direction > 0); front otherwise (solids, and where ∇F vanishes).
SurfaceSide surface_side(const RenderTarget& target, const std::array<double, 3>& p,
                         const std::array<double, 3>& direction);

/// The display colour (each channel in [0, 1]) of the hit at distance t along
/// `ray`. The normal is target.normal(), turned to face the viewer (an implicit
/// surface is seen from both sides); the albedo is the side's (surface_side). Adds
/// the scene evaluations spent (normal, shadows, occlusion) to *evaluations.
std::array<double, 3> shade_hit(const RenderTarget& target, const Ray& ray, double t, const ShadingParams& params,
                                std::uint64_t* evaluations = nullptr);

/// The improved soft shadow (000, Fig. 2.30, with its evaluation moved before its
/// use): march from p towards `light` (unit) by |f| from t_min to t_max (at least
/// ε per step so that a grazing ray cannot stall), res = min(res, k·f/t), stop
/// once res < −1; returns smoothstep(−1, 1, res) ∈ [0, 1] (1: fully lit). Letting
/// the march enter the solid, where f < 0, is what softens the shadow's inner edge
/// without the light leaks of the plain version.
double soft_shadow(const RenderTarget& target, const std::array<double, 3>& p, const std::array<double, 3>& light,
                   double sharpness, const ShadingParams& params, std::uint64_t* evaluations = nullptr);

/// Ambient occlusion along the unit normal n (000, Alg. 16, after Evans 2006):
/// 1 − Σ_{i=1..M} 2^(−i)·(d_i − f(p + d_i·n))/u with d_i = u·i/M (u the length
/// unit), clamped to [0, 1]. For an exact distance and no other geometry near,
/// f(p + d·n) = d and the point is unoccluded (1).
double ambient_occlusion(const RenderTarget& target, const std::array<double, 3>& p, const std::array<double, 3>& n,
                         std::uint32_t samples, std::uint64_t* evaluations = nullptr);

}  // namespace implicitizer
