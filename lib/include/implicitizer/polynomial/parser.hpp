#pragma once
/// \file
/// From text to polynomials and rational functions: parse_expression() then an
/// evaluator. Errors carry the position of the node that caused them.

#include <functional>
#include <string_view>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/expression.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/polynomial/rational_function.hpp"

namespace implicitizer {

/// Evaluates `e` in `ring`. Division is only by non-zero constants. Throws
/// InputError: `unknown_variable` (an identifier that is not a ring variable),
/// `non_constant_denominator`, `division_by_zero`, `function_not_allowed` (a call such
/// as cos(x): only parametrizations take functions); LimitExceeded from `budget`.
Polynomial evaluate_polynomial(const Expression& e, const RingPtr& ring, const Budget& budget = Budget());

/// The value of a call node (`cos(u)`) as a rational function in the evaluator's ring;
/// it throws InputError when the call has none.
using CallEvaluator = std::function<RationalFunction(const Expression& call)>;

/// Evaluates `e` as a quotient of polynomials in `ring`. Throws InputError
/// `unknown_variable` or `division_by_zero` (a denominator that is the zero
/// polynomial, at the position of its `/`); a call node goes to `calls`, and without
/// it throws `function_not_allowed`.
RationalFunction evaluate_rational_function(const Expression& e, const RingPtr& ring, const Budget& budget = Budget(),
                                            const CallEvaluator& calls = CallEvaluator());

/// parse_expression then evaluate_polynomial.
Polynomial parse_polynomial(std::string_view text, const RingPtr& ring, const Budget& budget = Budget(),
                            const ParseParams& limits = {});

}  // namespace implicitizer
