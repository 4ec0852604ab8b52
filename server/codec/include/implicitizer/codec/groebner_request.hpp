#pragma once
/// \file
/// A Gröbner-basis request as the outside world states it (the contract's
/// `POST /v1/groebner` body, or `implicitizer groebner`'s arguments), its answer,
/// and the one function that computes it, shared by the HTTP handler and the CLI.

#include <optional>
#include <string>
#include <vector>

#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/groebner/modular_groebner.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// The fields of a request, still as text.
struct GroebnerRequest {
  std::vector<std::string> polynomials;  ///< generators of the ideal, at least one
  /// The ring's variables, largest first; absent means the identifiers of the
  /// polynomials in order of first appearance.
  std::optional<std::vector<std::string>> variables;
  /// `lex`, `grlex` or `grevlex`; with `weights`, the tie-break of a weighted order.
  std::string order = "grevlex";
  /// Weights of a weighted order (one per variable, in [0, 1024]); absent for a plain order.
  std::optional<std::vector<int>> weights;
  /// Variables to eliminate; absent or empty means no elimination.
  std::optional<std::vector<std::string>> eliminate;
  /// Wall-time limit in seconds; absent or <= 0 means none.
  std::optional<double> timeout_seconds;
  /// `auto` (Buchberger over ℚ first, the proven modular computation if it has not
  /// finished within kBuchbergerHeadStartMs of work), `buchberger` or `modular`.
  std::string method = "auto";
};

/// How long `auto` lets Buchberger's algorithm over ℚ run before it switches to the
/// modular computation, in milliseconds of Buchberger's work
/// (buchberger_work_of_milliseconds: the same allowance on every run, loaded or not;
/// docs/algorithms.md has the measurements behind it).
inline constexpr double kBuchbergerHeadStartMs = 100;

/// What a Gröbner request computed.
struct GroebnerAnswer {
  /// The reduced basis, monic, sorted by increasing leading monomial. With
  /// elimination it is the basis under the block order (eliminated variables first).
  std::vector<Polynomial> basis;
  /// Name of the order `basis` is in (MonomialOrder::name(): `grevlex`,
  /// `weighted(1,2,3;grevlex)`, `block(2:grevlex|lex)`).
  std::string order;
  BuchbergerStats stats;  ///< of the Buchberger run (with `modular`, of one run modulo a prime)
  /// `buchberger` or `modular`: what computed the basis.
  std::string method;
  /// With `modular`: the primes, the lifting and the proof.
  std::optional<ModularGroebnerStats> modular;
  double elapsed_ms = 0;  ///< wall time of the whole answer, parsing included
  /// With elimination: the reduced basis of the elimination ideal, in the remaining
  /// variables under the requested order. Empty optional without elimination.
  std::optional<std::vector<Polynomial>> elimination_ideal;
};

/// Answers `request` with `params` (strategy, criteria, size limit, cancellation;
/// the request's timeout, when present, replaces the deadline and starts now).
/// Throws InputError with its field set: `empty_input` ("polynomials", none given),
/// parse and evaluation errors ("polynomials[i]"), `invalid_variables` ("variables"),
/// `unknown_order` / `invalid_order` ("order" / "weights"), `unknown_variable`
/// ("eliminate"), `unknown_method` ("method"); LimitExceeded when the budget runs out.
GroebnerAnswer answer_groebner_request(const GroebnerRequest& request, BuchbergerParams params = BuchbergerParams());

}  // namespace implicitizer
