#pragma once
// The measured half of the two-sided bound, in double: how far points of {q = 0} near
// the patch lie from the patch, on a stated sample; and a quick estimate of the other
// direction that lets the driver skip the exact certificate of hopeless degrees.
//
// Sample (measure_surface_to_patch): a 16×16 grid of parameters over the piece S
// (cell centres), at each the patch point X(s, t) moved by a random offset of length
// up to `reach` (= 0.1·h, h the largest half side of the piece's box: the part of
// {q = 0} the trimming keeps) in a uniformly random direction (a fixed seed, so the
// answer is reproducible). Each is Newton-projected onto {q = 0} along ∇q; converged
// points that moved at most `reach` are kept. The distance of a kept point y to X(S')
// (S' = S widened by a quarter of its sides, so that the patch's continuation beyond
// the edge of S counts, as it does for the exact equation) is |X(s*, t*) − y| for the
// Gauss–Newton projection (s*, t*) of y seeded at the nearest point of a 25×25 grid of
// S': the distance to an actual patch point, so never below the true distance.

#include <array>
#include <cstddef>

#include "implicitizer/core/budget.hpp"
#include "patch_evaluator.hpp"

namespace implicitizer::approximation {

/// A rectangle of parameters in double: s0, s1, t0, t1.
using ParameterRect = std::array<double, 4>;

/// The result of measure_surface_to_patch().
struct SurfaceToPatch {
  double distance = 0;      ///< the largest distance found (0 when no point converged)
  std::size_t samples = 0;  ///< points of {q = 0} measured
};

/// See the file comment.
SurfaceToPatch measure_surface_to_patch(const PatchEvaluator& patch, const FramedPolynomial& q,
                                        const ParameterRect& piece, double reach, const Budget& budget);

/// max |q(X)|/|∇q(X)| over a side×side grid of the piece: the first-order distance of
/// the patch to {q = 0}, an estimate (not a bound) used only to skip degrees.
double estimate_patch_to_surface(const PatchEvaluator& patch, const FramedPolynomial& q, const ParameterRect& piece,
                                 std::size_t side);

}  // namespace implicitizer::approximation
