// Tests of evaluate_polynomial / evaluate_rational_function / parse_polynomial
// (lib/src/polynomial/parser.cpp): the meaning the contract gives to the input
// syntax, and the evaluation errors with their positions.

#include "implicitizer/polynomial/parser.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "implicitizer/polynomial/printer.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

using testing::throws_input_error;

class ParserTest : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"x", "y", "z"});
  Polynomial x_ = Polynomial::variable(ring_, 0);
  Polynomial y_ = Polynomial::variable(ring_, 1);
  Polynomial z_ = Polynomial::variable(ring_, 2);

  Polynomial c(long n, long d = 1) const { return Polynomial::constant(ring_, Rational(n, d)); }
  Polynomial parse(const std::string& text) const { return parse_polynomial(text, ring_); }
  ::testing::AssertionResult rejects(const std::string& text, const std::string& code, std::size_t position) const {
    return throws_input_error([&] { parse(text); }, code, position);
  }
};

TEST_F(ParserTest, UnaryMinusAppliesAfterThePower) {
  EXPECT_EQ(parse("-x^2"), -(x_ * x_));
  EXPECT_NE(parse("-x^2"), parse("(-x)^2"));
  EXPECT_EQ(parse("(-x)^2"), x_ * x_);
  EXPECT_EQ(parse("-2^2"), c(-4));
  const std::vector<Rational> at3 = {Rational(3), Rational(0), Rational(0)};
  EXPECT_EQ(parse("-x^2").evaluate(at3), Rational(-9));
}

TEST_F(ParserTest, PowerBeforeDivision) {
  const RingPtr s_ring = Ring::make({"s"});
  const Polynomial s = Polynomial::variable(s_ring, 0);
  EXPECT_EQ(parse_polynomial("s^2/1000", s_ring), (s * s).divided_by(Rational(1000)));
  EXPECT_EQ(parse_polynomial("s^2/10^3", s_ring), (s * s).divided_by(Rational(1000)));
}

TEST_F(ParserTest, ExactDecimals) {
  EXPECT_EQ(parse("0.25"), c(1, 4));
  EXPECT_EQ(parse("0.25x"), x_.scaled(Rational(1, 4)));
  EXPECT_EQ(parse("1.5e2*y"), y_.scaled(Rational(150)));
  mpz_class ten30;
  mpz_ui_pow_ui(ten30.get_mpz_t(), 10, 30);
  const Polynomial tiny = parse("1e-30");
  ASSERT_TRUE(tiny.is_constant());
  EXPECT_EQ(tiny.coefficient(0), to_rational(mpq_class(1, ten30)));
  // 1e-30 + 1 - 1 is not 0: no floating point anywhere.
  EXPECT_FALSE(parse("1e-30+1-1").is_zero());
  EXPECT_EQ(to_string(parse("0.1+0.2-0.3")), "0");
}

TEST_F(ParserTest, NumberDirectlyBeforeANameIsAProduct) {
  EXPECT_EQ(parse("2x"), x_.scaled(Rational(2)));
  EXPECT_EQ(parse("2x^2"), (x_ * x_).scaled(Rational(2)));
  EXPECT_EQ(parse("2x^2"), parse("2*x^2"));
  EXPECT_NE(parse("2x^2"), parse("(2*x)^2"));
  EXPECT_EQ(parse("3y*2x"), (x_ * y_).scaled(Rational(6)));
  EXPECT_EQ(parse("-2x"), x_.scaled(Rational(-2)));
  EXPECT_EQ(parse("0.5z"), z_.scaled(Rational(1, 2)));
}

TEST_F(ParserTest, DoubleStarIsPower) {
  EXPECT_EQ(parse("x**3"), parse("x^3"));
  EXPECT_EQ(parse("(x+y)**2"), parse("x^2+2*x*y+y^2"));
}

