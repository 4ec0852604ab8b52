#include "implicitizer/groebner/groebner_method.hpp"

#include <utility>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/try_within.hpp"

namespace implicitizer {
namespace {

// The modular route `auto` hands over to after Buchberger's head start: F4, faster
// than Buchberger modulo p on every ideal measured past the head start
// (docs/algorithms.md, "F4 modulo primes").
constexpr GroebnerMethod kAutoModularRoute = GroebnerMethod::f4;

// Runs `buchberger(params)` over ℚ or `modular(modular_params, stats)` modulo primes
// as `method` says; `auto` gives Buchberger its head start first.
template <class Buchberger, class Modular>
auto compute_by_method(GroebnerMethod method, const BuchbergerParams& params, GroebnerRoute* route, GroebnerProof proof,
                       Buchberger buchberger, Modular modular) {
  GroebnerRoute answered;
  const auto by_modular = [&](GroebnerMethod modular_route) {
    ModularGroebnerParams modular_params;
    modular_params.buchberger = params;
    modular_params.algorithm =
        modular_route == GroebnerMethod::f4 ? ModularAlgorithm::f4 : ModularAlgorithm::buchberger;
    if (proof == GroebnerProof::random_primes) {
      modular_params.prove = false;
      modular_params.random_checks = kUnprovenRandomChecks;
    }
    ModularGroebnerStats stats;
    auto result = modular(modular_params, stats);
    answered = {modular_route, stats};
    return result;
  };
  const auto finish = [&](auto result) {
    if (route != nullptr) *route = std::move(answered);
    return result;
  };
  if (method == GroebnerMethod::modular || method == GroebnerMethod::f4) return finish(by_modular(method));
  if (method == GroebnerMethod::automatic) {
    // The caller's own limits (its deadline, memory, cancellation, the term limit)
    // stop everything; only the head start's work allowance hands over.
    auto quick =
        try_within(params.budget, buchberger_work_of_milliseconds(kBuchbergerHeadStartMs), [&](const Budget& trial) {
          BuchbergerParams limited = params;
          limited.budget = trial;
          return buchberger(limited);
        });
    if (quick) return finish(std::move(*quick));
    return finish(by_modular(kAutoModularRoute));
  }
  return finish(buchberger(params));
}

}  // namespace

GroebnerMethod parse_groebner_method(const std::string& name) {
  for (GroebnerMethod m :
       {GroebnerMethod::automatic, GroebnerMethod::buchberger, GroebnerMethod::modular, GroebnerMethod::f4}) {
    if (name == to_string(m)) return m;
  }
  throw InputError("unknown_method", "unknown method '" + name + "' (expected auto, buchberger, modular or f4)")
      .in_field("method");
}

const char* to_string(GroebnerMethod method) {
  switch (method) {
    case GroebnerMethod::automatic:
      return "auto";
    case GroebnerMethod::buchberger:
      return "buchberger";
    case GroebnerMethod::modular:
      return "modular";
    case GroebnerMethod::f4:
      return "f4";
  }
  return "auto";
}

GroebnerProof parse_groebner_proof(const std::string& name) {
  for (GroebnerProof p : {GroebnerProof::exact, GroebnerProof::random_primes}) {
    if (name == to_string(p)) return p;
  }
  throw InputError("unknown_proof", "unknown proof '" + name + "' (expected exact or random_primes)").in_field("proof");
}

const char* to_string(GroebnerProof proof) { return proof == GroebnerProof::random_primes ? "random_primes" : "exact"; }

GroebnerResult compute_groebner_basis_by_method(std::span<const Polynomial> generators, GroebnerMethod method,
                                                const BuchbergerParams& params, GroebnerRoute* route,
                                                GroebnerProof proof) {
  return compute_by_method(
      method, params, route, proof, [&](const BuchbergerParams& p) { return compute_groebner_basis(generators, p); },
      [&](const ModularGroebnerParams& p, ModularGroebnerStats& stats) {
        return compute_groebner_basis_modular(generators, p, &stats);
      });
}

EliminationResult eliminate_by_method(std::span<const Polynomial> generators, std::span<const std::string> names,
                                      GroebnerMethod method, const BuchbergerParams& params,
                                      const MonomialOrder& remaining_order, GroebnerRoute* route, GroebnerProof proof) {
  return compute_by_method(
      method, params, route, proof,
      [&](const BuchbergerParams& p) { return eliminate(generators, names, p, remaining_order); },
      [&](const ModularGroebnerParams& p, ModularGroebnerStats& stats) {
        return eliminate_modular(generators, names, p, remaining_order, &stats);
      });
}

}  // namespace implicitizer
