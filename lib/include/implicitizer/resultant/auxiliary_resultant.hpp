#pragma once
/// \file
/// The auxiliary resultant Res_aux(x, y, z) of a rational surface x = ξ/ω, y = η/ω,
/// z = ζ/ω in two parameters (Section 1.7.2 of the first seed thesis, after Chionh
/// and Goldman): the resultant of ξ − xω, η − yω, ζ − zω. When it is not identically
/// zero it is c·f^l with f the implicit equation and l the degree of the map
/// (Theorem 1.12); it is identically zero exactly when the parametrization has base
/// points (Theorem 1.14).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/modular/pencil_determinant.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// The largest matrix a formulation may build (rows): Macaulay's for total degree 11
/// (528 rows would be degree 11) is the last below it. Beyond it the matrices take
/// seconds to probe and hundreds of MB to hold, and Buchberger is the route.
inline constexpr std::size_t kMaxResultantMatrixSize = 500;

/// Which matrix formulation computed the resultant.
enum class AuxiliaryFormulation {
  dixon,     ///< tensor product, bidegree (m, n): Dixon's 2mn × 2mn matrix, degree bound 2mn
  macaulay,  ///< total degree n on P²: Macaulay's quotient det M / det E, degree bound n²
  sylvester, ///< a plane curve of degree n on P¹: Sylvester's 2n × 2n matrix, degree bound n
};

/// "dixon", "macaulay" or "sylvester".
const char* to_string(AuxiliaryFormulation formulation);

/// Options of auxiliary_resultant().
struct AuxiliaryResultantParams {
  Budget budget;         ///< time, size, cancellation
  unsigned threads = 0;  ///< threads for independent primes (0: every core)
  /// Macaulay's quotient stops when this many further primes change nothing
  /// (PencilDeterminantParams::stable_primes); callers that find the answer
  /// wrong by verification retry with more.
  std::size_t stable_primes = 1;
};

/// What auxiliary_resultant() did.
struct AuxiliaryResultantStats {
  AuxiliaryFormulation formulation = AuxiliaryFormulation::dixon;  ///< the formulation used
  std::int32_t bidegree_s = 0;        ///< m: degree in the first parameter
  std::int32_t bidegree_t = 0;        ///< n: degree in the second parameter
  std::int32_t total_degree = 0;      ///< total degree of the parametrization
  std::size_t matrix_size = 0;        ///< rows of the matrix
  std::size_t extraneous_size = 0;    ///< rows of Macaulay's extraneous minor (0 for Dixon)
  std::int32_t degree_bound = 0;      ///< the proven bound on deg Res_aux
  bool dixon_vanishes = false;        ///< Dixon's determinant is identically zero: base points on P¹×P¹
  bool macaulay_vanishes = false;     ///< Macaulay's quotient is identically zero: base points on P²
  /// A formulation was skipped because its matrix would exceed kMaxResultantMatrixSize
  /// rows (its vanishing flag is then false: it was not probed).
  bool matrix_too_large = false;
  PencilDeterminantStats determinant; ///< primes, evaluations
  double construction_ms = 0;         ///< building the matrix and probing
  double determinant_ms = 0;          ///< evaluation, interpolation, Chinese remaindering
};

/// The resultant and how it was found.
struct AuxiliaryResultant {
  Polynomial resultant;          ///< Res_aux in the space ring; zero when there are base points
  AuxiliaryResultantStats stats;
};

/// The formulation auxiliary_resultant() computes, chosen by the probes, with its
/// matrix: lets a caller weigh the route (predicted_operations) before paying for it.
struct AuxiliaryResultantPlan {
  /// The formulation to compute; none when every one vanishes identically.
  std::optional<AuxiliaryFormulation> formulation;
  MatrixPencil matrix{0, 3};          ///< its matrix
  std::vector<std::size_t> minor;     ///< Macaulay's extraneous minor (empty for Dixon)
  std::int32_t degree_bound = 0;      ///< the proven bound on deg Res_aux
  AuxiliaryResultantStats stats;      ///< degrees, probe flags, sizes, construction_ms
  /// Operations modulo a prime the determinant will take: lattice points × the
  /// elimination cost of the matrix and the minor × the primes expected (from the
  /// proven bound for Dixon, two for Macaulay). About 2 ns each on this machine.
  double predicted_operations() const;
};

/// Builds both formulations for `wxyz` (as auxiliary_resultant() does), probes them
/// and keeps the one to compute.
AuxiliaryResultantPlan plan_auxiliary_resultant(const std::array<Polynomial, 4>& wxyz,
                                                const AuxiliaryResultantParams& options = {});

/// Computes the determinant `plan` chose, in `space`; zero when it chose none.
AuxiliaryResultant compute_auxiliary_resultant(const AuxiliaryResultantPlan& plan, const RingPtr& space,
                                               const AuxiliaryResultantParams& options = {});

/// Computes Res_aux for `wxyz` = (ω, ξ, η, ζ), polynomials in a ring of exactly two
/// parameters (s, t) with rational coefficients, in the ring `space` (x, y, z).
///
/// Both formulations are probed at random points modulo a prime (cheap: one
/// determinant each), and the one that is not identically zero with the smaller
/// degree bound is computed. Base points depend on the compactification: x = st,
/// y = s, z = t has two on P² (r = 0, st = 0) and none on P¹×P¹, so Dixon's
/// determinant gives its equation x − yz while Macaulay's quotient vanishes. The bidegree-(m, n) Dixon determinant is computed with
/// enough primes for its proven coefficient bound, so it is exact by construction;
/// Macaulay's quotient, which has no cheap coefficient bound, stops when
/// `stable_primes` more primes change nothing, and the caller's exact verification
/// catches the rest.
/// When both vanish (base points, or an image that is not a surface) the result
/// is zero. Throws LimitExceeded from the budget.
AuxiliaryResultant auxiliary_resultant(const std::array<Polynomial, 4>& wxyz, const RingPtr& space,
                                       const AuxiliaryResultantParams& options = {});

}  // namespace implicitizer
