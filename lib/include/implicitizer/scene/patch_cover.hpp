#pragma once
/// \file
/// Boxes covering a patch X(D): what trims a parametric leaf to the patch its request
/// names (docs/sdf.md, "Patches").
///
/// Construction. A quadtree over the parameter box D (a binary tree for curves) whose
/// nodes carry exact boxes of their sub-patches (bound_patch() on the sub-domain: the
/// rational Bézier hull, patch_bounds.hpp). A node is a leaf once its box is small
/// (largest side <= tolerance·h, h the frame box's largest half side) or once it is
/// shown not to reach any far cell: a cell of space that may hold a point of the
/// algebraic surface Z = {F = 0} farther than reach·h from X(D). Whether a node's
/// box, widened by margin·h, reaches a far cell is asked of a search that subdivides
/// cells of that box (centre c, half diagonal r), stopping at the first far cell, and
/// drops a cell when
///   - the safe bound (safe_sdf.hpp, on a box enlarged by h/2 so that its faces do
///     not clip it) proves dist(c, Z) > r: the cell holds no point of Z; or
///   - a sample point of X(D) lies within reach·h − r of c: every point of the cell
///     is within reach·h of X(D) (the sample is a subset of X(D), so a sparse sample
///     only costs work, never correctness);
/// a cell still undecided at half diagonal <= resolution·h is far (and remembered:
/// later queries check the far cells found so far first). Both drops are proofs (up
/// to the double rounding of the sample points, covered by a slack), so:
/// a point q of Z in the frame box within margin·h of a leaf box B that is not small
/// is in no far cell, hence within reach·h of X(D). When the surface's safe bound
/// cannot be built (degree_too_high) only the second drop applies: the cover is then
/// a uniform refinement to the tolerance near every part of Z.
///
/// Consequence (the requirement, with the default parameters): let q be a
/// point of Z in the frame box farther than 0.1·h from X(D). If q were within 0.01·h
/// of a leaf box B, either B is small (diagonal <= √3/20·h < 0.0867·h, and B holds a
/// point of X(D), so q is within 0.0967·h of X(D)) or q is within reach·h = 0.09·h of
/// X(D): both false. So the distance to the union of the leaf boxes, D(p), exceeds
/// 0.01·h at q, and max(|d|, D(p)) does too. A leaf count cap (max_leaves) can stop
/// the refinement first; stats().unresolved then says how many leaves are neither
/// small nor proven, and stats().tolerance_reached how large the largest is.
///
/// Slabs. A box trims no closer than its own size: where Z continues past an edge of
/// D, up to a box of it stays inside. So each leaf also carries three slabs
/// lo_i <= w_i·(x − o) <= hi_i (o the box's lower corner) that its sub-patch lies in,
/// their normals taken from tangent frames: for a surface, w_n ∥ X_s × X_t at the
/// sub-domain's centre and the two in-plane normals w_s ⊥ X_t and w_t ⊥ X_s at the
/// middle of the leaf's side nearer D's edge in that parameter (the centre when the
/// leaf spans D in it), so that the faces of w_s lie along the sub-patch's s-edges and
/// those of w_t along its t-edges, bent away from the nearer one only by its curvature
/// (second order in the side's length, whatever the leaf's depth across it); for a
/// curve, its tangent and two normals. The bounds are exact
/// (bound_patch() of the rotated patch w·X, each w_i a float vector read exactly,
/// |w_i| <= 1 by construction) rounded outwards to float. For every x of the sub-patch
/// and every p, |p − x| >= w_i·(p − x) >= w_i·(p − o) − hi_i (and lo_i − w_i·(p − o)),
/// so the largest slab excess s(p) is a lower bound of the distance to the sub-patch;
/// the leaf's value is max(box distance, s(p) − kSlabSlack·|p − o|_∞), the slack
/// covering the rounding of p − o and of the three dot products (at most 4 roundings
/// of relative 2^-23 on at most √3·|p − o|_∞), the rest relative and inside the
/// final shrink. A leaf without a tangent frame (X_s × X_t vanishing at its centre) or
/// with a slab bound beyond float's range keeps its box alone (stats().box_leaves); its
/// slabs are then zero, 0 <= 0·x <= 0, which the GLSL leaves out.
///
/// Edges. Let σ be how far the sub-patch's edge on ∂D lies inside the facing slab
/// face (the bound of w·X over that edge against the face). A point of Z a distance d
/// past the edge continues the patch across it; the face contains the normal w_n, so
/// the point's excess over it is its distance to the face within the tangent plane,
/// about d − σ. A leaf on an edge of D across which Z continues inside the frame
/// (sampled: the continuation a sharp_reach·h step past the edge, at points about
/// 0.01·h apart, lies within 1.05·sharp_value·h of the frame box) is halved along that
/// edge until σ <= (sharp_reach − 1.2·sharp_value)·h, so that points of Z sharp_reach·h
/// past the edge get values above sharp_value·h (docs/sdf.md, "Patches", measures it).
/// Z past the same edge beside the leaf belongs to its neighbours, but where X_s and
/// X_t are nearly parallel the leaf's in-plane slab along the edge is wide and can take
/// it in: a leaf whose box and slabs come within 1.2·sharp_value·h of such a point
/// (1025 samples per edge) is halved along the edge too, down to 1/32 of D.
///
/// Evaluation. The leaves, in quadtree order, are grouped in clusters of
/// cluster_size (default ⌈√leaves⌉) consecutive leaves (the last one padded by repeating its last leaf),
/// each with the box around its leaves and a point of its sub-patch. distance_lower_bound()
/// starts from the squared distance to the nearest cluster point (raised by its
/// rounding: at least D(p)², since D(p) <= dist(p, X(D))), walks the clusters, opens
/// only those closer than the best so far, evaluates a leaf's slabs only when its box
/// is closer than the best, and returns as soon as the best is within |d| (the
/// cluster's and the leaf's box distances are at most the leaf's value, so a skipped
/// leaf could not have lowered the minimum; whatever the start, the result is at most
/// the smallest leaf value). Boxes are stored rounded outwards (float and double; corners beyond
/// float's range clamped to ±FLT_MAX, which only shortens distances), squared
/// distances are computed with each component clamped to 1e18 (no overflow; a
/// smaller distance), and the final square root is multiplied by 1 − 2^−17 (float;
/// 1 − 2^−46 for double), more than the relative rounding of the few operations
/// involved, so the result is at most the true distance to the union of the leaves.
/// to_glsl() prints the same steps.

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/scene/vec3.hpp"
#include "implicitizer/sdf/scene_frame.hpp"

