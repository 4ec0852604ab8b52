#include "implicitizer/polynomial/rational_function.hpp"

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/gcd.hpp"

namespace implicitizer {

namespace {

// The ways of RationalFunction's arithmetic keep every gcd on the operands, which the
// budget has already let through, and never on a product or sum: FLINT's gcd cannot be
// interrupted, and the gcd of two products of a million terms took longer than any
// request's limit (issue 41).

// a/g for a g that divides a (g = 1 often: no FLINT call then).
Polynomial without(const Polynomial& a, const Polynomial& g, const Budget& budget) {
  return g.is_constant() ? a : divide_exact(a, g, budget);
}

}  // namespace

RationalFunction::RationalFunction(Polynomial p)
    : numerator_(std::move(p)), denominator_(Polynomial::constant(numerator_.ring(), Rational(1))) {}

RationalFunction::RationalFunction(const Polynomial& n, const Polynomial& d) : numerator_(n), denominator_(d) {
  if (d.is_zero()) throw InputError("division_by_zero", "the denominator is the zero polynomial");
  if (!n.is_zero()) {
    const Polynomial g = gcd(n, d);
    numerator_ = without(n, g, Budget());
    denominator_ = without(d, g, Budget());
  }
  normalize();
}

RationalFunction RationalFunction::from_coprime(Polynomial n, Polynomial d) {
  if (d.is_zero()) throw InputError("division_by_zero", "the denominator is the zero polynomial");
  RationalFunction r(std::move(n));
  r.denominator_ = std::move(d);
  r.normalize();
  return r;
}

void RationalFunction::normalize() {
  if (numerator_.is_zero()) {
    denominator_ = Polynomial::constant(numerator_.ring(), Rational(1));
    return;
  }
  // Keep the denominator primitive with a positive leading coefficient; move its
  // content into the numerator.
  const Rational c = denominator_.content();
  denominator_ = denominator_.primitive_part();
  numerator_ = numerator_.divided_by(c);
}

RationalFunction RationalFunction::add(const RationalFunction& o, const Budget& budget) const {
  if (numerator_.is_zero()) return o;
  if (o.numerator_.is_zero()) return *this;
  // Henrici's sum (Knuth, TAOCP 4.5.1): with g = gcd(b, d), a/b + c/d =
  // t / ((b/g)·d), t = a·(d/g) + c·(b/g), and a factor common to t and the
  // denominator divides g (a prime of b/g divides c·(b/g) but not a·(d/g)), so only
  // gcd(t, g) remains to cancel.
  const Polynomial g = denominator_ == o.denominator_ ? denominator_ : gcd(denominator_, o.denominator_, budget);
  const Polynomial b_g = without(denominator_, g, budget);
  const Polynomial d_g = without(o.denominator_, g, budget);
  const Polynomial t = numerator_.multiply(d_g, budget) + o.numerator_.multiply(b_g, budget);
  if (t.is_zero()) return RationalFunction(t);
  const Polynomial h = gcd(t, g, budget);
  return from_coprime(without(t, h, budget), b_g.multiply(without(o.denominator_, h, budget), budget));
}

RationalFunction RationalFunction::multiply(const RationalFunction& o, const Budget& budget) const {
  if (numerator_.is_zero() || o.numerator_.is_zero()) return RationalFunction(Polynomial(numerator_.ring()));
  // (a/b)·(c/d) = ((a/g1)·(c/g2)) / ((b/g2)·(d/g1)) with g1 = gcd(a, d), g2 = gcd(c, b):
  // in lowest terms already, since a/b and c/d are.
  const Polynomial g1 = gcd(numerator_, o.denominator_, budget);
  const Polynomial g2 = gcd(o.numerator_, denominator_, budget);
  // Numerator first: a limit then names the same product on every compiler.
  Polynomial n = without(numerator_, g1, budget).multiply(without(o.numerator_, g2, budget), budget);
  Polynomial d = without(denominator_, g2, budget).multiply(without(o.denominator_, g1, budget), budget);
  return from_coprime(std::move(n), std::move(d));
}

RationalFunction RationalFunction::divide(const RationalFunction& o, const Budget& budget) const {
  if (o.numerator_.is_zero()) throw InputError("division_by_zero", "division by zero");
  return multiply(from_coprime(o.denominator_, o.numerator_), budget);
}

RationalFunction RationalFunction::operator+(const RationalFunction& o) const { return add(o, Budget()); }

RationalFunction RationalFunction::operator-() const {
  RationalFunction r = *this;
  r.numerator_ = -numerator_;
  return r;
}

RationalFunction RationalFunction::operator-(const RationalFunction& o) const { return *this + (-o); }

RationalFunction RationalFunction::operator*(const RationalFunction& o) const { return multiply(o, Budget()); }

RationalFunction RationalFunction::operator/(const RationalFunction& o) const { return divide(o, Budget()); }

RationalFunction RationalFunction::pow(unsigned e, const Budget& budget) const {
  // Powers of coprime polynomials stay coprime: no gcd needed.
  RationalFunction r(numerator_.pow(e, budget));
  r.denominator_ = denominator_.pow(e, budget);
  return r;
}

}  // namespace implicitizer
