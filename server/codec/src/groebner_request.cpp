#include "implicitizer/codec/groebner_request.hpp"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/try_within.hpp"
#include "implicitizer/groebner/elimination.hpp"
#include "implicitizer/polynomial/expression.hpp"
#include "implicitizer/polynomial/monomial_order.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer {
namespace {

std::string element_field(const char* name, std::size_t i) { return std::string(name) + "[" + std::to_string(i) + "]"; }

MonomialOrder order_of(const GroebnerRequest& request) {
  MonomialOrder order;
  try {
    order = MonomialOrder::from_name(request.order);
  } catch (const InputError& e) {
    throw e.in_field("order");
  }
  if (!request.weights) return order;
  try {
    return MonomialOrder::weighted(*request.weights, order);
  } catch (const InputError& e) {
    throw e.in_field("weights");
  }
}

// The variables named by the request, or those of the inputs in order of first
// appearance (one identifier list per expression, merged without repeats).
std::vector<std::string> variables_of(const GroebnerRequest& request,
                                      const std::vector<std::unique_ptr<Expression>>& expressions) {
  if (request.variables) return *request.variables;
  return collect_identifiers(expressions);
}

enum class GroebnerMethod { automatic, buchberger, modular };

GroebnerMethod method_of(const GroebnerRequest& request) {
  if (request.method == "auto") return GroebnerMethod::automatic;
  if (request.method == "buchberger") return GroebnerMethod::buchberger;
  if (request.method == "modular") return GroebnerMethod::modular;
  throw InputError("unknown_method", "unknown method '" + request.method + "' (expected auto, buchberger or modular)")
      .in_field("method");
}

// What computes a basis: `buchberger(params)` over ℚ, `modular(modular_params,
// stats)` modulo primes; `auto` gives Buchberger a head start.
template <class Buchberger, class Modular>
auto compute_with(GroebnerMethod method, const BuchbergerParams& params, GroebnerAnswer& answer, Buchberger buchberger,
                  Modular modular) {
  const auto by_modular = [&] {
    ModularGroebnerParams modular_params;
    modular_params.buchberger = params;
    ModularGroebnerStats stats;
    auto result = modular(modular_params, stats);
    answer.method = "modular";
    answer.modular = stats;
    return result;
  };
  if (method == GroebnerMethod::modular) return by_modular();
  if (method == GroebnerMethod::automatic) {
    // The caller's own limits (its deadline, memory, cancellation, the term limit)
    // stop everything; only the head start's work allowance hands over.
    auto quick =
        try_within(params.budget, buchberger_work_of_milliseconds(kBuchbergerHeadStartMs), [&](const Budget& trial) {
          BuchbergerParams limited = params;
          limited.budget = trial;
          return buchberger(limited);
        });
    if (quick) {
      answer.method = "buchberger";
      return std::move(*quick);
    }
    return by_modular();
  }
  answer.method = "buchberger";
  return buchberger(params);
}

}  // namespace

GroebnerAnswer answer_groebner_request(const GroebnerRequest& request, BuchbergerParams params) {
  const auto start = std::chrono::steady_clock::now();
  if (request.polynomials.empty()) {
    throw InputError("empty_input", "no polynomials given").in_field("polynomials");
  }
  if (request.timeout_seconds) params.budget.set_timeout(*request.timeout_seconds);
  params.budget.check_polynomials(request.polynomials.size(), "the ideal");

  std::vector<std::unique_ptr<Expression>> expressions;
  expressions.reserve(request.polynomials.size());
  for (std::size_t i = 0; i < request.polynomials.size(); ++i) {
    try {
      expressions.push_back(parse_expression(request.polynomials[i]));
    } catch (const InputError& e) {
      throw e.in_field(element_field("polynomials", i));
    }
  }
  const MonomialOrder order = order_of(request);
  const GroebnerMethod method = method_of(request);
  const bool eliminating = request.eliminate && !request.eliminate->empty();

  // When eliminating, the generators' ring only fixes the order of the remaining
  // variables; eliminate() builds the block ring itself and applies `order` to them.
  std::vector<std::string> variables = variables_of(request, expressions);
  params.budget.check_variables(variables.size(), "the ideal");
  RingPtr ring;
  try {
    ring = Ring::make(std::move(variables), eliminating ? MonomialOrder::grevlex() : order);
  } catch (const InputError& e) {
    throw e.in_field(e.code() == "invalid_order" ? (request.weights ? "weights" : "order") : "variables");
  }

  std::vector<Polynomial> generators;
  generators.reserve(expressions.size());
  for (std::size_t i = 0; i < expressions.size(); ++i) {
    try {
      generators.push_back(evaluate_polynomial(*expressions[i], ring, params.budget));
    } catch (const InputError& e) {
      throw e.in_field(element_field("polynomials", i));
    }
  }

  GroebnerAnswer answer;
  if (eliminating) {
    // Every name must be a variable, listed once, and some variable must remain:
    // the library's block ring needs a non-empty second block.
    const std::vector<std::string>& names = *request.eliminate;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (!ring->index_of(names[i])) {
        throw InputError("unknown_variable", "cannot eliminate '" + names[i] + "': it is not a variable of the ring")
            .in_field(element_field("eliminate", i));
      }
      for (std::size_t j = 0; j < i; ++j) {
        if (names[j] == names[i]) {
          throw InputError("invalid_variables", "'" + names[i] + "' is listed twice")
              .in_field(element_field("eliminate", i));
        }
      }
    }
    if (names.size() >= ring->num_variables()) {
      throw InputError("invalid_variables", "eliminating every variable leaves no variable for the ideal")
          .in_field("eliminate");
    }
    EliminationResult result;
    try {
      result = compute_with(
          method, params, answer,
          [&](const BuchbergerParams& p) { return eliminate(generators, *request.eliminate, p, order); },
          [&](const ModularGroebnerParams& p, ModularGroebnerStats& stats) {
            return eliminate_modular(generators, *request.eliminate, p, order, &stats);
          });
    } catch (const InputError& e) {
      throw e.field().empty()
          ? e.in_field(e.code() == "invalid_order" ? (request.weights ? "weights" : "order") : "eliminate")
          : e;
    }
    answer.basis = std::move(result.groebner.basis);
    answer.stats = result.groebner.stats;
    answer.order = result.block_ring->order().name();
    answer.elimination_ideal = std::move(result.elimination);
  } else {
    GroebnerResult result = compute_with(
        method, params, answer, [&](const BuchbergerParams& p) { return compute_groebner_basis(generators, p); },
        [&](const ModularGroebnerParams& p, ModularGroebnerStats& stats) {
          return compute_groebner_basis_modular(generators, p, &stats);
        });
    answer.basis = std::move(result.basis);
    answer.stats = result.stats;
    answer.order = order.name();
  }
  answer.elapsed_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return answer;
}

}  // namespace implicitizer