namespace implicitizer {

/// How finely build() covers a patch (lengths as fractions of h, the frame box's
/// largest half side).
struct PatchCoverParams {
  double tolerance = 1.0 / 20;    ///< leaves whose largest side is at most tolerance·h are never split
  double reach = 0.09;            ///< points of Z within reach·h of X(D) may lie near a leaf box
  double margin = 0.0105;         ///< how close to a leaf box a far point must not come (0.01·h and slack)
  double resolution = 0.01;       ///< the half diagonal at which the far-cell search stops subdividing
  std::size_t max_leaves = 1024;  ///< the refinement stops splitting here
  /// Leaves per cluster; 0: ⌈√leaves⌉, which balances the clusters every evaluation
  /// visits against the leaves of a cluster it opens.
  std::size_t cluster_size = 0;
  std::size_t tightening_depth = 1;          ///< bound_patch()'s tightening per node box
  std::size_t max_search_cells = 4'000'000;  ///< cells the far-cell search may visit (LimitExceeded beyond)
  /// Edge sharpness: a leaf at an edge of D across which Z continues inside the frame
  /// is split until a point of Z `sharp_reach`·h past that edge gets a slab value
  /// above `sharp_value`·h (the file comment's "Edges").
  double sharp_reach = 0.003;
  double sharp_value = 0.001;  ///< see sharp_reach
};

/// What build() did.
struct PatchCoverStats {
  std::size_t leaves = 0;           ///< leaf boxes
  std::size_t clusters = 0;         ///< clusters of cluster_size leaves
  std::size_t nodes = 0;            ///< quadtree nodes bounded (leaves and inner nodes)
  std::size_t sample_points = 0;    ///< points of X(D) sampled for the far-cell search
  std::size_t search_cells = 0;     ///< cells visited by the far-cell search
  std::size_t far_cells = 0;        ///< cells that may hold far points of Z
  bool proven_empty_cells = false;  ///< whether the safe bound was available to drop cells without Z
  std::size_t unresolved = 0;       ///< leaves neither small nor proven away from far cells (the cap stopped them)
  double tolerance_reached = 0;     ///< largest side / h of an unresolved leaf (0: none)
  std::size_t box_leaves = 0;       ///< leaves trimmed by their box alone (no tangent frame: a singular point)
  std::size_t edge_unresolved = 0;  ///< edge leaves the cap left blunter than sharp_reach
};

/// The boxes covering X(D), ready to evaluate in C++ and GLSL.
class PatchCover {
 public:
  /// Covers X(`domain`) of `parametrization` (2 or 3 coordinates; a plane curve lies
  /// in z = 0) for the surface `equation` F(x, y, z) (its implicit equation, in a
  /// ring of three variables) trimmed inside `frame_box`. Preconditions: bound_patch()
  /// succeeded on `domain` (no denominator vanishes there), every interval has lo < hi.
  /// Throws LimitExceeded from `budget` (time, cancellation; size: sample points and
  /// far cells count as terms) or when the search exceeds params.max_search_cells.
  static PatchCover build(const Parametrization& parametrization, const ParameterDomain& domain,
                          const Polynomial& equation, const SceneBox& frame_box, const Budget& budget = Budget(),
                          const PatchCoverParams& params = PatchCoverParams());

