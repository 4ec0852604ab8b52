#include "implicitizer/groebner/division.hpp"

#include <stdexcept>

namespace implicitizer {

DivisionResult divide(const Polynomial& f, std::span<const Polynomial> divisors, const Budget& budget) {
  const RingPtr& ring = f.ring();
  for (const auto& g : divisors) {
    if (g.is_zero()) throw std::invalid_argument("division by the zero polynomial");
  }
  DivisionResult result{std::vector<Polynomial>(divisors.size(), Polynomial(ring)), Polynomial(ring)};
  // The textbook loop on rational polynomials (CLO Thm 2.3.3): readable and exact;
  // each step removes the leading term of p, so the loop ends.
  Polynomial p = f;
  std::vector<std::int32_t> quotient_exponents(ring->num_variables());
  while (!p.is_zero()) {
    budget.check("polynomial division");
    const std::int32_t* lead = p.leading_monomial();
    bool divided = false;
    for (std::size_t i = 0; i < divisors.size(); ++i) {
      const Polynomial& g = divisors[i];
      if (!ring->divides(g.leading_monomial(), lead)) continue;
      for (std::size_t v = 0; v < quotient_exponents.size(); ++v) {
        quotient_exponents[v] = ring->exponents(lead)[v] - ring->exponents(g.leading_monomial())[v];
      }
      const Polynomial q = Polynomial::term(ring, p.leading_coefficient() / g.leading_coefficient(), quotient_exponents);
      result.quotients[i] += q;
      p -= q * g;
      divided = true;
      break;
    }
    if (!divided) {
      const Polynomial lt = Polynomial::term(ring, p.leading_coefficient(), p.exponents(0));
      result.remainder += lt;
      p -= lt;
    }
  }
  return result;
}

Polynomial normal_form(const Polynomial& f, std::span<const Polynomial> basis, const Budget& budget) {
  return divide(f, basis, budget).remainder;
}

Polynomial s_polynomial(const Polynomial& f, const Polynomial& g) {
  if (f.is_zero() || g.is_zero()) throw std::invalid_argument("s_polynomial of zero");
  const Ring& ring = *f.ring();
  const std::size_t n = ring.num_variables();
  std::vector<std::int32_t> a(n), b(n);
  const std::int32_t* ef = ring.exponents(f.leading_monomial());
  const std::int32_t* eg = ring.exponents(g.leading_monomial());
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t l = std::max(ef[i], eg[i]);
    a[i] = l - ef[i];
    b[i] = l - eg[i];
  }
  return Polynomial::term(f.ring(), Rational(1) / f.leading_coefficient(), a) * f -
         Polynomial::term(f.ring(), Rational(1) / g.leading_coefficient(), b) * g;
}

}  // namespace implicitizer
