#pragma once
/// \file
/// Approximate implicitization of a parametric patch within a stated tolerance
/// (docs/sdf.md, "Approximate implicitization"): instead of the exact implicit equation
/// (degree up to 18 for a bicubic patch), low-degree algebraic surfaces q_k = 0, one
/// per piece S_k of a subdivision of the parameter domain D, each close to X(S_k) in
/// both directions. The scene joins the pieces by min (scene/polynomial_leaf.hpp).
///
/// Method: Dokken's approximate implicitization (Dokken 2001; Barrowclough and Dokken
/// 2012). For a piece S and a degree m, the columns of the matrix D are the Bernstein
/// coefficients over S of φ_j(X(s, t)), φ_j a basis of trivariate polynomials of degree
/// m in the piece's frame coordinates; the right singular vector b of D's smallest
/// singular value σ gives q = Σ b_j φ_j with max_S |q(X)| <= σ (Bernstein coefficients
/// bound the values; ||D b|| = σ for ||b|| = 1). The SVD is Eigen's.

#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "implicitizer/approximation/trim_polytope.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// How an error bound was established.
enum class BoundMethod {
  certified,  ///< proven in exact rational (or outward-rounded interval) arithmetic
  measured,   ///< the largest error seen on a stated sample
};

/// "certified" or "measured" (the API's spelling).
std::string to_string(BoundMethod method);

struct ApproximationPiece;

/// What approximate_patch() may spend.
struct ApproximationParams {
  /// EPS: both one-sided distances must stay within EPS · (the diagonal of the patch's
  /// exact box, bound_patch() of D). 0 < EPS <= 0.5.
  double tolerance = 1e-3;
  int max_degree = 6;           ///< algebraic degrees 1 … max_degree are tried per piece
  std::size_t max_pieces = 64;  ///< subdivision of D stops here (tolerance_not_met beyond)
  /// Asked before each sub-domain is tried, with the pieces accepted so far (in domain
  /// order) and the number of sub-domains still to do (each will give at least one
  /// piece); false stops the approximation with ApproximationStopped. The scene stops
  /// it once the pieces cannot end up cheaper than the exact equation. Empty: never.
  std::function<bool(const std::vector<ApproximationPiece>& accepted, std::size_t pending)> keep_going;
};

/// One piece: the surface q = 0 standing for X(S).
struct ApproximationPiece {
  ParameterDomain domain;  ///< S, a sub-box of D
  PatchBounds box;         ///< exact box of X(S) (bound_patch)
  Polynomial equation;     ///< q in x, y, z (a ring of three variables), exact rational coefficients
  int degree = 0;          ///< total degree of q
  /// Every point of X(S) is within this distance (absolute units) of {q = 0}.
  double patch_to_surface = 0;
  BoundMethod patch_to_surface_method = BoundMethod::certified;
  /// Every point of {q = 0} the trimming keeps (in `polytope` ∩ `box` when there is a
  /// polytope; else within 0.1·h of X(S), h the largest half side of `box`, what a box
  /// cover keeps) is within this distance of X(D') (D' = D widened by a quarter of its
  /// sides, so that the edge's continuation counts as it does for the exact equation),
  /// measured on the sample of lib/src/approximation/surface_distance.hpp.
  double surface_to_patch = 0;
  BoundMethod surface_to_patch_method = BoundMethod::measured;
  std::size_t surface_to_patch_samples = 0;  ///< points of {q = 0} the measurement used
  /// The polytope q = 0 is trimmed to (with `box`), when its zeros there met the
  /// tolerance; none: the piece is trimmed to a box cover of X(S) (scene/patch_cover.hpp).
  std::optional<TrimPolytope> polytope;
};

/// The result: pieces and the bounds relative to the patch box's diagonal.
struct PatchApproximation {
  std::vector<ApproximationPiece> pieces;
  double diagonal = 0;                                           ///< of the exact box of X(D)
  double tolerance = 0;                                          ///< EPS asked
  double patch_to_surface = 0;                                   ///< max over pieces / diagonal
  BoundMethod patch_to_surface_method = BoundMethod::certified;  ///< measured if any piece's is
  double surface_to_patch = 0;                                   ///< max over pieces / diagonal
  BoundMethod surface_to_patch_method = BoundMethod::measured;
  std::size_t surface_to_patch_samples = 0;  ///< sum over pieces
  int max_degree = 0;                        ///< largest piece degree
};

/// Approximates the patch X(`domain`) (a surface: three coordinates, two parameters;
/// a bounded domain) within params.tolerance. Tries, per piece, degrees 1, 2, … and
/// keeps the first whose bounds meet the tolerance; when none does, splits the piece
/// (longest parameter side) and recurses. Cheapest: fewest coefficients in total.
/// Throws InputError `invalid_tolerance` (field "tolerance") for EPS <= 0, > 0.5 or
/// non-finite; ToleranceNotMet when max_pieces or max_degree cannot reach it;
/// ApproximationStopped when params.keep_going says so;
/// LimitExceeded from `budget` (checked in every phase).
PatchApproximation approximate_patch(const Parametrization& parametrization, const ParameterDomain& domain,
                                     const ApproximationParams& params, const Budget& budget = Budget());

/// ApproximationParams::keep_going said stop.
class ApproximationStopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The tolerance could not be met: `best` is the smallest two-sided bound reached
/// (relative to the diagonal). Maps to the stable code `tolerance_not_met`.
class ToleranceNotMet : public std::runtime_error {
 public:
  ToleranceNotMet(const std::string& message, double best) : std::runtime_error(message), best_(best) {}
  /// The best bound reached, relative to the patch box's diagonal.
  double best() const { return best_; }

 private:
  double best_;
};

}  // namespace implicitizer