  /// max(|d|, D(p)) with D(p) <= the distance from p to the patch, the smallest of
  /// the leaves' values (the file comment's steps; float: the GLSL's arithmetic).
  template <typename T>
  T distance_lower_bound(const Vec3<T>& p, T d) const {
    const Boxes<T>& b = boxes<T>();
    const T ad = std::abs(d);
    const T d2 = ad * ad;
    T best = seed_squared(b, p);
    if (best <= d2) return ad;
    const std::size_t k = cluster_size_;
    for (std::size_t c = 0; c < b.cluster_lo.size(); ++c) {
      if (squared_distance(p, b.cluster_lo[c], b.cluster_hi[c]) < best) {
        for (std::size_t j = c * k; j < (c + 1) * k; ++j) best = leaf_squared(b, j, p, best);
        if (best <= d2) return ad;
      }
    }
    return std::max(ad, std::sqrt(best) * b.shrink);
  }

  /// A lower bound of distance_lower_bound(p, d) for every d: the distance to the box
  /// around all leaf boxes (lo(), hi()), by the same steps, shrunk by a further
  /// kHullShrink. Each leaf box lies in that box, so every rounded step of the walk is
  /// at least the hull's (correctly rounded operations are monotone); the extra factor
  /// covers a GPU's own freedoms (a fused multiply-add). What lets a union of covered
  /// pieces skip a piece whose hull is no nearer than the best value so far.
  template <typename T>
  T hull_distance_lower_bound(const Vec3<T>& p) const {
    const Boxes<T>& b = boxes<T>();
    return std::sqrt(squared_distance(p, b.hull_lo, b.hull_hi)) * (b.shrink * T(kHullShrink));
  }
  /// The GLSL expression of hull_distance_lower_bound<float>(`p`), `p` a vec3 expression
  /// without side effects.
  std::string hull_glsl(const std::string& p) const;
  /// The further factor of hull_distance_lower_bound().
  static constexpr double kHullShrink = 1.0 - 0x1p-16;

  /// `float FUNCTION(vec3 p, float d)` and its helpers FUNCTION_d2, FUNCTION_s2 and FUNCTION_leaf, computing
  /// distance_lower_bound<float>: the same walk, unrolled, the boxes stated as
  /// literals. Precondition: FUNCTION is a valid GLSL identifier.
  std::string to_glsl(const std::string& function) const;
  /// The other global names to_glsl(FUNCTION) defines: FUNCTION + each suffix.
  static std::vector<std::string> glsl_suffixes() { return {"_d2", "_s2", "_leaf"}; }

  /// What build() did.
  const PatchCoverStats& stats() const { return stats_; }
  /// The leaf boxes (padded to whole clusters), corners rounded outwards to float.
  const std::vector<Vec3<float>>& leaf_lo() const { return float_.lo; }
  /// See leaf_lo().
  const std::vector<Vec3<float>>& leaf_hi() const { return float_.hi; }
  /// Each leaf's slab normals w_i (i = 0, 1, 2; all zero: no slabs), aligned with leaf_lo().
  const std::vector<Vec3<float>>& leaf_slab_normals(std::size_t i) const {
    return i == 0 ? float_.w0 : (i == 1 ? float_.w1 : float_.w2);
  }
  /// Each leaf's lower slab bounds of w_i·(x − leaf_lo()), one component per slab.
  const std::vector<Vec3<float>>& leaf_slab_lo() const { return float_.slab_lo; }
  /// See leaf_slab_lo().
  const std::vector<Vec3<float>>& leaf_slab_hi() const { return float_.slab_hi; }
  /// The union of the leaf boxes' float corners (the box the trimmed leaf lies in).
  Vec3<float> lo() const;
  /// See lo().
  Vec3<float> hi() const;

