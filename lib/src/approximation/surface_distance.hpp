#pragma once
// The measured half of the two-sided bound, in double: how far points of {q = 0} near
// the patch lie from the patch, on a stated sample; and a quick estimate of the other
// direction that lets the driver skip the exact certificate of hopeless degrees.
//
// Sample (measure_surface_to_patch), on a 25×25 grid of parameters over the piece S
// widened by an eighth of its sides (for the caps of the tube beyond S's edges), with
// reach = 0.1·h (h the largest half side of the piece's box: the trimming keeps the
// points of {q = 0} within reach of X(S); the others found are dropped):
//   - every zero of q on the normal segment X(s, t) + λ·ν, |λ| <= reach, found by a
//     sign change between 17 equally spaced λ and bisection (sheets that cross the
//     tube: a random sample of 17×17 points with two offsets missed one of tp_22 at
//     1e-3 that the test's own sample found);
//   - X(s, t) moved by a random length up to reach and by reach itself, in uniformly
//     random directions (a fixed seed, so the answer is
//     reproducible), each Newton-projected onto {q = 0} along ∇q; converged points that moved at most reach are kept.
//     The distance of a kept point y to X(D')
// (D' = D widened by a quarter of its sides, so that the patch's continuation beyond
// the edge counts, as it does for the exact equation; the pieces are joined by min, so
// the patch as a whole is what a point of one piece's surface must be near) is
// the smaller |X(s*, t*) − y| of two Gauss–Newton projections (s*, t*) in D' of y,
// seeded at the nearest point of a 25×25 grid of S' (S widened likewise) and at that
// of a 25×25 grid of D' (a folded patch such as tp_22 brings another part close):
// the distance to an actual patch point, so never below the true distance. (S' alone
// is too short where the parametrization is slow: measured on tri_quartic near s = 0,
// points of {q = 0} at 0.1·h from X(S) lie by X(s < −S's quarter) of the exact patch.)

#include <array>
#include <cstddef>
#include <vector>

#include "implicitizer/approximation/trim_polytope.hpp"
#include "implicitizer/core/budget.hpp"
#include "patch_evaluator.hpp"

namespace implicitizer::approximation {

/// A rectangle of parameters in double: s0, s1, t0, t1.
using ParameterRect = std::array<double, 4>;

/// The result of measure_surface_to_patch().
struct SurfaceToPatch {
  double distance = 0;      ///< the largest distance found (0 when no point converged)
  std::size_t samples = 0;  ///< points of {q = 0} measured
  /// The largest distance of a measured point to X(S) itself (a polytope's only: the
  /// tube drops the points beyond its reach).
  double beyond_piece = 0;
};

/// R widened by a quarter of its sides on every side.
ParameterRect widened(const ParameterRect& r);

/// Points of the patch over a 25×25 grid of a parameter rectangle, with their
/// parameters: where the projections of distance_to_patch start.
struct SeedGrid {
  std::vector<Point> points;
  std::vector<std::array<double, 2>> parameters;
};

/// The zeros of q near X(S) of the file comment's sample, the seed grids of S, S' and
/// D', and the distances of the zeros computed on first use. A piece's two
/// measurements (its polytope's, then the tube's where the polytope is not kept) read
/// the same sample, so it is collected once.
class TubeSample {
 public:
  /// `domain` is D, `piece` S.
  TubeSample(const PatchEvaluator& patch, const FramedPolynomial& q, const ParameterRect& piece,
             const ParameterRect& domain, double reach, const Budget& budget);
  /// Whether every seed grid has a point (a patch defined nowhere on them has none).
  bool seeded() const;
  const std::vector<Point>& zeros() const { return zeros_; }
  /// The distance of y to X(S), and to X(D') (the smaller of the two projections).
  double to_piece(const Point& y) const;
  double to_patch(const Point& y) const;
  /// The same of zeros()[k], each computed at most once.
  double zero_to_piece(std::size_t k);
  double zero_to_patch(std::size_t k);
  double reach() const { return reach_; }

 private:
  const PatchEvaluator& patch_;
  ParameterRect piece_;
  ParameterRect whole_;  // D'
  double reach_;
  SeedGrid own_, near_, far_;  // over S, S' and D'
  std::vector<Point> zeros_;
  std::vector<double> to_piece_, to_patch_;  // NaN until computed
};

/// See the file comment.
SurfaceToPatch measure_surface_to_patch(TubeSample& tube);

/// The same measurement for a piece trimmed to `polytope` ∩ the box [lo, hi]
/// (trim_polytope.hpp) instead of the tube: the zeros of q that lie in both, found as
/// above (the tube's sample) and where q changes sign along lines parallel to x, y and
/// z through a 48×48 grid of the box's cross-section (48 samples per line, then
/// bisection; a sheet is crossed by the family most normal to it), measured against
/// X(D') as above; and against X(S) (beyond_piece), which says whether the polytope
/// keeps more of q's continuation past S's edges than the tube of the sample's reach
/// would.
SurfaceToPatch measure_polytope_to_patch(TubeSample& tube, const FramedPolynomial& q, const TrimPolytope& polytope,
                                         const Point& lo, const Point& hi, const Budget& budget);

/// max |q(X)|/|∇q(X)| over a side×side grid of the piece: the first-order distance of
/// the patch to {q = 0}, an estimate (not a bound) used only to skip degrees.
double estimate_patch_to_surface(const PatchEvaluator& patch, const FramedPolynomial& q, const ParameterRect& piece,
                                 std::size_t side);

}  // namespace implicitizer::approximation
