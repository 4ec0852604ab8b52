#pragma once
/// \file
/// Implicitization: from a parametrization to the implicit equation of its image
/// (Theorems 1.8 and 1.9 of the seed thesis, with the lcm of the denominators).

#include <string>

#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/implicitization/parametrization.hpp"

namespace implicitizer {

/// The ring of implicit equations: x, y, z with grevlex (the contract's output order).
RingPtr space_ring();

/// Which route computes the equation.
enum class ImplicitizationMethod {
  automatic,  ///< the route that is right and fastest for the input (today: groebner)
  groebner,   ///< elimination with Buchberger's algorithm
};

/// Parses `auto` and `groebner`; throws InputError (`unknown_method`) otherwise,
/// naming the methods of later releases (`resultant`, `interpolation`) as not yet built.
ImplicitizationMethod parse_implicitization_method(const std::string& name);

/// Options of implicitize().
struct ImplicitizeOptions {
  ImplicitizationMethod method = ImplicitizationMethod::automatic;
  BuchbergerParams groebner;  ///< includes the budget
};

/// The implicit equation and how it was found.
struct ImplicitizeResult {
  Polynomial implicit{space_ring()};  ///< primitive, positive leading coefficient, ring x,y,z grevlex
  std::int32_t degree = 0;         ///< total degree of `implicit`
  std::string method;              ///< the route used ("groebner")
  bool verified = false;           ///< substitution into `implicit` gave exactly 0
  double elapsed_ms = 0;           ///< wall time of the whole call
  double verify_ms = 0;            ///< of which spent verifying
  BuchbergerStats stats;           ///< of the elimination
  std::string singular_script;     ///< recomputes the elimination in Singular
  std::string macaulay2_script;    ///< recomputes the elimination in Macaulay2
};

/// The generator of the elimination ideal of I = ⟨q_i·X_i − p_i, 1 − L·w⟩ (L the lcm
/// of the denominators; w only when L is not constant), verified by substitution.
/// Throws NoSingleEquation when the ideal is zero or needs several generators (the
/// image is a curve, a point, or fills space), LimitExceeded when the budget runs out.
/// A failed verification throws std::logic_error: it is a bug, never an answer.
ImplicitizeResult implicitize(const Parametrization& parametrization, const ImplicitizeOptions& options = {});

}  // namespace implicitizer