  /// The starting value of the squared distance (finite, above any clamped square).
  static constexpr double kFarSquared = 3.0e38;
  /// The slab excess is lowered by this times |p − o|_∞ (float; kSlabSlackDouble in
  /// double): 4 roundings of 2^-23 on at most √3·|p − o|_∞ is 8.3·2^-23 < 2^-19.
  static constexpr double kSlabSlack = 0x1p-19;
  /// See kSlabSlack (the same count of roundings of 2^-52).
  static constexpr double kSlabSlackDouble = 0x1p-48;
  /// Each component of a box distance is clamped to this before squaring.
  static constexpr double kClamp = 1e18;
  /// The seed's relative raise: far above the few roundings of a squared distance.
  static constexpr double kSeedScale = 1.0 + 0x1p-10;

 private:
  // Sets the double boxes to the float ones (exact in double) and both shrink factors.
  void copy_boxes_to_double();

  template <typename T>
  struct Boxes {
    std::vector<Vec3<T>> lo, hi;                  // cluster_size_ per cluster
    std::vector<Vec3<T>> w0, w1, w2;              // each leaf's slab normals (0: no slabs)
    std::vector<Vec3<T>> slab_lo, slab_hi;        // its slab bounds, relative to lo
    T slack = 0;                                  // kSlabSlack or kSlabSlackDouble
    std::vector<Vec3<T>> cluster_lo, cluster_hi;  // one per cluster
    std::vector<Vec3<T>> cluster_point;           // a point of each cluster's sub-patch
    T seed_margin = 0;                            // added to the seed: the points' rounding
    Vec3<T> hull_lo{}, hull_hi{};                 // the box around every leaf box
    T shrink = 1;
  };

  template <typename T>
  static T squared_distance(const Vec3<T>& p, const Vec3<T>& lo, const Vec3<T>& hi) {
    const Vec3<T> q{std::max(lo.x - p.x, p.x - hi.x), std::max(lo.y - p.y, p.y - hi.y),
                    std::max(lo.z - p.z, p.z - hi.z)};
    const Vec3<T> m = min(max(q, T(0)), T(kClamp));
    return m.x * m.x + m.y * m.y + m.z * m.z;
  }

  // The walk's starting best: the squared distance to the nearest cluster point, a point
  // of X(D) up to its rounding, so at least D(p)² once raised by kSeedScale and the
  // points' rounding. Any start is safe (a cluster left closed has leaf values at
  // least its box distance, at least best); this one only lets the walk skip the
  // clusters farther than the patch is already known to be near.
  template <typename T>
  static T seed_squared(const Boxes<T>& b, const Vec3<T>& p) {
    T best = T(kFarSquared);
    for (const Vec3<T>& s : b.cluster_point) {
      const Vec3<T> q = p - s;
      best = std::min(best, q.x * q.x + q.y * q.y + q.z * q.z);
    }
    return best * T(kSeedScale) + b.seed_margin;
  }

  // min(best, leaf j's squared value): the larger of its box distance and the square of
  // its slab excess less the slack (0 when negative). The GLSL computes the same without
  // a branch, since SwiftShader paid far more for a return inside the leaf's function
  // than for its arithmetic (docs/sdf.md, "Patches"); here a leaf whose box is no nearer
  // than best is skipped, which gives the same min.
  template <typename T>
  static T leaf_squared(const Boxes<T>& b, std::size_t j, const Vec3<T>& p, T best) {
    const T a = squared_distance(p, b.lo[j], b.hi[j]);
    if (!(a < best)) return best;
    const Vec3<T> d = p - b.lo[j];
    const Vec3<T> q{dot(d, b.w0[j]), dot(d, b.w1[j]), dot(d, b.w2[j])};
    const Vec3<T> s = max(b.slab_lo[j] - q, q - b.slab_hi[j]);
    const T t = std::max(std::max(std::max(s.x, s.y), s.z) -
                             b.slack * std::max(std::max(std::abs(d.x), std::abs(d.y)), std::abs(d.z)),
                         T(0));
    return std::min(best, std::max(a, t * t));
  }

  template <typename T>
  const Boxes<T>& boxes() const {
    if constexpr (sizeof(T) == sizeof(float)) {
      return float_;
    } else {
      return double_;
    }
  }

  Boxes<float> float_;
  Boxes<double> double_;
  std::size_t cluster_size_ = 1;
  PatchCoverStats stats_;
};

}  // namespace implicitizer
