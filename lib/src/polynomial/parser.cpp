#include "implicitizer/polynomial/parser.hpp"

#include "implicitizer/core/errors.hpp"

namespace implicitizer {

namespace {

InputError unknown_variable(const Expression& e, const Ring& ring) {
  std::string names;
  for (const auto& v : ring.variables()) names += (names.empty() ? "" : ", ") + v;
  return InputError(
      "unknown_variable",
      "unknown variable '" + e.name + "' (the variables are " + (names.empty() ? std::string("none") : names) + ")",
      e.position);
}

InputError function_not_allowed(const Expression& e) {
  return InputError(
      "function_not_allowed",
      "the function '" + e.name + "' is accepted only in a parametrization's coordinates (x, y, z in the parameters)",
      e.position);
}

Polynomial polynomial_of(const Expression& e, const RingPtr& ring, const Budget& budget) {
  using Kind = Expression::Kind;
  switch (e.kind) {
    case Kind::number:
      return Polynomial::constant(ring, e.value);
    case Kind::identifier: {
      const auto index = ring->index_of(e.name);
      if (!index) throw unknown_variable(e, *ring);
      return Polynomial::variable(ring, *index);
    }
    case Kind::sum: {
      std::vector<Polynomial> parts;
      parts.reserve(e.children.size());
      for (const auto& c : e.children) parts.push_back(polynomial_of(*c, ring, budget));
      Polynomial s = sum_of(ring, std::move(parts));
      budget.check_terms(s.num_terms(), "parsing");
      return s;
    }
    case Kind::product: {
      Polynomial p = Polynomial::constant(ring, Rational(1));
      for (const auto& c : e.children) {
        if (c->kind == Kind::reciprocal) {
          const Polynomial d = polynomial_of(*c->children[0], ring, budget);
          if (d.is_zero()) throw InputError("division_by_zero", "division by zero", c->position);
          if (!d.is_constant()) {
            throw InputError("non_constant_denominator", "a polynomial may only be divided by a non-zero constant",
                             c->position);
          }
          p = p.divided_by(d.coefficient(0));
        } else {
          p = p.multiply(polynomial_of(*c, ring, budget), budget);
        }
      }
      return p;
    }
    case Kind::negate:
      return -polynomial_of(*e.children[0], ring, budget);
    case Kind::reciprocal: {
      // Only reachable for a tree not built by the parser; treat as 1/child.
      const Polynomial d = polynomial_of(*e.children[0], ring, budget);
      if (d.is_zero()) throw InputError("division_by_zero", "division by zero", e.position);
      if (!d.is_constant()) {
        throw InputError("non_constant_denominator", "a polynomial may only be divided by a non-zero constant",
                         e.position);
      }
      return Polynomial::constant(ring, Rational(1) / d.coefficient(0));
    }
    case Kind::power:
      return polynomial_of(*e.children[0], ring, budget).pow(e.exponent, budget);
    case Kind::call:
      throw function_not_allowed(e);
  }
  throw std::logic_error("unknown expression kind");
}

RationalFunction rational_function_of(const Expression& e, const RingPtr& ring, const Budget& budget,
                                      const CallEvaluator& calls) {
  using Kind = Expression::Kind;
  switch (e.kind) {
    case Kind::number:
    case Kind::identifier:
      return RationalFunction(polynomial_of(e, ring, budget));
    case Kind::sum: {
      RationalFunction s{Polynomial(ring)};
      for (const auto& c : e.children) {
        s = s.add(rational_function_of(*c, ring, budget, calls), budget);
        budget.check_terms(s.numerator().num_terms(), "parsing");
      }
      return s;
    }
    case Kind::product: {
      RationalFunction p(Polynomial::constant(ring, Rational(1)));
      for (const auto& c : e.children) p = p.multiply(rational_function_of(*c, ring, budget, calls), budget);
      return p;
    }
    case Kind::negate:
      return -rational_function_of(*e.children[0], ring, budget, calls);
    case Kind::reciprocal: {
      const RationalFunction d = rational_function_of(*e.children[0], ring, budget, calls);
      if (d.numerator().is_zero()) {
        throw InputError("division_by_zero", "the denominator is identically zero", e.position);
      }
      return RationalFunction(Polynomial::constant(ring, Rational(1))).divide(d, budget);
    }
    case Kind::power:
      return rational_function_of(*e.children[0], ring, budget, calls).pow(e.exponent, budget);
    case Kind::call:
      if (!calls) throw function_not_allowed(e);
      return calls(e);
  }
  throw std::logic_error("unknown expression kind");
}

}  // namespace

Polynomial evaluate_polynomial(const Expression& e, const RingPtr& ring, const Budget& budget) {
  return polynomial_of(e, ring, budget);
}

RationalFunction evaluate_rational_function(const Expression& e, const RingPtr& ring, const Budget& budget,
                                            const CallEvaluator& calls) {
  return rational_function_of(e, ring, budget, calls);
}

Polynomial parse_polynomial(std::string_view text, const RingPtr& ring, const Budget& budget,
                            const ParseParams& limits) {
  return evaluate_polynomial(*parse_expression(text, limits), ring, budget);
}

}  // namespace implicitizer
