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
/// frame box is fitted to X(D): the exact bound of bound_patch() padded by 1e-4 of its
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
///
/// Approximated patches (a tolerance EPS, issue 19). A parametric leaf over a bounded
/// domain with source.tolerance is the cheaper of two representations, both within
/// EPS·diag of X(D): its exact equation (the trimmed sheet above, error 0), and the
/// approximation of approximate_patch() (approximation/patch_approximation.hpp):
/// pieces q_k = 0 over sub-domains S_k, the leaf their union, min_k t_k(p), each t_k
/// the trimmed sheet above for q_k in its own frame box (the exact box of X(S_k)
/// padded as a patch's) and its own cover of X(S_k). Each t_k is >= 0, so the min is
/// the union of the sheets. In safe mode each t_k is a lower bound of the distance to
/// {q_k = 0} inside X(S_k)'s cover, so the min is one of the distance to the union of
/// those trimmed zero sets; that union is within EPS·diag of X(D) both ways
/// (approximation() reports the two bounds and how they were established), which is
/// the error against the true patch. Cheaper means fewer GLSL lines (glsl_lines(): what
/// a scene embeds and a shader compiler digests); the approximation stops as soon as it
/// cannot win, and where the exact equation wins, or no approximation meets EPS within
/// ApproximationParams' limits, the leaf is exact and tolerance_kept_exact() says why.
/// ToleranceNotMet only when neither exists (safe mode refusing the exact equation as
/// degree_too_high). An approximation is a sheet: asking it for a solid is InputError
/// `invalid_tolerance` (an approximating surface's inside says nothing about the
/// patch). Over the whole parameter plane (closed surfaces: sphere, torus, Steiner's
/// surface) the leaf keeps its exact equation, whose degree is already low.

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/approximation/patch_approximation.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/scene/patch_cover.hpp"
#include "implicitizer/scene/polytope_trim.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/scene/sheet_side.hpp"
#include "implicitizer/scene/vec3.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"
#include "implicitizer/sdf/scene_frame.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer {

/// How a trimmed leaf cuts its surface to its patch (the answers' "trimming").
struct TrimmingSummary {
  /// "slabs": every cover leaf has its slabs and every edge met the sharpness
  /// criterion (patch_cover.hpp, "Edges"); "slabs and boxes": some leaves have a box
  /// alone (no tangent plane at their centre) or the leaf cap left edges blunt;
  /// "polytopes": an approximation's pieces cut by their polytopes (each piece's
  /// planes, measured with the approximation); "polytopes and slabs": both kinds of
  /// pieces.
  std::string method;
  std::size_t leaves = 0;             ///< cover leaves over all pieces
  std::size_t box_leaves = 0;         ///< of which with their box alone
  std::size_t blunt_edge_leaves = 0;  ///< edge leaves the cap left blunter than the criterion
};

/// One compiled polynomial leaf.
class PolynomialLeaf {
 public:
  /// Builds the leaf of `source` (kind implicit or parametric; see scene_node.hpp)
  /// under `budget`: parses (ring x, y, z), implicitizes (parametric) or approximates
  /// too (parametric with a tolerance over a bounded domain), bounds the patch over its
  /// domain (parametric), compiles the distance of `mode` in the leaf's box
  /// (source.box, else, parametric, the padded patch box, else `default_box`; an
  /// approximation's pieces each in their own padded box) and covers the patch (a
  /// sheet over a bounded domain).
  /// Errors are InputError with field `field` + ".equation" / ".x" / ".domain" / … :
  /// parse errors, `constant_polynomial`, `invalid_box`, `degree_too_high` (safe),
  /// `invalid_domain`, `unbounded_patch`, `no_single_equation` (the image is not a
  /// surface), `invalid_tolerance` (".tolerance": not in (0, 0.5], an implicit leaf's,
  /// a curve's, or with shape solid); ToleranceNotMet (no approximation reaches the
  /// tolerance and safe mode refuses the exact equation); LimitExceeded from the budget.
  /// `dimension` is 3 (a surface) or 2 (a plane curve, see the file comment; a
  /// parametric curve's z text must be empty, else InputError `invalid_value` at
  /// field + ".z"). The shape is resolved as the file comment says.
  static PolynomialLeaf build(NodeKind kind, const PolynomialLeafSource& source, const SceneBox& default_box,
                              SdfMode mode, const Budget& budget, const std::string& field, int dimension = 3);

