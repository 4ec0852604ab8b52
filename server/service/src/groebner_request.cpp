#include "implicitizer/service/groebner_request.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <utility>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/groebner/elimination.hpp"
#include "implicitizer/polynomial/expression.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer {
namespace {

std::string element_field(const char* name, std::size_t i) { return std::string(name) + "[" + std::to_string(i) + "]"; }

// An invalid_order names the weights when there are any (their count or range is
// what is wrong), else the order.
const char* order_field(const GroebnerRequest& request) { return request.weights ? "weights" : "order"; }

MonomialOrder order_of(const GroebnerRequest& request) {
  if (!request.weights) return request.order;
  try {
    return MonomialOrder::weighted(*request.weights, request.order);
  } catch (const InputError& e) {
    throw e.in_field("weights");
  }
}

std::vector<std::unique_ptr<Expression>> parse_expressions(const GroebnerRequest& request) {
  std::vector<std::unique_ptr<Expression>> expressions;
  expressions.reserve(request.polynomials.size());
  for (std::size_t i = 0; i < request.polynomials.size(); ++i) {
    try {
      expressions.push_back(parse_expression(request.polynomials[i]));
    } catch (const InputError& e) {
      throw e.in_field(element_field("polynomials", i));
    }
  }
  return expressions;
}

// The generators in the ring of the request's variables (or those of the inputs in
// order of first appearance). When eliminating, that ring only fixes the order of the
// remaining variables: eliminate() builds the block ring and applies `order` to them.
std::vector<Polynomial> evaluate_generators(const GroebnerRequest& request,
                                            const std::vector<std::unique_ptr<Expression>>& expressions,
                                            const MonomialOrder& order, bool eliminating, const Budget& budget) {
  std::vector<std::string> variables = request.variables ? *request.variables : collect_identifiers(expressions);
  budget.check_variables(variables.size(), "the ideal");
  RingPtr ring;
  try {
    ring = Ring::make(std::move(variables), eliminating ? MonomialOrder::grevlex() : order);
  } catch (const InputError& e) {
    throw e.in_field(e.code() == "invalid_order" ? order_field(request) : "variables");
  }
  std::vector<Polynomial> generators;
  generators.reserve(expressions.size());
  for (std::size_t i = 0; i < expressions.size(); ++i) {
    try {
      generators.push_back(evaluate_polynomial(*expressions[i], ring, budget));
    } catch (const InputError& e) {
      throw e.in_field(element_field("polynomials", i));
    }
  }
  return generators;
}

// Every name must be a variable, listed once, and some variable must remain: the
// library's block ring needs a non-empty second block.
void check_eliminated_names(const std::vector<std::string>& names, const Ring& ring) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!ring.index_of(names[i])) {
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
  if (names.size() >= ring.num_variables()) {
    throw InputError("invalid_variables", "eliminating every variable leaves no variable for the ideal")
        .in_field("eliminate");
  }
}

void answer_elimination(const GroebnerRequest& request, const std::vector<Polynomial>& generators,
                        const MonomialOrder& order, const BuchbergerParams& params, GroebnerAnswer& answer) {
  check_eliminated_names(*request.eliminate, *generators.front().ring());
  EliminationResult result;
  try {
    result = eliminate_by_method(generators, *request.eliminate, request.method, params, order, &answer.route,
                                 request.proof);
  } catch (const InputError& e) {
    throw e.field().empty() ? e.in_field(e.code() == "invalid_order" ? order_field(request) : "eliminate") : e;
  }
  answer.basis = std::move(result.groebner.basis);
  answer.stats = result.groebner.stats;
  answer.order = result.block_ring->order().name();
  answer.elimination_ideal = std::move(result.elimination);
}

}  // namespace

GroebnerAnswer answer_groebner_request(const GroebnerRequest& request, Budget budget,
                                       const BuchbergerVariant& variant) {
  const Stopwatch timer;
  if (request.polynomials.empty()) {
    throw InputError("empty_input", "no polynomials given").in_field("polynomials");
  }
  if (request.timeout_seconds) budget.set_timeout(*request.timeout_seconds);
  budget.check_polynomials(request.polynomials.size(), "the ideal");
  const std::vector<std::unique_ptr<Expression>> expressions = parse_expressions(request);
  const MonomialOrder order = order_of(request);
  const bool eliminating = request.eliminate && !request.eliminate->empty();
  const std::vector<Polynomial> generators = evaluate_generators(request, expressions, order, eliminating, budget);

  const BuchbergerParams params{variant, budget};
  GroebnerAnswer answer;
  if (eliminating) {
    answer_elimination(request, generators, order, params, answer);
  } else {
    GroebnerResult result =
        compute_groebner_basis_by_method(generators, request.method, params, &answer.route, request.proof);
    answer.basis = std::move(result.basis);
    answer.stats = result.stats;
    answer.order = order.name();
  }
  answer.elapsed_ms = timer.elapsed_ms();
  return answer;
}

}  // namespace implicitizer
