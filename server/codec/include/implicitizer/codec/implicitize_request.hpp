#pragma once
/// \file
/// An implicitization request as the outside world states it (the contract's
/// `POST /v1/implicitize` body, or the command line's flags), and the one function
/// that answers it with the library. The HTTP handler and `implicitizer implicitize`
/// both call answer_implicitize_request(), so they cannot disagree.

#include <optional>
#include <string>
#include <vector>

#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/reproduce.hpp"

namespace implicitizer {

/// The fields of a request, still as text: nothing is parsed or validated here.
struct ImplicitizeRequest {
  std::string x;  ///< expression for x in the parameters
  std::string y;  ///< expression for y
  /// Expression for z; absent for a plane curve (then the answer is f(x, y)).
  std::optional<std::string> z;
  /// Explicit parameter names; absent means "every identifier other than x, y, z".
  std::optional<std::vector<std::string>> parameters;
  /// `auto`, `groebner`, `resultant` or `interpolation`.
  std::string method = "auto";
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
};

/// Answers `request`: parses the method (InputError `unknown_method`, field
/// "method"), then the parametrization (InputError with field "x", "y", "z" or
/// "parameters"), then implicitizes with `params` (strategy, criteria, size limit,
/// cancellation). The request's timeout, when present, replaces the deadline of
/// `params.budget` and starts counting now. Throws what implicitize() throws:
/// NoSingleEquation, LimitExceeded.
ImplicitizeAnswer answer_implicitize_request(const ImplicitizeRequest& request,
                                             BuchbergerParams params = BuchbergerParams());

}  // namespace implicitizer
