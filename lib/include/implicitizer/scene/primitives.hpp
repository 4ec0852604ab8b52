#pragma once
/// \file
/// The primitives of a scene: Íñigo Quílez's exact distance functions (sphere, box,
/// round box, torus, plane, capsule, capped cone, infinite cylinder) and the
/// ellipsoid (his approximation in mode fast; a provable bound in mode safe). Each
/// comes as a C++ template twin and, next to it, the GLSL text of the same
/// operations in the same order (defined in primitives.cpp), so evaluate<float>
/// predicts the GPU.
///
/// Conventions (right-handed x, y, z; every primitive centred on the origin unless
/// said otherwise; negative inside):
///   sphere(radius r):          |p| − r.
///   box(size b):               the box [−b, b] (b = half extents).
///   round_box(size b, radius r): the box [−b, b] with its edges rounded by r
///                              (b includes the rounding; 0 ≤ r ≤ min b).
///   torus(major R, minor r):   the ring of radius R in the xy plane around the z axis,
///                              tube radius r (as ../shared/bench's torus_R2_r1).
///   plane(normal n, offset h): dot(p, n̂) − h, n̂ = n/|n|: the half-space
///                              dot(p, n̂) ≤ h is inside, n̂ points outwards.
///   capsule(a, b, radius r):   the points within r of the segment [a, b].
///   cone(angle θ, height h):   the solid capped cone with its apex at (0, 0, h), its
///                              axis the z axis, its base the disc of radius h·tan θ
///                              in the plane z = 0 (θ the half-angle at the apex).
///   ellipsoid(radii r):        x²/r_x² + y²/r_y² + z²/r_z² ≤ 1.
///   cylinder(radius r):        the infinite solid cylinder x² + y² ≤ r² along z.
///
/// Every function but the fast ellipsoid is 1-Lipschitz with the right sign: the
/// exact ones because they are distances (|d(p) − d(q)| ≤ |p − q|), the safe
/// ellipsoid (|p/r| − 1)·min r because p ↦ |p/r| is (1/min r)-Lipschitz
/// (|p/r − q/r| ≤ |p − q|/min r). The fast ellipsoid k0(k0 − 1)/k1 is only an
/// estimate (exact on spheres, off by up to the eccentricity elsewhere).

#include <algorithm>
#include <cmath>
#include <string>

#include "implicitizer/scene/vec3.hpp"