TEST_F(ParserTest, MultiLetterNamesAreSingleVariables) {
  const RingPtr ring = Ring::make({"rx", "r", "x", "ex", "e"});
  const Polynomial rx = Polynomial::variable(ring, 0), r = Polynomial::variable(ring, 1),
                   x = Polynomial::variable(ring, 2), ex = Polynomial::variable(ring, 3),
                   e = Polynomial::variable(ring, 4);
  EXPECT_EQ(parse_polynomial("rx", ring), rx);
  EXPECT_EQ(parse_polynomial("r*x", ring), r * x);
  EXPECT_NE(parse_polynomial("rx", ring), parse_polynomial("r*x", ring));
  EXPECT_EQ(parse_polynomial("2ex", ring), ex.scaled(Rational(2)));
  EXPECT_EQ(parse_polynomial("2e", ring), e.scaled(Rational(2)));
  EXPECT_EQ(parse_polynomial("2e1", ring), Polynomial::constant(ring, Rational(20)));
  EXPECT_EQ(parse_polynomial("2e-x", ring), e.scaled(Rational(2)) - x);
  EXPECT_EQ(parse_polynomial("2e2x", ring), x.scaled(Rational(200)));
  // `xy` is a name of its own, not x·y: unknown in this ring.
  EXPECT_TRUE(throws_input_error([&] { parse_polynomial("x+xy", ring); }, "unknown_variable", 2));
}

TEST_F(ParserTest, OperatorsAssociateToTheLeft) {
  EXPECT_EQ(parse("2-3-4"), c(-5));
  EXPECT_EQ(parse("2/3/4"), c(1, 6));
  EXPECT_EQ(parse("x/2*3"), x_.scaled(Rational(3, 2)));
  EXPECT_EQ(parse("x-y-z"), x_ - y_ - z_);
  EXPECT_EQ(parse("x-(y-z)"), x_ - y_ + z_);
}

TEST_F(ParserTest, ExpandsProductsAndPowers) {
  EXPECT_EQ(parse("(x+y)*(x-y)"), parse("x^2-y^2"));
  EXPECT_EQ(parse("(x+1)^3"), parse("x^3+3*x^2+3*x+1"));
  EXPECT_EQ(parse("(x+y+z)^0"), c(1));
  EXPECT_EQ(parse("0^0"), c(1));
  EXPECT_TRUE(parse("0^5").is_zero());
  EXPECT_TRUE(parse("(x-y)*(x+y)-x^2+y^2").is_zero());
}

TEST_F(ParserTest, DivisionByAConstantExpression) {
  EXPECT_EQ(parse("x/(1+1)"), x_.scaled(Rational(1, 2)));
  EXPECT_EQ(parse("(x+y)/(2/3)"), (x_ + y_).scaled(Rational(3, 2)));
  EXPECT_EQ(parse("x/(y-y+4)"), x_.scaled(Rational(1, 4)));
}

TEST_F(ParserTest, ErrorsCarryThePositionOfTheCause) {
  EXPECT_TRUE(rejects("x+w", "unknown_variable", 2));
  EXPECT_TRUE(rejects("x*(y+t^2)", "unknown_variable", 5));
  EXPECT_TRUE(rejects("x/0", "division_by_zero", 1));
  EXPECT_TRUE(rejects("x+y/(2-2)", "division_by_zero", 3));
  EXPECT_TRUE(rejects("x/(y-y)", "division_by_zero", 1));
  EXPECT_TRUE(rejects("x/0.0", "division_by_zero", 1));
  EXPECT_TRUE(rejects("x/(y+1)", "non_constant_denominator", 1));
  EXPECT_TRUE(rejects("1+x/(2*y)", "non_constant_denominator", 3));
  EXPECT_TRUE(rejects("x / y", "non_constant_denominator", 2));
  // `3x` is one atom, so `2/3x` is 2/(3x): a non-constant denominator.
  EXPECT_TRUE(rejects("2/3x", "non_constant_denominator", 1));
  // Syntax errors pass through parse_polynomial unchanged.
  EXPECT_TRUE(rejects("x+*y", "unexpected_token", 2));
}

TEST_F(ParserTest, ErrorMessagesNameTheVariables) {
  try {
    parse("x+w");
    FAIL();
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'w'"), std::string::npos) << message;
    EXPECT_NE(message.find("x, y, z"), std::string::npos) << message;
  }
}

TEST_F(ParserTest, BudgetLimitsTheSize) {
  Budget budget;
  budget.set_max_terms(50);
  try {
    parse_polynomial("(x+y+z+1)^20", ring_, budget);
    FAIL() << "a polynomial with 1771 terms fit a 50-term budget";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
  }
  EXPECT_NO_THROW(parse_polynomial("(x+y+z+1)^3", ring_, budget));  // 20 terms
}

