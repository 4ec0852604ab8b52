#include "implicitizer/core/rational.hpp"

#include <cmath>
#include <limits>
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

// mpq_get_d truncates toward zero, so step once or twice to the right side. Beyond
// F's range the answer is ±infinity; mpq_class(±inf) would raise SIGFPE in GMP (the
// request fuzzer found it with a patch whose box exceeds float's range), hence the
// isfinite guard.
template <typename F>
F round_down(const Rational& q) {
  const mpq_class exact = to_mpq(q);
  F x = static_cast<F>(exact.get_d());
  while (std::isfinite(x) && mpq_class(static_cast<double>(x)) > exact) {
    x = std::nextafter(x, -std::numeric_limits<F>::infinity());
  }
  return x;
}

template <typename F>
F round_up(const Rational& q) {
  const mpq_class exact = to_mpq(q);
  F x = static_cast<F>(exact.get_d());
  while (std::isfinite(x) && mpq_class(static_cast<double>(x)) < exact) {
    x = std::nextafter(x, std::numeric_limits<F>::infinity());
  }
  return x;
}

template float round_down<float>(const Rational&);
template double round_down<double>(const Rational&);
template float round_up<float>(const Rational&);
template double round_up<double>(const Rational&);

}  // namespace implicitizer
