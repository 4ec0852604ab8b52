#include "implicitizer/implicitization/verify.hpp"

namespace implicitizer {

bool substitutes_to_zero(const Polynomial& implicit, const Parametrization& parametrization, const Budget& budget) {
  const RingPtr& params = parametrization.parameter_ring;
  const Ring& space = *implicit.ring();
  // Clearing denominators: F(p1/q1, p2/q2, p3/q3)·q1^a·q2^b·q3^c is a polynomial, and
  // it vanishes exactly when F vanishes on the image (the q_i are non-zero).
  std::array<std::int32_t, 3> degree{};
  for (std::size_t v = 0; v < 3; ++v) degree[v] = std::max(0, implicit.degree_in(v));
  // Power tables: numerator^e and denominator^e for each coordinate.
  std::array<std::vector<Polynomial>, 3> num_powers, den_powers;
  for (std::size_t v = 0; v < 3; ++v) {
    const auto& c = parametrization.coordinates[v];
    num_powers[v].push_back(Polynomial::constant(params, Rational(1)));
    den_powers[v].push_back(Polynomial::constant(params, Rational(1)));
    for (std::int32_t e = 1; e <= degree[v]; ++e) {
      num_powers[v].push_back(num_powers[v].back().multiply(c.numerator(), budget));
      den_powers[v].push_back(den_powers[v].back().multiply(c.denominator(), budget));
    }
  }
  std::vector<Polynomial> terms;
  terms.reserve(implicit.num_terms());
  for (std::size_t t = 0; t < implicit.num_terms(); ++t) {
    const std::int32_t* e = space.exponents(implicit.monomial(t));
    Polynomial term = Polynomial::constant(params, implicit.coefficient(t));
    for (std::size_t v = 0; v < 3; ++v) {
      term = term.multiply(num_powers[v][e[v]], budget);
      term = term.multiply(den_powers[v][degree[v] - e[v]], budget);
    }
    terms.push_back(std::move(term));
    budget.check("verification");
  }
  return sum_of(params, std::move(terms)).is_zero();
}

}  // namespace implicitizer
