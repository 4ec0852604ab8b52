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
/// boundary and encloses a region; else sheet. A parametric leaf over a bounded
/// domain is a sheet under automatic (the patch, trimmed below); asked for a solid it
/// is the solid F <= 0 in its frame box, untrimmed.
///
/// Curves (SceneParams::dimension 2). The equation is F(x, y) (a z in it is
/// `unknown_variable`), or the implicitization of a parametrization with x and y only;
/// the leaf is the 3-D leaf of the cylinder F(x, y) = 0 over the curve, in the frame
/// box [x0, x1]×[y0, y1]×[−m, m] with m the larger half side of the 2-D box (so the
/// frame's scale is the 2-D box's), evaluated by the scene at z = 0: the distance in
/// space from (x, y, 0) to the cylinder is the planar distance to the curve, so both
/// modes keep their meaning (docs/sdf.md, "Curves").
///
/// Patches. A parametric leaf is the patch X(D) of its domain D (the source's, else
/// the default domain of patch_domain.hpp: the whole parameter plane when the
/// parametrization is bounded on it, else [0, 1]^m). Without a box of its own the
/// frame box is fitted to X(D): the exact bound of bound_patch() padded by 1e-3 of its
/// largest side. Over a bounded domain a sheet is trimmed to a PatchCover
/// (patch_cover.hpp), boxes B_k with X(D) ⊂ ∪ B_k, and its value is
///     t(p) = max(|d(p)|, D(p)),  D(p) <= dist(p, ∪ B_k),
/// computed by PatchCover::distance_lower_bound. It is 0 on X(D) (d = 0 there and
/// p lies in a box) and a lower bound of the distance to X(D) whenever |d| is one of
/// the distance to Z = {F = 0} (safe mode), because X(D) ⊂ Z ∩ ∪ B_k gives
/// dist(p, X(D)) >= max(dist(p, Z), dist(p, ∪ B_k)). Points of Z farther than 0.1·h
/// from X(D) get values above 0.01·h (patch_cover.hpp says why). A trimmed leaf has
/// no inside (t >= 0 everywhere): it is meant for union and intersection; as the
/// subtrahend of a difference it removes nothing. Over the whole plane X(D) is, up to
/// its closure, all of Z in the fitted box (a closed surface): nothing is trimmed, the
/// frame box clips as for an implicit leaf and auto may pick a solid (docs/sdf.md,
/// "Patches").

#include <array>
#include <optional>
#include <string>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/scene/patch_cover.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/scene/vec3.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"
#include "implicitizer/sdf/scene_frame.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer {

/// One compiled polynomial leaf.
class PolynomialLeaf {
 public:
  /// Builds the leaf of `source` (kind implicit or parametric; see scene_node.hpp)
  /// under `budget`: parses (ring x, y, z), implicitizes (parametric), bounds the
  /// patch over its domain (parametric), compiles the distance of `mode` in the
  /// leaf's box (source.box, else, parametric, the padded patch box, else
  /// `default_box`) and covers the patch (a sheet over a bounded domain).
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
    return cover_ ? cover_->distance_lower_bound(p, d) : d;
  }

  /// `float FUNCTION(vec3 p)`: the distance of F = 0 before trimming (the scene's
  /// GLSL applies the cover's function when trimmed()).
  std::string to_glsl(const std::string& function) const {
    return fast_ ? fast_->to_glsl(function) : safe_->to_glsl(function);
  }

  /// Whether the leaf is a patch trimmed to its cover.
  bool trimmed() const { return cover_.has_value(); }
  /// The shape the leaf's value describes (never automatic: what was picked).
  SdfShape shape() const { return shape_; }
  /// Why that shape: "asked", or decide_enclosure()'s reason under automatic.
  const std::string& shape_reason() const { return shape_reason_; }
  /// Whether the value is that of −F (a solid whose F is negative on its box's
  /// boundary: the enclosed region is then where F > 0).
  bool negated() const { return negated_; }
  /// The cover a trimmed leaf is cut to (null when not trimmed).
  const PatchCover* cover() const { return cover_ ? &*cover_ : nullptr; }
  /// The box around the cover's boxes, float corners (trimmed leaves only).
  Vec3<float> trim_lo() const { return cover_->lo(); }
  /// See trim_lo().
  Vec3<float> trim_hi() const { return cover_->hi(); }
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
  std::optional<PatchCover> cover_;
};

}  // namespace implicitizer
