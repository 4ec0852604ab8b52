#pragma once
/// \file
/// Implicitization: from a parametrization to the implicit equation of its image
/// (Theorems 1.8 and 1.9 of the seed thesis, with the lcm of the denominators).

#include <optional>
#include <string>

#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/groebner/modular_groebner.hpp"
#include "implicitizer/implicitization/interpolation.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/resultant/auxiliary_resultant.hpp"

namespace implicitizer {

/// The ring of implicit equations of surfaces: x, y, z with grevlex (the contract's
/// output order).
RingPtr space_ring();

/// The ring of implicit equations of plane curves: x, y with grevlex.
RingPtr plane_ring();

/// space_ring() for 3 coordinates, plane_ring() for 2.
inline RingPtr implicit_ring(std::size_t coordinates) { return coordinates == 2 ? plane_ring() : space_ring(); }

/// Which route computes the equation.
enum class ImplicitizationMethod {
  automatic,      ///< chosen by measured rules among the others (docs/algorithms.md)
  groebner,       ///< elimination with Buchberger's algorithm
  resultant,      ///< the auxiliary resultant; refused (base_points) when it vanishes
  interpolation,  ///< the kernel of evaluated monomials modulo primes (interpolation.hpp)
};

/// Parses `auto`, `groebner`, `resultant` and `interpolation`; throws InputError
/// (`unknown_method`) otherwise.
ImplicitizationMethod parse_implicitization_method(const std::string& name);

/// Parameters of implicitize().
struct ImplicitizeParams {
  ImplicitizationMethod method = ImplicitizationMethod::automatic;
  /// Time, size, memory, work and cancellation of the whole call: every route and
  /// every head start of `auto` runs under it.
  Budget budget;
  /// The pair selection and criteria of the Gröbner route (over ℚ and modulo primes).
  BuchbergerVariant buchberger;
  /// The Gröbner route computes the elimination modulo primes (eliminate_modular with
  /// F4 modulo each prime, lifting only the elimination ideal) and proves the equation it lifts by exact
  /// substitution and check_implicit_equation's minimality; where that proof fails
  /// (an image that is not a surface, an unlucky check prime) it falls back to
  /// Buchberger over ℚ, which also gives the generators of a non-principal ideal.
  bool modular_groebner = false;
};

/// The implicit equation and how it was found.
struct ImplicitizeResult {
  Polynomial implicit{space_ring()};  ///< primitive, positive leading coefficient, in implicit_ring()
  std::int32_t degree = 0;            ///< total degree of `implicit`
  std::string method;                 ///< the route used ("groebner", "resultant" or "interpolation")
  std::string route;                  ///< with method auto: why that route (empty otherwise)
  bool verified = false;              ///< substitution into `implicit` gave exactly 0
  double elapsed_ms = 0;              ///< wall time of the whole call
  double verify_ms = 0;               ///< of which spent verifying
  BuchbergerStats stats;              ///< of the elimination (Gröbner route)
  /// Of the auxiliary resultant (resultant route; also set when `auto` probed it and
  /// took another route).
  std::optional<AuxiliaryResultantStats> resultant_stats;
  /// Of the interpolation route (method interpolation, or auto's choice of it).
  std::optional<InterpolationStats> interpolation_stats;
  /// Of the modular elimination (the Gröbner route with modular_groebner, or auto's
  /// fallback where interpolation's matrix is too large).
  std::optional<ModularGroebnerStats> modular_stats;
  /// l in Res_aux = c·f^l: the degree of the parametrization as a map onto its
  /// image (resultant route; 0 when unknown).
  std::int32_t map_degree = 0;
  // The scripts that recompute the elimination in Singular and Macaulay2 are not
  // here: they depend on the parametrization alone (reproduce_scripts()), and
  // printing them is output, not elimination (10–30 µs on a small surface,
  // docs/benchmarks.md), so the codec makes them when it writes an answer.
};

/// The implicit equation of the image (a surface f(x, y, z) = 0 for three
/// coordinates, a curve f(x, y) = 0 for two), verified by substitution, by the route of
/// `options.method`:
///   - groebner: the generator of the elimination ideal of I = ⟨q_i·X_i − p_i, 1 − L·w⟩
///     (L the lcm of the denominators; w only when L is not constant);
///   - resultant: the square-free part of the auxiliary resultant (Theorem 1.13),
///     for a surface in two parameters (Dixon or Macaulay) or a plane curve in one
///     (Sylvester); NoSingleEquation with code `base_points` when the auxiliary
///     resultant vanishes identically (Theorem 1.14), InputError
///     `method_not_applicable` for other numbers of parameters;
///   - interpolation: implicitize_by_interpolation() under `options.budget` (any number of parameters, base points or
///   not);
///   - auto: interpolation up to degree 4; else, after short head starts for
///     Buchberger, the resultant (tensor-product patches, triangular ones above
///     degree 9) or interpolation (triangular patches up to degree 9, base points);
///     the modular elimination or Buchberger where those cannot answer (the rule
///     and the measurements behind it are in docs/algorithms.md).
/// Throws NoSingleEquation when the ideal is zero or needs several generators (the
/// image is a curve, a point, or fills space), LimitExceeded when the budget runs out.
/// A failed verification throws std::logic_error: it is a bug, never an answer.
ImplicitizeResult implicitize(const Parametrization& parametrization, const ImplicitizeParams& options = {});

}  // namespace implicitizer
