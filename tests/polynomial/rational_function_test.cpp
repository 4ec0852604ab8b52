// Tests of RationalFunction (lib/src/polynomial/rational_function.cpp): lowest terms,
// the normal form of the denominator, field arithmetic, division by zero.

#include "implicitizer/polynomial/rational_function.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/polynomial/gcd.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

class RationalFunctionTest : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"s", "t"});
  Polynomial parse(const std::string& text) const { return parse_polynomial(text, ring_); }
  RationalFunction fraction(const std::string& n, const std::string& d) const {
    return RationalFunction(parse(n), parse(d));
  }
};

// The normal form: gcd(n, d) = 1, d primitive with integer coefficients and a positive
// leading coefficient.
::testing::AssertionResult is_normal(const RationalFunction& f) {
  const Polynomial& d = f.denominator();
  if (d.is_zero()) return ::testing::AssertionFailure() << "zero denominator";
  if (d.content() != Rational(1)) return ::testing::AssertionFailure() << "denominator not primitive: " << to_string(d);
  if (!(d.leading_coefficient() > Rational(0))) return ::testing::AssertionFailure() << "negative leading coefficient";
  if (!gcd(f.numerator(), d).is_constant()) {
    return ::testing::AssertionFailure() << "not in lowest terms: " << to_string(f.numerator()) << " / "
                                         << to_string(d);
  }
  if (f.numerator().is_zero() && d != Polynomial::constant(d.ring(), Rational(1))) {
    return ::testing::AssertionFailure() << "zero with denominator " << to_string(d);
  }
  return ::testing::AssertionSuccess();
}

TEST_F(RationalFunctionTest, LowestTerms) {
  const RationalFunction f = fraction("s^2-t^2", "2s+2t");
  EXPECT_EQ(f.numerator(), parse("s/2-t/2"));
  EXPECT_EQ(f.denominator(), parse("1"));
  EXPECT_TRUE(f.is_polynomial());
  EXPECT_TRUE(is_normal(f));

  const RationalFunction g = fraction("6*s*(t+1)", "-4*(t+1)^2*s^2");
  EXPECT_EQ(g.numerator(), parse("-3/2"));
  EXPECT_EQ(g.denominator(), parse("s*t+s"));
  EXPECT_FALSE(g.is_polynomial());
  EXPECT_TRUE(is_normal(g));
}

TEST_F(RationalFunctionTest, DenominatorNormalForm) {
  const RationalFunction f = fraction("1", "1/3 - t/3");
  EXPECT_EQ(f.denominator(), parse("t-1"));
  EXPECT_EQ(f.numerator(), parse("-3"));
  EXPECT_TRUE(is_normal(f));
}

TEST_F(RationalFunctionTest, ZeroNumeratorHasDenominatorOne) {
  const RationalFunction f = fraction("0", "s+t");
  EXPECT_TRUE(f.numerator().is_zero());
  EXPECT_EQ(f.denominator(), parse("1"));
}

TEST_F(RationalFunctionTest, DivisionByZero) {
  EXPECT_TRUE(testing::throws_input_error([&] { fraction("s", "t-t"); }, "division_by_zero"));
  EXPECT_TRUE(testing::throws_input_error([&] { RationalFunction(parse("s")) / RationalFunction(Polynomial(ring_)); },
                                          "division_by_zero"));
}

TEST_F(RationalFunctionTest, Arithmetic) {
  const RationalFunction a = fraction("1", "s"), b = fraction("1", "t");
  const RationalFunction sum = a + b;
  EXPECT_EQ(sum.numerator(), parse("s+t"));
  EXPECT_EQ(sum.denominator(), parse("s*t"));
  EXPECT_TRUE((a - a).numerator().is_zero());
  EXPECT_TRUE(is_normal(a - a));
  const RationalFunction q = fraction("2t", "1+t^2");
  const RationalFunction one_minus = RationalFunction(parse("1")) - q * q;  // (1-t^2)^2/(1+t^2)^2
  EXPECT_EQ(one_minus.numerator(), parse("(1-t^2)^2"));
  EXPECT_EQ(one_minus.denominator(), parse("(1+t^2)^2"));
  EXPECT_EQ((q / q).numerator(), parse("1"));
  EXPECT_EQ((q / q).denominator(), parse("1"));
  const RationalFunction cube = fraction("s", "2t-2").pow(3);
  EXPECT_EQ(cube.numerator(), parse("s^3/8"));
  EXPECT_EQ(cube.denominator(), parse("(t-1)^3"));
  EXPECT_TRUE(is_normal(cube));
  EXPECT_EQ(fraction("s", "t").pow(0).numerator(), parse("1"));
  EXPECT_EQ((-fraction("s", "t")).numerator(), parse("-s"));
}

// Field identities on random fractions; every result in normal form, and equal
// fractions have equal normal forms (so == on the parts is equality of functions).
TEST(RationalFunctionProperties, FieldIdentities) {
  const RingPtr ring = Ring::make({"s", "t"});
  testing::RandomSource random(123);
  auto random_fraction = [&] {
    Polynomial d = random.polynomial(ring, 3, 2);
    if (d.is_zero()) d = Polynomial::constant(ring, Rational(3));
    return RationalFunction(random.polynomial(ring, 3, 2), d);
  };
  auto same = [](const RationalFunction& f, const RationalFunction& g) {
    return f.numerator() == g.numerator() && f.denominator() == g.denominator();
  };
  for (int i = 0; i < 60; ++i) {
    const RationalFunction a = random_fraction(), b = random_fraction(), c = random_fraction();
    EXPECT_TRUE(is_normal(a));
    EXPECT_TRUE(is_normal(a + b));
    EXPECT_TRUE(is_normal(a * b));
    EXPECT_TRUE(same(a + b, b + a));
    EXPECT_TRUE(same((a + b) * c, a * c + b * c));
    EXPECT_TRUE(same((a * b) * c, a * (b * c)));
    EXPECT_TRUE(same((a - b) + b, a));
    if (!b.numerator().is_zero()) {
      EXPECT_TRUE(same((a / b) * b, a));
      EXPECT_TRUE(is_normal(a / b));
    }
    EXPECT_TRUE(same(a.pow(2), a * a));
    // Henrici's sum and the crosswise product take gcds of the operands only; they
    // agree with the gcd of the whole result.
    const Polynomial &an = a.numerator(), &ad = a.denominator(), &bn = b.numerator(), &bd = b.denominator();
    EXPECT_TRUE(same(a + b, RationalFunction(an * bd + bn * ad, ad * bd)));
    EXPECT_TRUE(same(a * b, RationalFunction(an * bn, ad * bd)));
    const std::vector<Rational> point = random.point(2);
    const Rational da = a.denominator().evaluate(point), db = b.denominator().evaluate(point);
    if (da != 0 && db != 0) {
      const RationalFunction p = a * b;
      const Rational dp = p.denominator().evaluate(point);
      ASSERT_NE(dp, Rational(0));
      EXPECT_EQ(p.numerator().evaluate(point) / dp,
                (a.numerator().evaluate(point) / da) * (b.numerator().evaluate(point) / db));
    }
  }
}

}  // namespace
}  // namespace implicitizer
