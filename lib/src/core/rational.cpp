#include "implicitizer/core/rational.hpp"

namespace implicitizer {

mpq_class to_mpq(const Rational& q) { return mpq_class(q.mpq()); }

Rational to_rational(const mpq_class& q) { return Rational(q.get_mpq_t()); }

Rational to_rational(const Integer& z) {
  mpq_class q(z);
  return Rational(q.get_mpq_t());
}

std::string to_string(const Rational& q) { return to_mpq(q).get_str(); }

}  // namespace implicitizer
