#pragma once
/// \file
/// An approximated piece trimmed to a convex polytope ∩ a box (approximation/
/// trim_polytope.hpp), ready to evaluate in C++ and GLSL: the cheap alternative to a
/// PatchCover for a piece whose kept zeros in the polytope met the tolerance. Its
/// value is
///     t(p) = max(|d|, P(p), B(p)),
/// P a lower bound of the distance to the polytope, B of the distance to the box. Both
/// are at most 0 on X(S) (which lies in both), so t = |d| there; and where |d| is one of
/// the distance to {q = 0} (safe mode), t stays one of the distance to {q = 0} ∩
/// polytope ∩ box, as for a cover (polynomial_leaf.hpp).
///
/// Rounding. The planes are stated in float about the box's float centre c: unit
/// normals n_i rounded to float, offsets o_i >= max over X(S) of n_i·(x − c) (the
/// exact offset moved to c in double, plus |n_i(float) − n_i|·R for the normals'
/// rounding, R the box's circumradius about c, plus a relative 1e-12 for the double
/// steps, rounded up to float). In float, P = max_i (n_i·u − o_i) with u = p − c is
/// off by at most a few ε·(|u|_1 + max|o_i|) (ε = 2^-24: the rounding of u, the three
/// products, two sums and the subtraction); 8ε·(|u|_1 + max|o_i|) is subtracted, and
/// the result, positive, multiplied by 1 − 2^-17 for |n_i| <= 1 + 2^-23.

#include <array>
#include <string>
#include <vector>

#include "implicitizer/approximation/trim_polytope.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"
#include "implicitizer/scene/patch_cover.hpp"
#include "implicitizer/scene/vec3.hpp"

namespace implicitizer {

/// The trimming of one approximated piece to its polytope and box.
class PolytopeTrim {
 public:
  /// The polytope of an ApproximationPiece (1 to kMaxPlanes planes) and that piece's
  /// exact box (3 coordinates); std::invalid_argument otherwise.
  PolytopeTrim(const TrimPolytope& polytope, const PatchBounds& box);

  /// max(|d|, P(p), B(p)) (the file comment), in T's arithmetic (float: the GLSL's).
  template <typename T>
  T distance_lower_bound(const Vec3<T>& p, T d) const {
    return std::max(std::abs(d), std::max(polytope_bound(p), box_bound(p, T(kShrink))));
  }

  /// A lower bound of distance_lower_bound(p, d) for every d: B(p) shrunk by a further
  /// PatchCover::kHullShrink, which covers a GPU evaluating the culling test and the
  /// trimming's own B differently (a fused multiply-add). What lets a union skip a
  /// piece whose box is no nearer than the best value so far.
  template <typename T>
  T hull_distance_lower_bound(const Vec3<T>& p) const {
    return box_bound(p, T(kShrink) * T(PatchCover::kHullShrink));
  }

  /// The GLSL expression of hull_distance_lower_bound<float>(`p`), `p` a vec3
  /// expression without side effects.
  std::string hull_glsl(const std::string& p) const;
  /// `float FUNCTION(vec3 p, float d)` computing distance_lower_bound<float>: the
  /// planes three at a time (u * mat3(n_a, n_b, n_c) − o), the last repeated to fill a
  /// group (a repeated plane changes no max).
  std::string to_glsl(const std::string& function) const;
  /// The other global names to_glsl(FUNCTION) defines (none).
  static std::vector<std::string> glsl_suffixes() { return {}; }

  /// The box's float corners (the trimmed piece lies in it).
  Vec3<float> lo() const { return lo_; }
  /// See lo().
  Vec3<float> hi() const { return hi_; }

 private:
  static constexpr double kClamp = 1e18;          // each box overshoot is clamped before squaring
  static constexpr double kShrink = 1 - 0x1p-17;  // float's roundings of the box distance and |n_i|
  static constexpr double kSlack = 8 * 0x1p-24;   // per unit of |u|_1 + max|o_i| (the file comment)

 public:
  /// The most planes a trimming states.
  static constexpr std::size_t kMaxPlanes = 12;

 private:
  template <typename T>
  static Vec3<T> cast(const Vec3<float>& v) {
    return {T(v.x), T(v.y), T(v.z)};
  }

  // The distance to the box times `factor` (B(p) for kShrink: rounded down).
  template <typename T>
  T box_bound(const Vec3<T>& p, T factor) const {
    const Vec3<T> lo = cast<T>(lo_), hi = cast<T>(hi_);
    const Vec3<T> q{std::max(lo.x - p.x, p.x - hi.x), std::max(lo.y - p.y, p.y - hi.y),
                    std::max(lo.z - p.z, p.z - hi.z)};
    const Vec3<T> m = min(max(q, T(0)), T(kClamp));
    return std::sqrt(m.x * m.x + m.y * m.y + m.z * m.z) * factor;
  }

  template <typename T>
  T polytope_bound(const Vec3<T>& p) const {
    const Vec3<T> u{p.x - T(centre_.x), p.y - T(centre_.y), p.z - T(centre_.z)};
    T worst = -T(kClamp);
    for (std::size_t i = 0; i < normals_.size(); ++i) {
      const Vec3<float>& n = normals_[i];
      worst = std::max(worst, u.x * T(n.x) + u.y * T(n.y) + u.z * T(n.z) - T(offsets_[i]));
    }
    const T slack = T(kSlack) * (std::abs(u.x) + std::abs(u.y) + std::abs(u.z) + T(largest_offset_));
    return (worst - slack) * T(kShrink);
  }

  Vec3<float> centre_{}, lo_{}, hi_{};
  std::vector<Vec3<float>> normals_;  // a multiple of three (the last plane repeated)
  std::vector<float> offsets_;
  float largest_offset_ = 0;
};

}  // namespace implicitizer