TEST_F(ParserTest, CancelledBudgetStopsParsing) {
  Budget budget;
  budget.cancel();
  try {
    parse_polynomial("x+y", ring_, budget);
    FAIL();
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
    EXPECT_NE(std::string(e.what()).find("parsing"), std::string::npos) << e.what();
  }
}

TEST_F(ParserTest, ParseLimitsArePassedThrough) {
  ParseParams limits;
  limits.max_exponent = 3;
  EXPECT_TRUE(throws_input_error([&] { parse_polynomial("x^4", ring_, Budget(), limits); }, "exponent_too_large", 2));
  EXPECT_EQ(parse_polynomial("x^3", ring_, Budget(), limits), x_ * x_ * x_);
}

class RationalParserTest : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"s", "t"});
  Polynomial s_ = Polynomial::variable(ring_, 0);
  Polynomial t_ = Polynomial::variable(ring_, 1);
  Polynomial one_ = Polynomial::constant(ring_, Rational(1));

  RationalFunction parse(const std::string& text) const {
    return evaluate_rational_function(*parse_expression(text), ring_);
  }
};

TEST_F(RationalParserTest, ReducesToLowestTerms) {
  const RationalFunction f = parse("(t^2-1)/(t-1)");
  EXPECT_EQ(f.numerator(), t_ + one_);
  EXPECT_EQ(f.denominator(), one_);
  EXPECT_TRUE(f.is_polynomial());

  const RationalFunction h = parse("1/(1/s)");
  EXPECT_EQ(h.numerator(), s_);
  EXPECT_EQ(h.denominator(), one_);

  const RationalFunction k = parse("s/(s^2)");
  EXPECT_EQ(k.numerator(), one_);
  EXPECT_EQ(k.denominator(), s_);
}

TEST_F(RationalParserTest, DenominatorIsPrimitiveWithPositiveLeadingCoefficient) {
  const RationalFunction f = parse("1/(2-2t)");
  EXPECT_EQ(f.denominator(), t_ - one_);
  EXPECT_EQ(f.numerator(), Polynomial::constant(ring_, Rational(-1, 2)));

  const RationalFunction g = parse("(2t)/(2+2t^2)");
  EXPECT_EQ(g.numerator(), t_);
  EXPECT_EQ(g.denominator(), t_ * t_ + one_);
}

TEST_F(RationalParserTest, SumsOverCommonDenominators) {
  const RationalFunction f = parse("1/s + 1/t");
  EXPECT_EQ(f.numerator(), s_ + t_);
  EXPECT_EQ(f.denominator(), s_ * t_);
  EXPECT_TRUE(parse("1/(s+t) - 1/(t+s)").numerator().is_zero());
}

TEST_F(RationalParserTest, ZeroDenominatorAtItsSlash) {
  auto rejects = [&](const std::string& text, std::size_t position) {
    return throws_input_error([&] { parse(text); }, "division_by_zero", position);
  };
  EXPECT_TRUE(rejects("1/(t-t)", 1));
  EXPECT_TRUE(rejects("s + t/0", 5));
  EXPECT_TRUE(rejects("(1/t)/(1/t-1/t)", 5));
  EXPECT_TRUE(throws_input_error([&] { parse("s/q"); }, "unknown_variable", 2));
}

// Calls are the parametrization's business (trigonometric_substitution.hpp): an
// evaluator without a CallEvaluator refuses them at the function's name.
TEST_F(ParserTest, EvaluatorsRefuseCallsUnlessGivenAnEvaluator) {
  EXPECT_TRUE(throws_input_error([&] { parse_polynomial("x+cos(y)", ring_); }, "function_not_allowed", 2));
  EXPECT_TRUE(throws_input_error([&] { evaluate_rational_function(*parse_expression("1/sin(x)"), ring_); },
                                 "function_not_allowed", 2));
  const CallEvaluator y_for_every_call = [&](const Expression&) { return RationalFunction(y_); };
  const RationalFunction f =
      evaluate_rational_function(*parse_expression("x/cos(z)^2"), ring_, Budget(), y_for_every_call);
  EXPECT_EQ(to_string(f), "x/(y^2)");
}

}  // namespace
}  // namespace implicitizer
