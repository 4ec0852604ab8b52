#pragma once
/// \file
/// A Gröbner-basis request as the outside world states it (the contract's
/// `POST /v1/groebner` body, or `implicitizer groebner`'s arguments), its answer,
/// and the one function that computes it, shared by the HTTP handler and the CLI.

#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/groebner/groebner_method.hpp"
#include "implicitizer/groebner/modular_groebner.hpp"
#include "implicitizer/polynomial/monomial_order.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// The fields of a request; the polynomials and names are still text (parsing them
/// needs the ring and the budget, and their errors carry positions).
struct GroebnerRequest {
  std::vector<std::string> polynomials;  ///< generators of the ideal, at least one
  /// The ring's variables, largest first; absent means the identifiers of the
  /// polynomials in order of first appearance.
  std::optional<std::vector<std::string>> variables;
  /// lex, grlex or grevlex (MonomialOrder::from_name); with `weights`, the tie-break
  /// of a weighted order.
  MonomialOrder order = MonomialOrder::grevlex();
  /// Weights of a weighted order (one per variable, in [0, 1024]); absent for a plain order.
  std::optional<std::vector<int>> weights;
  /// Variables to eliminate; absent or empty means no elimination.
  std::optional<std::vector<std::string>> eliminate;
  /// Wall-time limit in seconds; absent or <= 0 means none.
  std::optional<double> timeout_seconds;
  GroebnerMethod method = GroebnerMethod::automatic;
  /// exact (the default) or random_primes: a modular route's answer not proven, only
  /// checked modulo random primes, and labelled `proven: false` (groebner_method.hpp).
  GroebnerProof proof = GroebnerProof::exact;
};

/// What a Gröbner request computed.
struct GroebnerAnswer {
  /// The reduced basis, monic, sorted by increasing leading monomial. With
  /// elimination it is the basis under the block order (eliminated variables first).
  std::vector<Polynomial> basis;
  /// Name of the order `basis` is in (MonomialOrder::name(): `grevlex`,
  /// `weighted(1,2,3;grevlex)`, `block(2:grevlex|lex)`).
  std::string order;
  BuchbergerStats stats;  ///< of the Buchberger run (with `modular`, of one run modulo a prime)
  /// What computed the basis (buchberger or modular) and, with modular, the primes,
  /// the lifting and the proof.
  GroebnerRoute route;
  double elapsed_ms = 0;  ///< wall time of the whole answer, parsing included
  /// With elimination: the reduced basis of the elimination ideal, in the remaining
  /// variables under the requested order. Empty optional without elimination.
  std::optional<std::vector<Polynomial>> elimination_ideal;
};

/// Answers `request` under `budget` (the request's timeout, when present, replaces
/// its deadline and starts now), running Buchberger's algorithm as `variant` says
/// (the command line's --strategy and --criteria). Throws InputError with its field
/// set: `empty_input` ("polynomials", none given), parse and evaluation errors
/// ("polynomials[i]"), `invalid_variables` ("variables"), `invalid_order`
/// ("weights"), `unknown_variable` ("eliminate"); LimitExceeded when the budget runs out.
GroebnerAnswer answer_groebner_request(const GroebnerRequest& request, Budget budget = Budget(),
                                       const BuchbergerVariant& variant = BuchbergerVariant());

}  // namespace implicitizer
