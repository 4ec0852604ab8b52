#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {

std::string to_string(const Polynomial& p) {
  if (p.is_zero()) return "0";
  const Ring& ring = *p.ring();
  const mpq_class content = to_mpq(p.content());
  std::string out;
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    mpq_class c = content * p.integer_coefficients()[t];
    if (c < 0) {
      out += '-';
      c = -c;
    } else if (t > 0) {
      out += '+';
    }
    const std::int32_t* e = ring.exponents(p.monomial(t));
    std::string mono;
    for (std::size_t i = 0; i < ring.num_variables(); ++i) {
      if (e[i] == 0) continue;
      if (!mono.empty()) mono += '*';
      mono += ring.variables()[i];
      if (e[i] > 1) mono += '^' + std::to_string(e[i]);
    }
    if (mono.empty()) {
      out += c.get_str();
    } else if (c == 1) {
      out += mono;
    } else {
      out += c.get_str() + '*' + mono;
    }
  }
  return out;
}

std::string to_string(const RationalFunction& f) {
  const std::string n = to_string(f.numerator());
  if (f.is_polynomial() && f.denominator().leading_coefficient() == Rational(1)) return n;
  // A single-term numerator needs no parentheses (a/b·c/d is one product chain), a
  // denominator does unless it is a number: n/2*e would read as (n/2)·e.
  const std::string numerator = f.numerator().num_terms() > 1 ? "(" + n + ")" : n;
  const std::string d = to_string(f.denominator());
  return numerator + "/" + (f.denominator().is_constant() ? d : "(" + d + ")");
}

}  // namespace implicitizer
