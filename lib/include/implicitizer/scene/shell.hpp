#pragma once
/// \file
/// The shell operator of a scene: |d| − t, the points within t of the child's
/// surface, so that a sheet (sdf_shape.hpp: a surface with no inside, value >= 0) can
/// enter CSG as a thin solid of thickness 2t. C++ twin and, next to it, the GLSL of
/// the same operations (shell.cpp); docs/sdf.md, "Shell".
///
/// What it guarantees in mode safe (proved in docs/sdf.md, "Shell"):
///   - over a 1-Lipschitz child, |d| − t is 1-Lipschitz (|·| is 1-Lipschitz), with
///     the right sign: class lipschitz;
///   - over a bound d (|d| never exceeds the distance δ to the other side of its
///     surface): δ is 1-Lipschitz and |d| <= δ, so where v = |d| − t > 0,
///     v <= δ − t <= dist(p, N), N = {δ <= t} the exact shell of thickness t around
///     the child's surface, and N ⊆ {v <= 0}. Sphere tracing from outside never
///     enters N. Inside nothing is claimed (t − |d| may exceed the depth, since |d|
///     may be far below δ): class outer_bound (compiled_scene.hpp), which a difference
///     refuses as its subtrahend in mode safe;
///   - over an outer bound nothing holds (|d| on the child's inside is unbounded by
///     anything): safe mode refuses it (InputError `unsafe_operator`).

#include <cmath>
#include <string>

namespace implicitizer {

/// |d| − t: the shell of thickness 2t about the surface d = 0.
template <typename T>
T shell_value(T d, T t) {
  return std::abs(d) - t;
}

/// `float PREFIX_shell(float d, float t)`: shell_value.
std::string shell_glsl(const std::string& prefix);

}  // namespace implicitizer