  /// The leaf's value at p: d (untrimmed, signed), the trimmed sheet, or the min of
  /// the pieces' trimmed sheets (an approximation). A piece's value, max(|d|, its
  /// cover's distance), is at least both |d| and its cover's hull distance
  /// (PatchCover::hull_distance_lower_bound), so a piece whose hull is no nearer than
  /// the min so far is skipped, and so is the cover of one whose |d| is not below it:
  /// the min is the same, and a point meets only the polynomials of the pieces near
  /// it and only the covers of the sheets near it (the GLSL does the same).
  template <typename T>
  T evaluate(const Vec3<T>& p) const {
    T value = pieces_.front().evaluate(p);
    for (std::size_t k = 1; k < pieces_.size(); ++k) {
      const Piece& piece = pieces_[k];
      if (!(piece.hull_distance_lower_bound(p) < value)) continue;
      const T d = piece.distance(p);
      if (std::abs(d) < value) value = std::min(value, piece.trim(p, d));
    }
    return value;
  }

  /// How many surfaces the leaf joins by min: 1, or an approximation's pieces.
  std::size_t piece_count() const { return pieces_.size(); }
  /// Fewer lines than any piece of a trimmed leaf takes: its distance function alone has
  /// a comment, the frame, the box distance and the far-field return before its first
  /// term (and its cover more). A tolerance's approximation stops once its pieces plus
  /// this much per sub-domain left reach the exact leaf's lines.
  static constexpr std::size_t kMinPieceGlslLines = 16;
  /// Mode fast: an approximated piece's |q/|grad q|| is capped at this fraction of its
  /// frame box's largest half side (FastSdf::build's sheet_cap).
  static constexpr double kPieceEstimateCap = 0.25;
  /// The lines the leaf adds to a scene's GLSL: its pieces' distance functions and
  /// covers, and each further piece's culling test (what a tolerance compares).
  std::size_t glsl_lines() const;
  /// `float FUNCTION(vec3 p)`: the distance of piece k's surface (F = 0, or q_k = 0)
  /// before trimming (the scene's GLSL applies piece k's trimming when trimmed()).
  std::string to_glsl(const std::string& function, std::size_t k = 0) const {
    const Piece& piece = pieces_[k];
    return piece.fast ? piece.fast->to_glsl(function) : piece.safe->to_glsl(function);
  }
  /// The cover piece k is cut to (null when not trimmed, or trimmed to a polytope).
  const PatchCover* cover(std::size_t k = 0) const { return pieces_[k].cover ? &*pieces_[k].cover : nullptr; }
  /// The polytope approximated piece k is cut to (null: none, or a cover).
  const PolytopeTrim* polytope(std::size_t k = 0) const {
    return pieces_[k].polytope ? &*pieces_[k].polytope : nullptr;
  }
  /// `float FUNCTION(vec3 p, float d)`: piece k's trimming applied to its distance d
  /// (its cover's or its polytope's; precondition: trimmed()).
  std::string trim_glsl(const std::string& function, std::size_t k = 0) const;
  /// The global names trim_glsl(FUNCTION, k) defines besides FUNCTION: FUNCTION + each suffix.
  std::vector<std::string> trim_glsl_suffixes(std::size_t k = 0) const;
  /// The GLSL expression of piece k's hull distance at `p` (the culling test's).
  std::string trim_hull_glsl(const std::string& p, std::size_t k = 0) const;

  /// Whether the leaf is a patch trimmed to its cover(s) or polytopes.
  bool trimmed() const { return pieces_.front().cover || pieces_.front().polytope; }
  /// How it is trimmed (precondition: trimmed()).
  TrimmingSummary trimming() const;
  /// The shape the leaf's value describes (never automatic: what was picked).
  SdfShape shape() const { return shape_; }
  /// Why that shape: "asked", or decide_enclosure()'s reason under automatic.
  const std::string& shape_reason() const { return shape_reason_; }
  /// Whether the value is that of −F (a solid whose F is negative on its box's
  /// boundary: the enclosed region is then where F > 0).
  bool negated() const { return negated_; }
  /// The box around every piece's trimming (cover boxes or polytope boxes), float
  /// corners (trimmed leaves only).
  Vec3<float> trim_lo() const { return trim_corner(false); }
  /// See trim_lo().
  Vec3<float> trim_hi() const { return trim_corner(true); }
  /// The implicit equation F (in x, y, z; a curve's has no z), as given or
  /// implicitized, before any negation (negated()); for an approximation, its first
  /// piece's q (approximation() has every piece).
  const Polynomial& equation() const { return equation_; }
  /// The frame box the distance is computed in (an approximation: the box fitted to
  /// the whole patch, which the answers report; each piece has its own).
  const SceneBox& frame_box() const { return frame_box_; }
  /// An approximation's side (sheet_side.hpp): the signed companion renderers read to
  /// tell its sides apart and notice steps across it (null: not an approximation).
  const SheetSide* sheet_side() const { return side_ ? &*side_ : nullptr; }
  /// The approximation the leaf is built from (null: the exact equation).
  const PatchApproximation* approximation() const { return approximation_ ? &*approximation_ : nullptr; }
  /// The tolerance the source asked for (none: exact).
  std::optional<double> tolerance() const { return tolerance_; }
  /// Why a leaf with a tolerance kept its exact equation ("" when it did not).
  const std::string& tolerance_kept_exact() const { return kept_exact_; }

