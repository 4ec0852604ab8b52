#include "implicitizer/service/resultant_request.hpp"

#include <memory>
#include <utility>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/polynomial/expression.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "implicitizer/resultant/subresultant.hpp"

namespace implicitizer {
namespace {

std::string polynomial_field(std::size_t i) { return "polynomials[" + std::to_string(i) + "]"; }

}  // namespace

ResultantAnswer answer_resultant_request(const ResultantRequest& request, Budget budget) {
  const Stopwatch timer;
  if (request.polynomials.size() != 2) {
    throw InputError("wrong_number_of_polynomials", "a resultant needs exactly two polynomials, F and G (got " +
                                                        std::to_string(request.polynomials.size()) + ")")
        .in_field("polynomials");
  }
  if (request.timeout_seconds) budget.set_timeout(*request.timeout_seconds);

  std::vector<std::unique_ptr<Expression>> expressions;
  for (std::size_t i = 0; i < request.polynomials.size(); ++i) {
    try {
      expressions.push_back(parse_expression(request.polynomials[i]));
    } catch (const InputError& e) {
      throw e.in_field(polynomial_field(i));
    }
  }
  if (!is_identifier(request.variable)) {
    throw InputError("invalid_variables", "'" + request.variable + "' is not a variable name").in_field("variable");
  }
  // Every identifier is a variable of the ring, so the variable must be one of them:
  // a name that occurs nowhere is most likely a typo (`--var s` for t).
  std::vector<std::string> identifiers = collect_identifiers(expressions);
  budget.check_variables(identifiers.size(), "the resultant request");
  const RingPtr ring = Ring::make(std::move(identifiers));
  const auto var = ring->index_of(request.variable);
  if (!var) {
    throw InputError("unknown_variable", "'" + request.variable + "' occurs in neither polynomial")
        .in_field("variable");
  }

  std::vector<Polynomial> fg;
  for (std::size_t i = 0; i < expressions.size(); ++i) {
    try {
      fg.push_back(evaluate_polynomial(*expressions[i], ring, budget));
    } catch (const InputError& e) {
      throw e.in_field(polynomial_field(i));
    }
  }

  ResultantAnswer answer{resultant(fg[0], fg[1], *var, budget), {}, -1, "subresultant", 0};
  for (const std::string& name : ring->variables()) {
    if (name != request.variable) answer.variables.push_back(name);
  }
  answer.degree = answer.resultant.total_degree();
  answer.elapsed_ms = timer.elapsed_ms();
  return answer;
}

}  // namespace implicitizer
