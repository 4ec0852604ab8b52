#pragma once
/// \file
/// An implicitization request as the outside world states it (the contract's
/// `POST /v1/implicitize` body, or the command line's flags), and the one function
/// that answers it with the library. The HTTP handler and `implicitizer implicitize`
/// both call answer_implicitize_request(), so they cannot disagree.

#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/reproduce.hpp"

namespace implicitizer {

/// The fields of a request; the coordinates are still text (parsing them needs the
/// budget, and their errors carry positions).
struct ImplicitizeRequest {
  std::string x;  ///< expression for x in the parameters
  std::string y;  ///< expression for y
  /// Expression for z; absent for a plane curve (then the answer is f(x, y)).
  std::optional<std::string> z;
  /// Explicit parameter names; absent means "every identifier other than x, y, z".
  std::optional<std::vector<std::string>> parameters;
  ImplicitizationMethod method = ImplicitizationMethod::automatic;
  /// The Gröbner route modulo primes (ImplicitizeParams::modular_groebner).
  bool modular = false;
  /// Wall-time limit in seconds; absent or <= 0 means none (the caller may impose its own).
  std::optional<double> timeout_seconds;
};

/// What the contract returns for a request: the library's result, and the scripts
/// that reproduce it in Singular and Macaulay2 (the answer's "reproduce").
struct ImplicitizeAnswer {
  ImplicitizeResult result;
  ReproduceScripts reproduce;
  /// How cos/sin/tan/cosh/sinh/tanh in the input were made rational; empty for a
  /// rational input (then the two fields below are empty too).
  std::vector<ParameterSubstitution> substitutions;
  /// The rational parametrization that was implicitized: its parameters and the
  /// coordinates x, y[, z] printed in them.
  std::vector<std::string> rational_parameters;
  std::vector<std::string> rational_coordinates;
};

/// Answers `request` under `budget` (the request's timeout, when present, replaces
/// its deadline and starts counting now, so that parsing counts too), running
/// Buchberger's algorithm as `variant` says (the command line's --strategy and
/// --criteria). Throws InputError with field "x", "y", "z" or "parameters" for the
/// parametrization, and what implicitize() throws: NoSingleEquation, LimitExceeded.
ImplicitizeAnswer answer_implicitize_request(const ImplicitizeRequest& request, Budget budget = Budget(),
                                             const BuchbergerVariant& variant = BuchbergerVariant());

}  // namespace implicitizer