 private:
  // One surface of the leaf, in its own frame box, trimmed to its own cover or (an
  // approximated piece whose zeros there met the tolerance) its own polytope.
  struct Piece {
    // Exactly one is set, by the mode (a branch per evaluation is cheaper than
    // std::visit's dispatch and reads as plainly).
    std::optional<FastSdf> fast;
    std::optional<SafeSdf> safe;
    // At most one is set: none for an untrimmed leaf.
    std::optional<PatchCover> cover;
    std::optional<PolytopeTrim> polytope;

    // The surface's distance, untrimmed.
    template <typename T>
    T distance(const Vec3<T>& p) const {
      return fast ? fast->evaluate<T>(p.x, p.y, p.z) : safe->evaluate<T>(p.x, p.y, p.z);
    }
    // The trimmed value of a distance d at p (d itself when untrimmed).
    template <typename T>
    T trim(const Vec3<T>& p, T d) const {
      if (cover) return cover->distance_lower_bound(p, d);
      return polytope ? polytope->distance_lower_bound(p, d) : d;
    }
    // A lower bound of trim(p, d) for every d (precondition: trimmed).
    template <typename T>
    T hull_distance_lower_bound(const Vec3<T>& p) const {
      return cover ? cover->hull_distance_lower_bound(p) : polytope->hull_distance_lower_bound(p);
    }
    template <typename T>
    T evaluate(const Vec3<T>& p) const {
      return trim(p, distance(p));
    }
  };

  // What the exact leaf is built from: F, and the patch it is trimmed to (both null:
  // untrimmed).
  struct ExactSource {
    NodeKind kind;
    const PolynomialLeafSource& source;
    const Polynomial& f;
    const SceneBox& frame_box;
    const Parametrization* parametrization;
    const ParameterDomain* domain;
    int dimension;
  };

  explicit PolynomialLeaf(Polynomial equation) : equation_(std::move(equation)) {}
  // The componentwise min (lower) or max (upper) of the pieces' cover corners.
  Vec3<float> trim_corner(bool upper) const;
  // Lines piece k adds to the scene's GLSL: its functions, and beyond the first its
  // culling test and min.
  std::size_t piece_glsl_lines(std::size_t k) const;
  // The leaf of F: its distance in the frame box, trimmed to the patch's cover.
  static PolynomialLeaf build_exact(const ExactSource& in, SdfMode mode, const Budget& budget,
                                    const std::string& field);
  // The leaf of a patch with a tolerance: the approximation when its GLSL is shorter
  // than `exact`'s, else `exact` saying why (none: `no_exact` says why).
  static PolynomialLeaf build_cheapest(std::optional<PolynomialLeaf> exact, const std::string& no_exact,
                                       const Parametrization& parametrization, const ParameterDomain& domain,
                                       const SceneBox& frame_box, double tolerance, SdfMode mode, const Budget& budget,
                                       const std::string& field);
  // One approximation piece: q_k's distance in its own fitted box cut to the leaf's
  // frame box, trimmed to X(S_k)'s polytope where the approximation kept one, else its cover.
  static Piece build_piece(const ApproximationPiece& source, const Parametrization& parametrization,
                           const SceneBox& frame_box, SdfMode mode, const Budget& budget,
                           const std::string& field);

  Polynomial equation_;
  std::vector<Piece> pieces_;  // one, or an approximation's
  SceneBox frame_box_;
  SdfShape shape_ = SdfShape::solid;
  std::string shape_reason_;
  bool negated_ = false;
  std::optional<PatchApproximation> approximation_;
  std::optional<SheetSide> side_;
  std::optional<double> tolerance_;
  std::string kept_exact_;
};

}  // namespace implicitizer
