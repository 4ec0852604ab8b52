#pragma once
/// \file
/// The leaves of a scene that are polynomial surfaces: an implicit equation F = 0, or a
/// parametric surface implicitized by the library (implicitize.hpp). Both become the
/// distance function of mode fast (FastSdf: F/|∇F|) or safe (SafeSdf: a lower bound)
/// of F = 0 in the leaf's frame box, named NAME_leaf<k> in the GLSL.
///
/// Patches. A parametric leaf is the patch X(D) of its domain D (the source's, else
/// the default domain of patch_domain.hpp: the whole parameter plane when the
/// parametrization is bounded on it, else [0, 1]^m). Without a box of its own the
/// frame box is fitted to X(D): the exact bound of bound_patch() padded by 1e-3 of its
/// largest side. Over a bounded domain the leaf is trimmed to a PatchCover
/// (patch_cover.hpp), boxes B_k with X(D) ⊂ ∪ B_k, and its value is the sheet
///     t(p) = max(|d(p)|, D(p)),  D(p) <= dist(p, ∪ B_k),
/// computed by PatchCover::distance_lower_bound. It is 0 on X(D) (d = 0 there and
/// p lies in a box) and a lower bound of the distance to X(D) whenever |d| is one of
/// the distance to Z = {F = 0} (safe mode), because X(D) ⊂ Z ∩ ∪ B_k gives
/// dist(p, X(D)) >= max(dist(p, Z), dist(p, ∪ B_k)). Points of Z farther than 0.1·h
/// from X(D) get values above 0.01·h (patch_cover.hpp says why). A trimmed leaf has
/// no inside (t >= 0 everywhere): it is meant for union and intersection; as the
/// subtrahend of a difference it removes nothing. Over the whole plane X(D) is, up to
/// its closure, all of Z in the fitted box (a closed surface): nothing is trimmed and
/// the frame box clips as for an implicit leaf (docs/sdf.md, "Patches").

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
  /// `default_box`) and covers the patch (bounded domain).
  /// Errors are InputError with field `field` + ".equation" / ".x" / ".domain" / … :
  /// parse errors, `constant_polynomial`, `invalid_box`, `degree_too_high` (safe),
  /// `invalid_domain`, `unbounded_patch`, `no_single_equation` (the image is not a
  /// surface); LimitExceeded from the budget.
  static PolynomialLeaf build(NodeKind kind, const PolynomialLeafSource& source, const SceneBox& default_box,
                              SdfMode mode, const Budget& budget, const std::string& field);

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
  SdfShape shape() const { return trimmed() ? SdfShape::sheet : SdfShape::solid; }
  /// The cover a trimmed leaf is cut to (null when not trimmed).
  const PatchCover* cover() const { return cover_ ? &*cover_ : nullptr; }
  /// The box around the cover's boxes, float corners (trimmed leaves only).
  Vec3<float> trim_lo() const { return cover_->lo(); }
  /// See trim_lo().
  Vec3<float> trim_hi() const { return cover_->hi(); }
  /// The implicit equation F (in x, y, z).
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
  std::optional<PatchCover> cover_;
};

}  // namespace implicitizer
