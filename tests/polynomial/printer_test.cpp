// Tests of to_string(Polynomial) (lib/src/polynomial/printer.cpp): the contract's
// output format, and print → parse being the identity in every order.

#include "implicitizer/polynomial/printer.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/polynomial/parser.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

std::string reprint(const std::string& text, const MonomialOrder& order = MonomialOrder::grevlex()) {
  return to_string(parse_polynomial(text, Ring::make({"x", "y", "z"}, order)));
}

TEST(Printer, ContractExamples) {
  EXPECT_EQ(reprint("1 - y + 0.75x^2"), "3/4*x^2-y+1");
  EXPECT_EQ(reprint("-x"), "-x");
  EXPECT_EQ(reprint("x-x"), "0");
  EXPECT_EQ(reprint("0"), "0");
  EXPECT_EQ(reprint("1"), "1");
  EXPECT_EQ(reprint("-1/2"), "-1/2");
  EXPECT_EQ(reprint("6/4"), "3/2");
}

TEST(Printer, ExplicitOperatorsAndNoSpaces) {
  EXPECT_EQ(reprint("z^3 * y^2 * x * (-3/4)"), "-3/4*x*y^2*z^3");
  EXPECT_EQ(reprint("2x*y*3"), "6*x*y");
  EXPECT_EQ(reprint("x^10"), "x^10");
  EXPECT_EQ(reprint("-x*y + 1/3"), "-x*y+1/3");
  EXPECT_EQ(reprint("123456789012345678901234567890*x - 1/98765432109876543210"),
            "123456789012345678901234567890*x-1/98765432109876543210");
}

TEST(Printer, IntegerCoefficientsOfARationalContent) {
  // Content 1/6 times 3x+2y: the printer must combine and reduce each coefficient.
  EXPECT_EQ(reprint("x/2 + y/3"), "1/2*x+1/3*y");
  EXPECT_EQ(reprint("(4x + 6y)/8"), "1/2*x+3/4*y");
  EXPECT_EQ(reprint("-(4x - 6y)/8"), "-1/2*x+3/4*y");
}

TEST(Printer, TermsInDecreasingOrderOfTheRing) {
  const std::string all_quadrics = "z^2+y*z+x*z+y^2+x*y+x^2";
  EXPECT_EQ(reprint(all_quadrics, MonomialOrder::grevlex()), "x^2+x*y+y^2+x*z+y*z+z^2");
  EXPECT_EQ(reprint(all_quadrics, MonomialOrder::grlex()), "x^2+x*y+x*z+y^2+y*z+z^2");
  EXPECT_EQ(reprint(all_quadrics, MonomialOrder::lex()), "x^2+x*y+x*z+y^2+y*z+z^2");
  EXPECT_EQ(reprint("1+z+y^5+x", MonomialOrder::lex()), "x+y^5+z+1");
  EXPECT_EQ(reprint("1+z+y^5+x", MonomialOrder::grevlex()), "y^5+x+z+1");
  EXPECT_EQ(reprint("x*z^2 + y^3", MonomialOrder::grevlex()), "y^3+x*z^2");
  EXPECT_EQ(reprint("x*z^2 + y^3", MonomialOrder::grlex()), "x*z^2+y^3");
  EXPECT_EQ(reprint("x + y^2", MonomialOrder::weighted({3, 1, 1}, MonomialOrder::grevlex())), "x+y^2");
  EXPECT_EQ(reprint("x + y^4", MonomialOrder::weighted({3, 1, 1}, MonomialOrder::grevlex())), "y^4+x");
}

TEST(Printer, VariablesInRingOrderWithinAMonomial) {
  const RingPtr ring = Ring::make({"t", "s"});
  EXPECT_EQ(to_string(parse_polynomial("s*t^2", ring)), "t^2*s");
}

// print → parse is the identity, and printing again gives the same text: for random
// polynomials with huge and tiny coefficients, in every kind of order, with variable
// names that could confuse a careless printer (`e` next to a number, multi-letter names).
TEST(Printer, RoundTripInEveryOrder) {
  const std::vector<std::string> names = {"x", "y", "z", "e", "rx", "t_1"};
  for (const MonomialOrder& order : testing::all_orders(names.size())) {
    const RingPtr ring = Ring::make(names, order);
    testing::RandomSource random(20240601);
    for (int i = 0; i < 150; ++i) {
      const Polynomial p = random.polynomial(ring, 8, 6);
      const std::string text = to_string(p);
      SCOPED_TRACE(order.name() + ": " + text);
      EXPECT_EQ(text.find(' '), std::string::npos);
      const Polynomial q = parse_polynomial(text, ring);
      EXPECT_TRUE(q.is_canonical());
      EXPECT_EQ(q, p);
      EXPECT_EQ(to_string(q), text);
    }
  }
}

// The printed terms come in the ring's decreasing order: re-parsing each printed term
// on its own and comparing neighbours must find them strictly decreasing.
TEST(Printer, PrintedTermsAreStrictlyDecreasing) {
  const std::vector<std::string> names = {"x", "y", "z"};
  for (const MonomialOrder& order : testing::all_orders(names.size())) {
    const RingPtr ring = Ring::make(names, order);
    testing::RandomSource random(7);
    for (int i = 0; i < 40; ++i) {
      const Polynomial p = random.polynomial(ring, 10, 5);
      if (p.is_zero()) continue;
      const std::string text = to_string(p);
      std::vector<Polynomial> terms;
      std::size_t start = 0;
      for (std::size_t k = 1; k <= text.size(); ++k) {
        if (k == text.size() || text[k] == '+' || text[k] == '-') {
          terms.push_back(parse_polynomial(text.substr(start, k - start), ring));
          start = k;
        }
      }
      ASSERT_EQ(terms.size(), p.num_terms()) << text;
      for (std::size_t k = 1; k < terms.size(); ++k) {
        EXPECT_GT(ring->compare(terms[k - 1].leading_monomial(), terms[k].leading_monomial()), 0)
            << order.name() << ": " << text;
      }
    }
  }
}

// A rational function prints as text that parses back to it: a denominator that is
// not a number keeps its parentheses (n/2*e would be (n/2)*e).
TEST(Printer, RationalFunctionsParseBack) {
  const RingPtr ring = Ring::make({"s", "t"});
  for (const char* text : {"s^2+t", "(1-t^2)/(1+t^2)", "2*t/(1+t^2)", "(s^2-1)/(2*s)", "s/2", "-t^2/(3*s)", "1/s"}) {
    SCOPED_TRACE(text);
    const RationalFunction f = evaluate_rational_function(*parse_expression(text), ring);
    const std::string printed = to_string(f);
    const RationalFunction back = evaluate_rational_function(*parse_expression(printed), ring);
    EXPECT_EQ(back.numerator(), f.numerator()) << printed;
    EXPECT_EQ(back.denominator(), f.denominator()) << printed;
  }
  EXPECT_EQ(to_string(evaluate_rational_function(*parse_expression("(s^2-1)/(2*s)"), ring)), "(1/2*s^2-1/2)/(s)");
}

}  // namespace
}  // namespace implicitizer
