#include "implicitizer/polynomial/rational_function.hpp"

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/gcd.hpp"

namespace implicitizer {

RationalFunction::RationalFunction(Polynomial p)
    : numerator_(std::move(p)), denominator_(Polynomial::constant(numerator_.ring(), Rational(1))) {}

RationalFunction::RationalFunction(const Polynomial& n, const Polynomial& d) : numerator_(n), denominator_(d) {
  if (d.is_zero()) throw InputError("division_by_zero", "the denominator is the zero polynomial");
  if (n.is_zero()) {
    denominator_ = Polynomial::constant(n.ring(), Rational(1));
    return;
  }
  const Polynomial g = gcd(n, d);
  if (!g.is_constant()) {
    numerator_ = divide_exact(n, g);
    denominator_ = divide_exact(d, g);
  }
  // Keep the denominator primitive with a positive leading coefficient; move its
  // content into the numerator.
  const Rational c = denominator_.content();
  denominator_ = denominator_.primitive_part();
  numerator_ = numerator_.divided_by(c);
}

RationalFunction RationalFunction::operator+(const RationalFunction& o) const {
  if (denominator_ == o.denominator_) return RationalFunction(numerator_ + o.numerator_, denominator_);
  // a/b + c/d = (a·(L/b) + c·(L/d)) / L with L = lcm(b, d): smaller than b·d.
  const Polynomial l = lcm(denominator_, o.denominator_);
  return RationalFunction(numerator_ * divide_exact(l, denominator_) + o.numerator_ * divide_exact(l, o.denominator_),
                          l);
}

RationalFunction RationalFunction::operator-() const {
  RationalFunction r = *this;
  r.numerator_ = -numerator_;
  return r;
}

RationalFunction RationalFunction::operator-(const RationalFunction& o) const { return *this + (-o); }

RationalFunction RationalFunction::operator*(const RationalFunction& o) const {
  return RationalFunction(numerator_ * o.numerator_, denominator_ * o.denominator_);
}

RationalFunction RationalFunction::operator/(const RationalFunction& o) const {
  if (o.numerator_.is_zero()) throw InputError("division_by_zero", "division by zero");
  return RationalFunction(numerator_ * o.denominator_, denominator_ * o.numerator_);
}

RationalFunction RationalFunction::pow(unsigned e, const Budget& budget) const {
  // Powers of coprime polynomials stay coprime: no gcd needed.
  RationalFunction r(numerator_.pow(e, budget));
  r.denominator_ = denominator_.pow(e, budget);
  return r;
}

}  // namespace implicitizer
