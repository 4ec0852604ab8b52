#pragma once
/// \file
/// The frame a distance function is evaluated in: the scene box [lo, hi] mapped onto
/// the cube [-1, 1]^3 by p = c + h·u, with c the box's centre and h its largest half
/// side (one scale for all three axes, so that distances scale isotropically: a
/// distance in u-space times h is the distance in p-space).
///
/// Why: fp32 has 8 exponent bits. A degree-18 polynomial evaluated at p ~ 1e12, or
/// with coefficients ~ 1e30, overflows (3.4e38 is the largest float); one with
/// coefficients ~ 1e-30 on a box of size 1e-6 underflows to 0 and loses its sign.
/// In the frame, |u| <= 1 inside the box, so u^k stays in [-1, 1] for every k, and
/// once G(u) = F(c + h·u) is divided by its largest |coefficient| every coefficient
/// is at most 1 in magnitude, whatever F's coefficients and the box's size are.
/// Both steps are exact (rational arithmetic); only the final coefficients are
/// rounded to float. tests/sdf/scene_frame_test.cpp shows the failures without it.

#include <array>

#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// An axis-aligned box [lo, hi] in x, y, z.
struct SceneBox {
  std::array<Rational, 3> lo;  ///< lower corner
  std::array<Rational, 3> hi;  ///< upper corner; hi[i] > lo[i]

  /// [-2, 2]^3: the surfaces of the docs and the seeds (unit sphere, Steiner's
  /// surface, the torus of radii 2 and 1 up to its outer rim, which the far-field
  /// margin of glsl_export.hpp still covers) fit in it. Any other scene passes a box.
  static SceneBox default_box();
};

/// The box's affine frame u = (p - centre)·scale, i.e. p = centre + u / scale.
/// Invariant: centre[i] and scale are exactly representable as floats (they are
/// the box's centre and 1 / (largest half side) rounded to float), so that the
/// GLSL states them without rounding and G is the exact polynomial of the map the
/// GPU applies. Near the centre, p - centre is then exact in fp32 (Sterbenz), and
/// the only rounding before the polynomial is the one of the product by scale.
/// The cube [-1, 1]^3 in u is the box up to a relative 1e-7.
struct SceneFrame {
  std::array<Rational, 3> centre;  ///< float((lo + hi) / 2)
  Rational scale;                  ///< float(1 / max_i ((hi[i] - lo[i]) / 2)), > 0
};

/// The frame of `box`. Throws InputError `invalid_box` (field "box") unless
/// hi[i] > lo[i] on every axis, the largest half side is within [1e-30, 1e30] and
/// the centre at most 1e30 in magnitude: outside that range 1/h or c are not
/// normal floats and the GLSL could not state them. A centre coordinate below 1e-30
/// in magnitude becomes 0.
SceneFrame make_scene_frame(const SceneBox& box);

/// G(u) = F(centre + u/scale) / M, with M the largest |coefficient| of F(centre + u/scale):
/// exact, in the ring of `f` (variables x, y, z standing for u, v, w). Every
/// coefficient of the result is in [-1, 1] and one is ±1. Sign-preserving: G < 0
/// exactly where F < 0. Precondition: f is in a ring of exactly three variables.
/// Throws InputError `constant_polynomial` when f is constant (no surface),
/// LimitExceeded when `budget` runs out during the composition.
Polynomial frame_polynomial(const Polynomial& f, const SceneFrame& frame, const Budget& budget = Budget());

}  // namespace implicitizer
