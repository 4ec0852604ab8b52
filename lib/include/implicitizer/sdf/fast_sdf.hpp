#pragma once
/// \file
/// Mode `fast`: the first-order distance estimate F/|∇F| of the surface F = 0,
/// evaluated in the scene frame (scene_frame.hpp) with the gradient from the same
/// Horner pass (polynomial_program.hpp). One object holds the rounded constants and
/// the program; it prints the GLSL function and evaluates the same steps in C++.
///
/// Mathematics (docs/sdf.md): with p = c + u/s and G(u) = F(p)/M,
/// ∇_p F = M·s·∇_u G, so F/|∇_p F| = (G/|∇_u G|)/s: the estimate is computed in
/// u-space and multiplied by h = 1/s. It is invariant under scaling F, so the
/// normalisation by M changes nothing. It is the distance to the zero set of F's
/// linearisation at p: exact for planes, first-order accurate near a regular part
/// of the surface, neither a lower nor an upper bound in general (it overshoots
/// where the surface curves towards p, and grows without bound near a point where
/// ∇F = 0 off the surface). Where |∇_u G| < kGradientFloor the estimate divides by
/// the floor instead: smaller in magnitude, never inf or NaN, but where the
/// surface is singular (∇F = 0 on it) it is not a distance at all.
///
/// What is drawn depends on the shape (sdf_shape.hpp), fixed at build time:
///   - solid: F <= 0 clipped to the box, max(estimate, signed distance to the box), so
///     its surface inside the box plus the caps where the box's faces cut the solid,
///     and nothing outside the box (before this, the estimate alone drew the surface
///     out to twice the box and jumped where that region began). Negative exactly
///     where F < 0 inside the box.
///   - sheet: the surface itself, max(|estimate|, signed distance to the box): |d|
///     inside the box (the box term is negative there), the distance to the box
///     outside; >= 0 everywhere and 0 exactly on F = 0 inside the box, no caps.
/// ("The box" is the frame's cube c ± h, h the largest half side: the box itself when
/// it is a cube.) Far from the box (max |u_i| > kFarField) the value is
/// the box distance alone: the polynomial is only evaluated where |u_i| <= 2, so
/// |u|^18 <= 2.6e5 cannot overflow fp32.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/sdf/polynomial_program.hpp"
#include "implicitizer/sdf/scene_frame.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer {

/// How a FastSdf sheet's estimate is tempered (FastSdf::build).
struct FastSheetOptions {
  /// > 0: |estimate| is capped at this times the box's largest half side, for a
  /// surface whose first-order estimate is not to be trusted far from where it was
  /// fitted (an approximation's piece, polynomial_leaf.hpp); 0: no cap.
  double cap = 0;
  /// For a sheet trimmed by a distance that is 0 on it (a patch's cover): where
  /// |∇_u G| < FastSdf::kTrustFactor·γ_m·Σ_k S_k·r^k (S_k the sum of |g_α| over G's
  /// terms of degree k, r = max|u_i|) the estimate is 0 and the trimming's distance
  /// stands alone. G's rounding is at most γ_m·Ĝ(|u|) <= γ_m·Σ_k S_k·r^k (m = 2n + 4
  /// roundings of 2^-23, docs/sdf.md §6), so where the estimate is kept its error from
  /// that rounding is below 1/kTrustFactor of the box's half side: on the surface,
  /// the estimate is below 1e-3 of it. Near a double curve (∇F = 0 on the surface) the
  /// dropped estimate is the one that would have divided that rounding by a vanishing
  /// gradient.
  bool zero_where_untrusted = false;
};

/// A compiled fast-mode distance estimate.
class FastSdf {
 public:
  /// Below this |∇_u G| the estimate divides by it instead. The coefficients of G
  /// are at most 1, so |∇_u G| is of order 1 on regular parts of the surface; below
  /// 1e-6 the fp32 gradient is dominated by rounding (terms of size up to ~1
  /// cancelling with relative error ~1e-7 each), so its length is noise anyway.
  static constexpr double kGradientFloor = 1e-6;
  /// Beyond this max-norm of u the box distance is returned (see the file comment).
  static constexpr double kFarField = 2;

  /// See FastSheetOptions::zero_where_untrusted.
  static constexpr double kTrustFactor = 2000;

