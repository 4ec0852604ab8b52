#pragma once
/// \file
/// Multivariate division by an ordered list (Cox–Little–O'Shea, Thm 2.3.3) and the
/// normal form. This is the readable reference used by the public API and tests;
/// the Buchberger driver has its own fraction-free reducer for speed.

#include <span>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// f = Σ quotients[i]·divisors[i] + remainder.
struct DivisionResult {
  std::vector<Polynomial> quotients;  ///< one per divisor
  Polynomial remainder;               ///< no term divisible by any leading monomial
};

/// Divides `f` by `divisors` in list order: at each step the first divisor whose
/// leading monomial divides the current leading term is used; otherwise the term
/// moves to the remainder. Preconditions: no divisor is zero; all share f's ring.
/// Invariant checked by tests: f = Σ q_i g_i + r and lm(q_i g_i) <= lm(f).
DivisionResult divide(const Polynomial& f, std::span<const Polynomial> divisors, const Budget& budget = Budget());

/// The remainder of divide(f, basis): for a Gröbner basis, the unique normal form
/// of f modulo the ideal (independent of the basis order).
Polynomial normal_form(const Polynomial& f, std::span<const Polynomial> basis, const Budget& budget = Budget());

/// S(f, g) = (L / lt(f))·f − (L / lt(g))·g with L = lcm(lm f, lm g); f, g non-zero.
Polynomial s_polynomial(const Polynomial& f, const Polynomial& g);

}  // namespace implicitizer
