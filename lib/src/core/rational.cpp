#include "implicitizer/core/rational.hpp"

#include <stdexcept>

namespace implicitizer {

mpq_class to_mpq(const Rational& q) { return mpq_class(q.mpq()); }

Rational to_rational(const mpq_class& q) { return Rational(q.get_mpq_t()); }

Integer to_integer(const Rational& q) {
  const mpq_class v = to_mpq(q);
  if (v.get_den() != 1) throw std::invalid_argument("to_integer: " + v.get_str() + " is not an integer");
  return v.get_num();
}

Rational to_rational(const Integer& z) {
  mpq_class q(z);
  return Rational(q.get_mpq_t());
}

std::string to_string(const Rational& q) { return to_mpq(q).get_str(); }

}  // namespace implicitizer
