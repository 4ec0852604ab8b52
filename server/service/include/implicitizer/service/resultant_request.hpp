#pragma once
/// \file
/// A resultant request as the outside world states it (the contract's
/// `POST /v1/resultant` body, or `implicitizer resultant`'s arguments), its answer,
/// and the one function that computes it, shared by the HTTP handler and the CLI.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// The fields of a request; the polynomials are still text (parsing them needs the
/// budget, and their errors carry positions).
struct ResultantRequest {
  std::vector<std::string> polynomials;  ///< F and G: exactly two
  std::string variable;                  ///< the variable to eliminate
  /// Wall-time limit in seconds; absent or <= 0 means none.
  std::optional<double> timeout_seconds;
};

/// What a resultant request computed.
struct ResultantAnswer {
  /// Res_v(F, G), exact (rational coefficients allowed), in the ring of every
  /// identifier of F and G in order of first appearance, under grevlex; it does not
  /// involve v.
  Polynomial resultant;
  /// The identifiers of F and G in order of first appearance, without v: the
  /// variables the resultant is a polynomial in (it is printed in grevlex on them).
  std::vector<std::string> variables;
  std::int32_t degree = -1;             ///< total degree of `resultant` (-1 when it is 0)
  std::string method = "subresultant";  ///< the algorithm (subresultant.hpp)
  double elapsed_ms = 0;                ///< wall time of the whole answer, parsing included
};

/// Answers `request` under `budget` (the request's timeout, when present, replaces
/// its deadline and starts now). Throws InputError with its field set:
/// `wrong_number_of_polynomials` ("polynomials": not exactly two), parse and
/// evaluation errors ("polynomials[i]"; a non-constant denominator is
/// `non_constant_denominator`), `invalid_variables` ("variable": not an identifier),
/// `unknown_variable` ("variable": it occurs in neither polynomial); LimitExceeded
/// when the budget runs out.
ResultantAnswer answer_resultant_request(const ResultantRequest& request, Budget budget = Budget());

}  // namespace implicitizer
