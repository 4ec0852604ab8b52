#pragma once
/// \file
/// The parameter domain a patch is drawn over when the request names none, and the
/// charts that prove a rational parametrization bounded on the whole parameter plane.
///
/// The rule (docs/sdf.md, "Patches"). The default domain is the whole parameter
/// plane ℝ^m (m = 2 for surfaces, 1 for curves) when the parametrization is bounded on
/// it, else the unit box [0, 1]^m. Why: a bounded rational parametrization of a closed
/// surface (the stereographic sphere, the rational torus, Steiner's surface) covers
/// the whole surface only on ℝ^m, so any box would cut a hole into it; a polynomial
/// map is never bounded on ℝ^m (a non-constant polynomial grows along some line), and
/// neither is a rational one whose denominator vanishes somewhere, so for those the
/// image of ℝ^m is not a finite object one could draw, and [0, 1]^m is the customary
/// patch of computer-aided design (Bézier and B-spline patches live on it).
///
/// The proof of boundedness. Write ℝ = [−1, 1] ∪ {|s| ≥ 1} and map the second part to
/// [−1, 1] by s = 1/σ (σ = 0 standing for s = ∞). ℝ^m is the union of the 2^m product
/// charts in which each parameter is either s itself or 1/σ, each over [−1, 1]^m, and
/// X is bounded on ℝ^m if bound_patch() proves every chart's rational map bounded on
/// [−1, 1]^m (it does so by proving the chart's common denominator zero-free there,
/// with subdivision; `unbounded_patch` means it could not). The charts are exact:
/// p(1/σ) = σ^−d·p̃(σ) with p̃ the coefficient reversal of p in s (d = deg_s p), so a
/// coordinate n/q becomes σ^(deg q − deg n)·ñ/q̃. For surfaces whose parametrization
/// lives on the projective plane (the stereographic sphere, Steiner's surface) the
/// product chart at (s, t) = (∞, ∞) has a denominator vanishing at σ = τ = 0 (a
/// removable 0/0), so a second covering is tried: [−1, 1]² and the two charts
/// (s, t) = (1/σ, τ/σ), (σ/τ, 1/τ) over [−1, 1]², which cover |s| >= max(1, |t|) and
/// |t| >= max(1, |s|); there p(1/σ, τ/σ) = σ^−d·P(σ, τ) with d the total degree and P
/// the homogenization of p in σ. Either covering proves boundedness (the rational
/// torus needs the first, the sphere and Steiner's surface the second). The union of
/// the chart bounds bounds the closure of X(ℝ^m), which is what a renderer draws.

#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"

namespace implicitizer {

/// The 2^m charts of the parameter space ℝ^m (m = number of parameters): chart k
/// replaces parameter j by 1/(parameter j) when bit j of k is set, the coordinates
/// kept in lowest terms. Chart 0 is the parametrization itself. Exact.
std::vector<Parametrization> parameter_charts(const Parametrization& parametrization, const Budget& budget = Budget());

/// The 3 charts of ℝ² seen in the projective plane: the parametrization itself, and
/// (s, t) = (1/σ, τ/σ) and (σ/τ, 1/τ), each over [−1, 1]² covering |s| >= max(1, |t|)
/// and |t| >= max(1, |s|). Exact. Throws std::invalid_argument unless m = 2.
std::vector<Parametrization> projective_charts(const Parametrization& parametrization, const Budget& budget = Budget());

/// The unit box [0, 1]^m of `parametrization`'s parameters.
ParameterDomain unit_domain(const Parametrization& parametrization);

/// A box containing X(ℝ^m): the union of bound_patch() over the charts on [−1, 1]^m,
/// the product charts or, when one of them fails, the projective ones. Throws
/// InputError `unbounded_patch` (field "domain") when neither system is proven
/// bounded, LimitExceeded from `budget`.
PatchBounds bound_patch_on_plane(const Parametrization& parametrization, const Budget& budget = Budget(),
                                 const PatchBoundsParams& params = PatchBoundsParams());

/// The default domain of a patch and the exact bound of its image.
struct DefaultPatchDomain {
  bool whole_plane = false;  ///< true: ℝ^m (then `domain` is empty); false: the unit box
  ParameterDomain domain;    ///< [0, 1]^m when !whole_plane
  PatchBounds bounds;        ///< a box containing X(domain), or X(ℝ^m) when whole_plane
};

/// The default domain (the file comment's rule) of `parametrization`. Throws
/// LimitExceeded from `budget`, and `unbounded_patch` when even [0, 1]^m is not
/// bounded (a denominator vanishes there).
DefaultPatchDomain default_patch_domain(const Parametrization& parametrization, const Budget& budget = Budget(),
                                        const PatchBoundsParams& params = PatchBoundsParams());

}  // namespace implicitizer
