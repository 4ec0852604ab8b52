#pragma once
/// \file
/// A three-vector for the C++ twins of the GLSL scene functions: the same operations
/// GLSL's vec3 offers, in float or double, so that a C++ function can mirror a GLSL
/// one operation for operation (the tests compare the two on a software GPU).
/// Every operation is written with the same association order GLSL's built-ins are
/// specified with (dot(a, b) = a.x*b.x + a.y*b.y + a.z*b.z, length(v) = sqrt(dot(v, v))).

#include <algorithm>
#include <cmath>

namespace implicitizer {

/// x, y, z in T (float or double).
template <typename T>
struct Vec3 {
  T x{}, y{}, z{};  ///< the components

  friend Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
  friend Vec3 operator*(const Vec3& a, T s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3 operator*(T s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
  friend Vec3 operator*(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
  friend Vec3 operator/(const Vec3& a, T s) { return {a.x / s, a.y / s, a.z / s}; }
  friend Vec3 operator/(const Vec3& a, const Vec3& b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }
};

/// GLSL dot().
template <typename T>
T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// GLSL length().
template <typename T>
T length(const Vec3<T>& a) {
  return std::sqrt(dot(a, a));
}

/// GLSL abs() on each component.
template <typename T>
Vec3<T> abs(const Vec3<T>& a) {
  return {std::abs(a.x), std::abs(a.y), std::abs(a.z)};
}

/// GLSL max(vec3, float) on each component.
template <typename T>
Vec3<T> max(const Vec3<T>& a, T b) {
  return {std::max(a.x, b), std::max(a.y, b), std::max(a.z, b)};
}

/// GLSL max(vec3, vec3) on each component.
template <typename T>
Vec3<T> max(const Vec3<T>& a, const Vec3<T>& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

/// GLSL min(vec3, float) on each component.
template <typename T>
Vec3<T> min(const Vec3<T>& a, T b) {
  return {std::min(a.x, b), std::min(a.y, b), std::min(a.z, b)};
}

/// GLSL clamp(vec3, vec3, vec3) on each component: min(max(a, lo), hi).
template <typename T>
Vec3<T> clamp(const Vec3<T>& a, const Vec3<T>& lo, const Vec3<T>& hi) {
  return {std::min(std::max(a.x, lo.x), hi.x), std::min(std::max(a.y, lo.y), hi.y),
          std::min(std::max(a.z, lo.z), hi.z)};
}

/// The largest component (GLSL max(v.x, max(v.y, v.z))).
template <typename T>
T max_component(const Vec3<T>& a) {
  return std::max(a.x, std::max(a.y, a.z));
}

}  // namespace implicitizer
