// Tests of gcd, lcm and divide_exact (lib/src/polynomial/gcd.cpp, via FLINT) on known
// factorizations and on random products.

#include "implicitizer/polynomial/gcd.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

class GcdTest : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"x", "y", "z"});
  Polynomial parse(const std::string& text) const { return parse_polynomial(text, ring_); }
};

TEST_F(GcdTest, KnownFactorizations) {
  EXPECT_EQ(gcd(parse("(x+y)*(x-2z)^2"), parse("(x+y)*(y+3)")), parse("x+y"));
  EXPECT_EQ(gcd(parse("(x^2-y)^2*(z+1)"), parse("(x^2-y)*(z+1)^3")), parse("(x^2-y)*(z+1)"));
  EXPECT_EQ(gcd(parse("x^4-y^4"), parse("x^6-y^6")), parse("x^2-y^2"));
  EXPECT_EQ(gcd(parse("x^2+y^2"), parse("x+y")), parse("1"));
}

TEST_F(GcdTest, ResultIsPrimitiveWithPositiveLeadingCoefficient) {
  // The contents 6 and -4 and the sign of the common factor must all disappear.
  const Polynomial g = gcd(parse("6*(y-x)*(x+1)"), parse("-4*(y-x)*(z-1)"));
  EXPECT_EQ(g, parse("x-y"));
  EXPECT_EQ(g.content(), Rational(1));
  EXPECT_GT(g.leading_coefficient(), Rational(0));
  EXPECT_EQ(gcd(parse("x/2+1/3"), parse("(3x+2)*(y-5)")), parse("3x+2"));
}

TEST_F(GcdTest, LeadingCoefficientSignFollowsTheRingOrder) {
  // In lex with z > y > x the polynomial x - z leads with -z: the gcd is z - x.
  const RingPtr zyx = Ring::make({"z", "y", "x"}, MonomialOrder::lex());
  const Polynomial g = gcd(parse_polynomial("(x-z)*(y+1)", zyx), parse_polynomial("(x-z)*(y-1)", zyx));
  EXPECT_EQ(to_string(g), "z-x");
}

TEST_F(GcdTest, ZeroAndConstants) {
  EXPECT_TRUE(gcd(Polynomial(ring_), Polynomial(ring_)).is_zero());
  EXPECT_EQ(gcd(Polynomial(ring_), parse("-2x+4")), parse("x-2"));
  EXPECT_EQ(gcd(parse("-2x+4"), Polynomial(ring_)), parse("x-2"));
  EXPECT_EQ(gcd(parse("7"), parse("x+1")), parse("1"));
  EXPECT_EQ(gcd(parse("x+1"), parse("1/3")), parse("1"));
}

TEST_F(GcdTest, Lcm) {
  EXPECT_EQ(lcm(parse("x^2-1"), parse("x^2+2x+1")), parse("(x-1)*(x+1)^2"));
  EXPECT_EQ(lcm(parse("2x"), parse("-3x*y")), parse("x*y"));
  EXPECT_EQ(lcm(parse("x-y"), parse("y-x")), parse("x-y"));
  EXPECT_TRUE(lcm(Polynomial(ring_), parse("x")).is_zero());
  EXPECT_TRUE(lcm(parse("x"), Polynomial(ring_)).is_zero());
}

TEST_F(GcdTest, DivideExact) {
  EXPECT_EQ(divide_exact(parse("x^2-1"), parse("x-1")), parse("x+1"));
  EXPECT_EQ(divide_exact(parse("3x^2-3"), parse("2x-2")), parse("3/2*x+3/2"));
  EXPECT_EQ(divide_exact(parse("x^2-y^2"), parse("y-x")), parse("-x-y"));
  EXPECT_EQ(divide_exact(parse("x*y"), parse("1/2")), parse("2x*y"));
  EXPECT_TRUE(divide_exact(Polynomial(ring_), parse("x+1")).is_zero());
  EXPECT_THROW(divide_exact(parse("x^2"), parse("x+1")), std::logic_error);
  EXPECT_THROW(divide_exact(parse("x"), Polynomial(ring_)), std::logic_error);
}

// Where one polynomial's variables are a proper subset of the other's, gcd and
// divide_exact go coefficient by coefficient (issue 41: FLINT cannot be interrupted on
// a million-term common denominator); they must agree with FLINT's answers.
TEST_F(GcdTest, FewerVariablesGoThroughTheCoefficients) {
  const Polynomial big = parse("(x^2+1)^3*(y^2+1)^2*(x-3z)");
  EXPECT_EQ(gcd(big, parse("(x^2+1)^5")), parse("(x^2+1)^3"));
  EXPECT_EQ(gcd(parse("(x^2+1)^5"), big), parse("(x^2+1)^3"));
  EXPECT_EQ(gcd(big, parse("(y^2+1)*(y-7)")), parse("y^2+1"));
  EXPECT_EQ(gcd(big, parse("x+2")), parse("1"));
  EXPECT_EQ(divide_exact(big, parse("-2*(x^2+1)^2")), parse("-1/2*(x^2+1)*(y^2+1)^2*(x-3z)"));
  EXPECT_EQ(divide_exact(parse("3*(x+y)*(x-1)"), parse("x-1")), parse("3x+3y"));
  EXPECT_THROW(divide_exact(big, parse("x+2")), std::logic_error);
  // The budget is read between the coefficients.
  Budget cancelled;
  cancelled.cancel();
  EXPECT_THROW(gcd(big, parse("(x^2+1)^5"), cancelled), LimitExceeded);
}

TEST(GcdProperties, RandomProducts) {
  for (const MonomialOrder& order : testing::all_orders(3)) {
    SCOPED_TRACE(order.name());
    const RingPtr ring = Ring::make({"x", "y", "z"}, order);
    testing::RandomSource random(77);
    for (int i = 0; i < 15; ++i) {
      const Polynomial a = random.polynomial(ring, 4, 3), b = random.polynomial(ring, 4, 3),
                       c = random.polynomial(ring, 4, 3);
      if (a.is_zero() || b.is_zero() || c.is_zero()) continue;
      const Polynomial g = gcd(a * c, b * c);
      EXPECT_TRUE(g.is_canonical());
      EXPECT_EQ(g.content(), Rational(1));
      // c divides the gcd, and the gcd divides both products.
      EXPECT_NO_THROW(divide_exact(g, c)) << to_string(g) << " / " << to_string(c);
      EXPECT_EQ(divide_exact(a * c, g) * g, a * c);
      EXPECT_EQ(divide_exact(b * c, g) * g, b * c);
      const Polynomial l = lcm(a * c, b * c);
      EXPECT_TRUE(l.is_canonical());
      // gcd · lcm = a c · b c up to a constant factor.
      EXPECT_EQ(g * l, (a * c * b * c).primitive_part());
      EXPECT_EQ(divide_exact(a * b, b), a);
      // The same with a factor in fewer variables (the coefficient-wise route).
      const Polynomial in_x = a.substitute(1, Polynomial::constant(ring, Rational(2)))
                                  .substitute(2, Polynomial::constant(ring, Rational(-1)));
      if (!in_x.is_constant()) {
        EXPECT_EQ(divide_exact(b * c * in_x, in_x), b * c);
        const Polynomial h = gcd(b * in_x, in_x * in_x);
        EXPECT_EQ(h, in_x.primitive_part() * gcd(b, in_x));
      }
    }
  }
}

}  // namespace
}  // namespace implicitizer