  /// Frames `f` (three variables x, y, z in ring order) in `box` and compiles the
  /// value of `shape` (solid or sheet; automatic is decided by the caller,
  /// enclosure.hpp, and throws std::invalid_argument here). Throws InputError
  /// `constant_polynomial` (no surface), `invalid_box`.
  static FastSdf build(const Polynomial& f, const SceneBox& box, const Budget& budget = Budget(),
                       SdfShape shape = SdfShape::solid, FastSheetOptions sheet = {});

  /// The estimate at p = (x, y, z), computed exactly as the GLSL does (float) or in
  /// double with the double-rounded constants. Solid: negative where F < 0 in the
  /// box; sheet: >= 0.
  template <typename T>
  T evaluate(T x, T y, T z) const {
    const T s = pick<T>(scale_, scale_float_);
    const T h = pick<T>(half_extent_, half_extent_float_);
    const T u = (x - pick<T>(centre_[0], centre_float_[0])) * s;
    const T v = (y - pick<T>(centre_[1], centre_float_[1])) * s;
    const T w = (z - pick<T>(centre_[2], centre_float_[2])) * s;
    const T one(1), zero(0), far(kFarField);
    // The signed distance to the box (iq's box: outside the Euclidean distance to it,
    // inside minus the distance to the nearest face).
    const T qu = std::abs(u) - one, qv = std::abs(v) - one, qw = std::abs(w) - one;
    const T du = std::max(qu, zero), dv = std::max(qv, zero), dw = std::max(qw, zero);
    const T box = (std::sqrt(du * du + dv * dv + dw * dw) + std::min(std::max(qu, std::max(qv, qw)), zero)) * h;
    if (std::max(std::abs(u), std::max(std::abs(v), std::abs(w))) > far) return box;
    const ValueAndGradient<T> r = program_.evaluate(u, v, w);
    const auto& g = r.gradient;
    const T length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const T d = trusted(length, std::max(std::abs(u), std::max(std::abs(v), std::abs(w))))
                    ? r.value / std::max(length, T(kGradientFloor)) * h
                    : T(0);
    // Solid: F <= 0 clipped to the box, its surface inside the box and the caps where
    // the box's faces cut the solid. Sheet: the surface inside the box. Nothing
    // outside the box either way.
    if (shape_ != SdfShape::sheet) return std::max(d, box);
    return std::max(cap_ > 0 ? std::min(std::abs(d), pick<T>(cap_, cap_float_)) : std::abs(d), box);
  }

  /// `float FUNCTION(vec3 p) { ... }` with a comment line above it. Precondition:
  /// `function` is a valid GLSL identifier (check_glsl_name on its prefix).
  std::string to_glsl(const std::string& function) const;

  /// The frame (exact, float-representable centre and scale).
  const SceneFrame& frame() const { return frame_; }
  /// What the value describes: solid or sheet (never automatic).
  SdfShape shape() const { return shape_; }
  /// The compiled G.
  const PolynomialProgram& program() const { return program_; }

 private:
  template <typename T>
  static T pick(double d, float f) {
    if constexpr (sizeof(T) == sizeof(float)) {
      return f;
    } else {
      return static_cast<T>(d);
    }
  }

  // The float constants for a float run, the double ones otherwise (as pick()).
  template <typename T>
  static const auto& pick_vector(const std::vector<double>& d, const std::vector<float>& f) {
    if constexpr (sizeof(T) == sizeof(float)) {
      return f;
    } else {
      return d;
    }
  }

  SceneFrame frame_;
  PolynomialProgram program_;
  SdfShape shape_ = SdfShape::solid;
  double cap_ = 0;       // the sheet's cap on |estimate| in space units (0: none)
  float cap_float_ = 0;  // the same, as the GLSL states it
  // The radial majorant's coefficients, kTrustFactor·γ_m·S_k (FastSheetOptions; empty:
  // every estimate kept).
  std::vector<double> trust_;
  std::vector<float> trust_float_;

  // Whether the estimate is kept at max|u_i| = r: |∇_u G| >= the majorant at r.
  template <typename T>
  bool trusted(T length, T r) const {
    const auto& c = pick_vector<T>(trust_, trust_float_);
    if (c.empty()) return true;
    T bound = T(c.back());
    for (std::size_t k = c.size() - 1; k-- > 0;) bound = bound * r + T(c[k]);
    return length >= bound;
  }
  std::array<double, 3> centre_{};
  std::array<float, 3> centre_float_{};
  double scale_ = 1, half_extent_ = 1;
  float scale_float_ = 1, half_extent_float_ = 1;
};

}  // namespace implicitizer
