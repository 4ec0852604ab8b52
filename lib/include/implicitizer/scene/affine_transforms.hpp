#pragma once
/// \file
/// Translate, rotate and uniform scale (Def. 1.19 of the seed thesis): the child is
/// evaluated at the preimage t⁻¹(p) of the point; the scale also multiplies the
/// value. C++ twins and, for the rotation, its GLSL (translate is p − v and scale
/// f(p/s)·s, written inline by the scene's GLSL).
///
/// What they keep: translations and rotations are isometries, so f ∘ t⁻¹ is
/// 1-Lipschitz when f is, and dist(p, t(S)) = dist(t⁻¹p, S) keeps any bound a bound.
/// For s > 0, g(p) = s·f(p/s) has |g(p) − g(q)| = s·|f(p/s) − f(q/s)| ≤ s·|p − q|/s
/// (f 1-Lipschitz), and {g ≤ 0} = s·{f ≤ 0} with dist(p, s·A) = s·dist(p/s, A), so a
/// bound stays a bound.

#include <cmath>
#include <string>

#include "implicitizer/scene/vec3.hpp"

namespace implicitizer {

/// The point rotated by −θ about the unit axis k (Rodrigues), i.e. the preimage of p
/// under the rotation by θ (right-hand rule) that the node applies to its child:
///     p·c − (k × p)·s + k·((k·p)·(1 − c)),   c = cos θ, s = sin θ.
template <typename T>
Vec3<T> rotate_point(const Vec3<T>& p, const Vec3<T>& k, T c, T s) {
  const T d = (k.x * p.x + k.y * p.y + k.z * p.z) * (T(1) - c);
  const Vec3<T> kp{k.y * p.z - k.z * p.y, k.z * p.x - k.x * p.z, k.x * p.y - k.y * p.x};
  return p * c - kp * s + k * d;
}
/// `vec3 PREFIX_rotate(vec3 p, vec3 k, float c, float s)`.
std::string rotate_glsl(const std::string& prefix);

/// The child's point of a translation by v: p − v.
template <typename T>
Vec3<T> translate_point(const Vec3<T>& p, const Vec3<T>& v) {
  return p - v;
}

/// The child's point of a scale by s: p/s (the value is then multiplied by s).
template <typename T>
Vec3<T> scale_point(const Vec3<T>& p, T s) {
  return p / s;
}

}  // namespace implicitizer
