#pragma once
/// \file
/// The leaves of a scene that are polynomial surfaces: an implicit equation F = 0, or a
/// parametric surface implicitized by the library (implicitize.hpp). Both become the
/// distance function of mode fast (FastSdf: F/|∇F|) or safe (SafeSdf: a lower bound)
/// of F = 0 in the leaf's frame box, named NAME_leaf<k> in the GLSL.
///
/// Shape (sdf_shape.hpp). The source's shape is resolved here, once: solid and sheet
/// as asked; automatic by decide_enclosure() (enclosure.hpp) on the box the value is
/// clipped to (the frame's cube c ± h; its x–y square for a curve): solid, with F
/// negated when F < 0 on the boundary, iff the zero set provably stays off the
/// boundary and encloses a region; else sheet. A parametric leaf with a domain is a
/// sheet under automatic (the patch, trimmed below); asked for a solid it is the solid
/// F <= 0 in its frame box, untrimmed.
///
/// Curves (SceneParams::dimension 2). The equation is F(x, y) (a z in it is
/// `unknown_variable`), or the implicitization of a parametrization with x and y only;
/// the leaf is the 3-D leaf of the cylinder F(x, y) = 0 over the curve, in the frame
/// box [x0, x1]×[y0, y1]×[−m, m] with m the larger half side of the 2-D box (so the
/// frame's scale is the 2-D box's), evaluated by the scene at z = 0: the distance in
/// space from (x, y, 0) to the cylinder is the planar distance to the curve, so both
/// modes keep their meaning (docs/sdf.md, "Curves").
///
/// Trimming. A parametric leaf with a parameter domain D is the patch X(D), not the
/// whole algebraic surface: bound_patch() (patch_bounds.hpp) gives an exact box B ⊇ X(D)
/// (its corners rounded outwards to float), the frame box is B padded by 1e-3 of its
/// largest side on every side, and the leaf's value is the unsigned trimmed sheet
///     t(p) = max(|d(p)|, |max(lo − p, p − hi, 0)|),
/// the second term being the distance from p to B (0 inside). Its zero set is exactly
/// {F = 0} ∩ B: t = 0 iff d = 0 and p ∈ B. It is a lower bound of the distance to
/// Z ∩ B whenever |d| is one of the distance to Z = {F = 0}, because
/// dist(p, Z ∩ B) ≥ max(dist(p, Z), dist(p, B)). A trimmed leaf is a sheet: it has
/// no inside (t ≥ 0 everywhere), so it is meant for union and intersection; as the
/// subtrahend of a difference it removes nothing. B contains the patch but may
/// contain more of Z (other sheets of the surface, or the rest of a piece whose
/// image is not box-shaped): trimming to a box is what a box can do.

#include <array>
#include <optional>
#include <string>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/scene/vec3.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"
#include "implicitizer/sdf/scene_frame.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer {

/// The trimmed sheet max(|d|, distance from p to [lo, hi]), the distance being
/// |max(lo − p, p − hi, 0)| component by component.
template <typename T>
T trim_to_box(const Vec3<T>& p, const Vec3<T>& lo, const Vec3<T>& hi, T d) {
  const Vec3<T> q{std::max(lo.x - p.x, p.x - hi.x), std::max(lo.y - p.y, p.y - hi.y), std::max(lo.z - p.z, p.z - hi.z)};
  return std::max(std::abs(d), length(max(q, T(0))));
}
/// `float PREFIX_trim(vec3 p, vec3 lo, vec3 hi, float d)`.
std::string trim_glsl(const std::string& prefix);

/// One compiled polynomial leaf.
class PolynomialLeaf {
 public:
  /// Builds the leaf of `source` (kind implicit or parametric; see scene_node.hpp)
  /// under `budget`: parses (ring x, y, z), implicitizes (parametric), bounds the
  /// patch (with a domain) and compiles the distance of `mode` in the leaf's box
  /// (source.box, else `default_box`, else, trimmed, the padded patch box).
  /// Errors are InputError with field `field` + ".equation" / ".x" / ".domain" / … :
  /// parse errors, `constant_polynomial`, `invalid_box`, `degree_too_high` (safe),
  /// `invalid_domain`, `unbounded_patch`, `no_single_equation` (the image is not a
  /// surface); LimitExceeded from the budget.
  /// `dimension` is 3 (a surface) or 2 (a plane curve, see the file comment; a
  /// parametric curve's z text must be empty, else InputError `invalid_value` at
  /// field + ".z"). The shape is resolved as the file comment says.
  static PolynomialLeaf build(NodeKind kind, const PolynomialLeafSource& source, const SceneBox& default_box,
                              SdfMode mode, const Budget& budget, const std::string& field, int dimension = 3);

  /// The leaf's value at p: d (untrimmed, signed) or the trimmed sheet.
  template <typename T>
  T evaluate(const Vec3<T>& p) const {
    const T d = fast_ ? fast_->evaluate<T>(p.x, p.y, p.z) : safe_->evaluate<T>(p.x, p.y, p.z);
    if (!trimmed_) return d;
    if constexpr (sizeof(T) == sizeof(float)) {
      return trim_to_box(p, lo_float_, hi_float_, d);
    } else {
      return trim_to_box(p, Vec3<T>{lo_.x, lo_.y, lo_.z}, Vec3<T>{hi_.x, hi_.y, hi_.z}, d);
    }
  }

  /// `float FUNCTION(vec3 p)`: the distance of F = 0 before trimming (the scene's
  /// GLSL applies PREFIX_trim with trim_lo/trim_hi when trimmed()).
  std::string to_glsl(const std::string& function) const {
    return fast_ ? fast_->to_glsl(function) : safe_->to_glsl(function);
  }

  /// Whether the leaf is a trimmed sheet.
  bool trimmed() const { return trimmed_; }
  /// The shape the leaf's value describes (never automatic: what was picked).
  SdfShape shape() const { return shape_; }
  /// Why that shape: "asked", or decide_enclosure()'s reason under automatic.
  const std::string& shape_reason() const { return shape_reason_; }
  /// Whether the value is that of −F (a solid whose F is negative on its box's
  /// boundary: the enclosed region is then where F > 0).
  bool negated() const { return negated_; }
  /// The trimming box's corners as floats (rounded outwards from the exact bound).
  const Vec3<float>& trim_lo() const { return lo_float_; }
  /// See trim_lo().
  const Vec3<float>& trim_hi() const { return hi_float_; }
  /// The implicit equation F (in x, y, z; a curve's has no z), as given or
  /// implicitized, before any negation (negated()).
  const Polynomial& equation() const { return equation_; }
  /// The frame box the distance is computed in.
  const SceneBox& frame_box() const { return frame_box_; }

 private:
  explicit PolynomialLeaf(Polynomial equation) : equation_(std::move(equation)) {}

  Polynomial equation_;
  // Exactly one is set, by the mode (a branch per evaluation is cheaper than
  // std::visit's dispatch and reads as plainly).
  std::optional<FastSdf> fast_;
  std::optional<SafeSdf> safe_;
  SceneBox frame_box_;
  SdfShape shape_ = SdfShape::solid;
  std::string shape_reason_;
  bool negated_ = false;
  bool trimmed_ = false;
  Vec3<double> lo_, hi_;
  Vec3<float> lo_float_, hi_float_;
};

}  // namespace implicitizer