namespace implicitizer {

/// GLSL text of dot(a, b) spelled out, `a.x * b.x + a.y * b.y + a.z * b.z`, where `a`
/// and `b` are vec3 variable names: the order dot() (vec3.hpp) computes in. GLSL's
/// built-in dot() and length() are left to the driver, which may fuse them into
/// multiply-adds (llvmpipe does: with them only 443 of 500 sphere values matched the
/// C++ float twin bit for bit, spelled out 500 of 500), so the scene's helpers spell
/// them out.
std::string glsl_dot(const std::string& a, const std::string& b);
/// GLSL text of length(v) spelled out: `sqrt(v.x * v.x + v.y * v.y + v.z * v.z)`.
std::string glsl_length(const std::string& v);

/// Below this dot(b − a, b − a) the capsule divides by it instead (a = b gives a
/// sphere, not 0/0). A normal float, so GPUs that flush subnormals agree.
inline constexpr float kCapsuleFloor = 1e-30f;

/// |p| − r.
template <typename T>
T sdf_sphere(const Vec3<T>& p, T r) {
  return length(p) - r;
}
/// `float PREFIX_sphere(vec3 p, float r)`.
std::string sphere_glsl(const std::string& prefix);

/// Distance to the box [−b, b]: q = |p| − b; |max(q, 0)| + min(max_i q_i, 0).
template <typename T>
T sdf_box(const Vec3<T>& p, const Vec3<T>& b) {
  const Vec3<T> q = abs(p) - b;
  return length(max(q, T(0))) + std::min(max_component(q), T(0));
}
/// `float PREFIX_box(vec3 p, vec3 b)`.
std::string box_glsl(const std::string& prefix);

/// The box [−b, b] rounded by r: q = |p| − b + r; |max(q, 0)| + min(max_i q_i, 0) − r.
template <typename T>
T sdf_round_box(const Vec3<T>& p, const Vec3<T>& b, T r) {
  const Vec3<T> q = abs(p) - b + Vec3<T>{r, r, r};
  return length(max(q, T(0))) + std::min(max_component(q), T(0)) - r;
}
/// `float PREFIX_round_box(vec3 p, vec3 b, float r)`.
std::string round_box_glsl(const std::string& prefix);

/// The torus around z: |(sqrt(x² + y²) − R, z)| − r.
template <typename T>
T sdf_torus(const Vec3<T>& p, T major, T minor) {
  const T qx = std::sqrt(p.x * p.x + p.y * p.y) - major;
  return std::sqrt(qx * qx + p.z * p.z) - minor;
}
/// `float PREFIX_torus(vec3 p, float major, float minor)`.
std::string torus_glsl(const std::string& prefix);

/// dot(p, n) − h, n a unit vector.
template <typename T>
T sdf_plane(const Vec3<T>& p, const Vec3<T>& n, T h) {
  return dot(p, n) - h;
}
/// `float PREFIX_plane(vec3 p, vec3 n, float h)`.
std::string plane_glsl(const std::string& prefix);

/// Distance to the segment [a, b] minus r (iq's sdCapsule, with the floor kCapsuleFloor
/// on |b − a|²).
template <typename T>
T sdf_capsule(const Vec3<T>& p, const Vec3<T>& a, const Vec3<T>& b, T r) {
  const Vec3<T> pa = p - a;
  const Vec3<T> ba = b - a;
  const T h = std::clamp(dot(pa, ba) / std::max(dot(ba, ba), T(kCapsuleFloor)), T(0), T(1));
  return length(pa - ba * h) - r;
}
/// `float PREFIX_capsule(vec3 p, vec3 a, vec3 b, float r)`.
std::string capsule_glsl(const std::string& prefix);

/// GLSL sign().
template <typename T>
T glsl_sign(T x) {
  return x > T(0) ? T(1) : (x < T(0) ? T(-1) : T(0));
}

/// iq's exact capped cone, in the 2D half-plane w = (sqrt(x² + y²), z − h) of the
/// apex: (qx, qy) = (h·tan θ, −h) is the base rim seen from the apex. The distance is
/// the smaller of those to the slanted side (segment 0 → q) and to the base (segment
/// (0, qy) → q); the sign says which side of both lines w is.
template <typename T>
T sdf_cone(const Vec3<T>& p, T height, T qx, T qy) {
  const T wx = std::sqrt(p.x * p.x + p.y * p.y);
  const T wy = p.z - height;
  const T t = std::clamp((wx * qx + wy * qy) / (qx * qx + qy * qy), T(0), T(1));
  const T ax = wx - qx * t;
  const T ay = wy - qy * t;
  const T bx = wx - qx * std::clamp(wx / qx, T(0), T(1));
  const T by = wy - qy;
  const T k = glsl_sign(qy);
  const T d = std::min(ax * ax + ay * ay, bx * bx + by * by);
  const T s = std::max(k * (wx * qy - wy * qx), k * (wy - qy));
  return std::sqrt(d) * glsl_sign(s);
}
/// `float PREFIX_cone(vec3 p, float h, float qx, float qy)`.
std::string cone_glsl(const std::string& prefix);

/// iq's ellipsoid approximation k0·(k0 − 1)/k1, k0 = |p/r|, k1 = |p/r²| (mode fast).
/// At the centre iq's formula divides 0 by 0; the floor kCapsuleFloor on k1 gives −0
/// there instead (a value on the inside's side, never NaN).
template <typename T>
T sdf_ellipsoid_estimate(const Vec3<T>& p, const Vec3<T>& r) {
  const T k0 = length(p / r);
  const T k1 = length(p / (r * r));
  return k0 * (k0 - T(1)) / std::max(k1, T(kCapsuleFloor));
}
/// `float PREFIX_ellipsoid(vec3 p, vec3 r)` (the estimate).
std::string ellipsoid_estimate_glsl(const std::string& prefix);

/// (|p/r| − 1)·min r: 1-Lipschitz, a lower bound of the distance (mode safe).
template <typename T>
T sdf_ellipsoid_bound(const Vec3<T>& p, const Vec3<T>& r) {
  return (length(p / r) - T(1)) * std::min(r.x, std::min(r.y, r.z));
}
/// `float PREFIX_ellipsoid(vec3 p, vec3 r)` (the bound).
std::string ellipsoid_bound_glsl(const std::string& prefix);

/// sqrt(x² + y²) − r.
template <typename T>
T sdf_cylinder(const Vec3<T>& p, T r) {
  return std::sqrt(p.x * p.x + p.y * p.y) - r;
}
/// `float PREFIX_cylinder(vec3 p, float r)`.
std::string cylinder_glsl(const std::string& prefix);

}  // namespace implicitizer
