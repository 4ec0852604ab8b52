// Tests of parse_expression (lib/src/polynomial/expression.cpp): the shape of the
// syntax tree and every error the lexer and parser report, with its exact position.

#include "implicitizer/polynomial/expression.hpp"

#include <gtest/gtest.h>

#include <string>

#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

using testing::throws_input_error;
using Kind = Expression::Kind;

::testing::AssertionResult rejects(const std::string& text, const std::string& code, std::size_t position,
                                   const ParseParams& limits = {}) {
  return throws_input_error([&] { parse_expression(text, limits); }, code, position);
}

std::string nested(std::size_t depth) { return std::string(depth, '(') + "x" + std::string(depth, ')'); }

TEST(ExpressionErrors, UnexpectedToken) {
  EXPECT_TRUE(rejects("x+*y", "unexpected_token", 2));
  EXPECT_TRUE(rejects("x*/y", "unexpected_token", 2));
  EXPECT_TRUE(rejects(")", "unexpected_token", 0));
  EXPECT_TRUE(rejects("x)", "unexpected_token", 1));
  EXPECT_TRUE(rejects("(x+1))", "unexpected_token", 5));
  EXPECT_TRUE(rejects("()", "unexpected_token", 1));
  EXPECT_TRUE(rejects("x^2*^3", "unexpected_token", 4));
  EXPECT_TRUE(rejects("*x", "unexpected_token", 0));
}

TEST(ExpressionErrors, MissingOperator) {
  EXPECT_TRUE(rejects("2 x", "missing_operator", 2));
  EXPECT_TRUE(rejects("x y", "missing_operator", 2));
  EXPECT_TRUE(rejects("2x y", "missing_operator", 3));
  EXPECT_TRUE(rejects("2(x+1)", "missing_operator", 1));
  EXPECT_TRUE(rejects("(x+1)(x-1)", "missing_operator", 5));
  EXPECT_TRUE(rejects("(x y)", "missing_operator", 3));
  EXPECT_TRUE(rejects("x.5", "missing_operator", 1));
  // After an exponent only an operator may follow, even a name directly after it.
  EXPECT_TRUE(rejects("2^2x", "missing_operator", 3));
}

// A name before '(' is a call: never missing_operator, and the error names the function.
TEST(ExpressionErrors, FunctionCallsAreNamedNotMissingOperators) {
  EXPECT_TRUE(rejects("sqrt(s)", "function_not_rational", 0));
  EXPECT_TRUE(rejects("2*exp(s)", "function_not_rational", 2));
  EXPECT_TRUE(rejects("1+log(t)", "function_not_rational", 2));
  EXPECT_TRUE(rejects("ln(t)", "function_not_rational", 0));
  EXPECT_TRUE(rejects("s*foo(t)", "unknown_function", 2));
  EXPECT_TRUE(rejects("s (t)", "unknown_function", 0));
  EXPECT_TRUE(rejects("acos(t)", "unknown_function", 0));
  // The name is checked before its argument, whatever is wrong inside.
  EXPECT_TRUE(rejects("sqrt(s+)", "function_not_rational", 0));
  EXPECT_TRUE(rejects("cos(s", "missing_parenthesis", 3));
  EXPECT_TRUE(rejects("cos()", "unexpected_token", 4));
  EXPECT_TRUE(rejects("cos(s t)", "missing_operator", 6));
  try {
    parse_expression("s*sqrt(t)");
    FAIL() << "sqrt accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'sqrt'"), std::string::npos) << e.what();
  }
}

TEST(ExpressionErrors, MissingParenthesisPointsAtTheOpeningOne) {
  EXPECT_TRUE(rejects("(x+1", "missing_parenthesis", 0));
  EXPECT_TRUE(rejects("x*(y+(z-1)", "missing_parenthesis", 2));
  EXPECT_TRUE(rejects("((x)", "missing_parenthesis", 0));
}

TEST(ExpressionErrors, UnexpectedEnd) {
  EXPECT_TRUE(rejects("x+", "unexpected_end", 2));
  EXPECT_TRUE(rejects("x^", "unexpected_end", 2));
  EXPECT_TRUE(rejects("x**", "unexpected_end", 3));
  EXPECT_TRUE(rejects("-", "unexpected_end", 1));
  EXPECT_TRUE(rejects("(x+1)* ", "unexpected_end", 7));
}

TEST(ExpressionErrors, ExponentMustBeANonNegativeIntegerLiteral) {
  EXPECT_TRUE(rejects("x^-1", "exponent_not_integer", 2));
  EXPECT_TRUE(rejects("x^1.5", "exponent_not_integer", 2));
  EXPECT_TRUE(rejects("x^y", "exponent_not_integer", 2));
  EXPECT_TRUE(rejects("x^(2)", "exponent_not_integer", 2));
  EXPECT_TRUE(rejects("x^1e3", "exponent_not_integer", 2));
  EXPECT_TRUE(rejects("x ^ -2", "exponent_not_integer", 4));
}

TEST(ExpressionErrors, ExponentTooLarge) {
  EXPECT_TRUE(rejects("x^1001", "exponent_too_large", 2));
  EXPECT_TRUE(rejects("x**99999999999999999999", "exponent_too_large", 3));
  EXPECT_NO_THROW(parse_expression("x^1000"));
  ParseParams limits;
  limits.max_exponent = 10;
  EXPECT_TRUE(rejects("y+x^11", "exponent_too_large", 4, limits));
  EXPECT_NO_THROW(parse_expression("x^10", limits));
  // Leading zeros count for nothing: x^0000000002 is x^2, x^00001001 still too large.
  EXPECT_NO_THROW(parse_expression("x^0000000002"));
  EXPECT_TRUE(rejects("x^00000000001001", "exponent_too_large", 2));
}

TEST(ExpressionErrors, ChainedExponentIsAmbiguous) {
  EXPECT_TRUE(rejects("x^2^3", "chained_exponent", 3));
  EXPECT_TRUE(rejects("x**2**3", "chained_exponent", 4));
  EXPECT_TRUE(rejects("2x^2^3", "chained_exponent", 4));
  EXPECT_NO_THROW(parse_expression("(x^2)^3"));
}

TEST(ExpressionErrors, IdentifierTooLong) {
  const std::string longest(32, 'a');
  EXPECT_NO_THROW(parse_expression(longest));
  EXPECT_TRUE(rejects(longest + "b", "identifier_too_long", 0));
  EXPECT_TRUE(rejects("x+" + longest + "_", "identifier_too_long", 2));
  ParseParams limits;
  limits.max_identifier = 3;
  EXPECT_TRUE(rejects("abc*abcd", "identifier_too_long", 4, limits));
}

TEST(ExpressionErrors, UnexpectedCharacter) {
  EXPECT_TRUE(rejects("x+\xc3\xa9", "unexpected_character", 2));  // é in UTF-8
  EXPECT_TRUE(rejects("\xff", "unexpected_character", 0));
  // Latin-1 letters are not identifier characters, whatever the C locale says.
  EXPECT_TRUE(rejects("\xe9", "unexpected_character", 0));
  EXPECT_TRUE(rejects("x\xe9", "unexpected_character", 1));
  EXPECT_TRUE(rejects("x\x80", "unexpected_character", 1));
  EXPECT_TRUE(rejects("x=y", "unexpected_character", 1));
  EXPECT_TRUE(rejects("x,y", "unexpected_character", 1));
  EXPECT_TRUE(rejects("x+y;", "unexpected_character", 3));
  EXPECT_TRUE(rejects("x+\x01", "unexpected_character", 2));
  EXPECT_TRUE(rejects(std::string("x+\0", 3), "unexpected_character", 2));
  EXPECT_TRUE(rejects("1.+x", "unexpected_character", 1));  // a decimal point needs a digit after it
}

TEST(ExpressionErrors, EmptyInput) {
  EXPECT_TRUE(rejects("", "empty_input", 0));
  EXPECT_TRUE(rejects("  \t\n ", "empty_input", 0));
}

TEST(ExpressionErrors, NestingTooDeep) {
  EXPECT_NO_THROW(parse_expression(nested(100)));
  try {
    parse_expression(nested(300));
    ADD_FAILURE() << "300 nested parentheses were accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "nesting_too_deep");
    ASSERT_TRUE(e.position().has_value());
    EXPECT_LT(*e.position(), 300u);  // inside the run of '('
  }
  EXPECT_TRUE(rejects(std::string(300, '-') + "x", "nesting_too_deep", 256));
  ParseParams limits;
  limits.max_depth = 4;
  EXPECT_TRUE(rejects("----x", "nesting_too_deep", 4, limits));
  EXPECT_NO_THROW(parse_expression("---x", limits));
}

TEST(ExpressionErrors, InputTooLong) {
  ParseParams limits;
  limits.max_length = 8;
  EXPECT_TRUE(rejects("x+y+z+x+y", "input_too_long", 0, limits));
  EXPECT_NO_THROW(parse_expression("x+y+z+xy", limits));
}

TEST(ExpressionErrors, HugeDecimalExponent) {
  EXPECT_TRUE(rejects("x+1e1000000", "number_too_large", 2));
  EXPECT_TRUE(rejects("2e100001", "number_too_large", 0));
}

TEST(ExpressionTree, SumsAreNaryWithNegatedTerms) {
  const auto e = parse_expression("a-b+c");
  ASSERT_EQ(e->kind, Kind::sum);
  ASSERT_EQ(e->children.size(), 3u);
  EXPECT_EQ(e->children[0]->kind, Kind::identifier);
  EXPECT_EQ(e->children[0]->name, "a");
  ASSERT_EQ(e->children[1]->kind, Kind::negate);
  EXPECT_EQ(e->children[1]->position, 1u);
  EXPECT_EQ(e->children[1]->children[0]->name, "b");
  EXPECT_EQ(e->children[2]->name, "c");
  EXPECT_EQ(e->children[2]->position, 4u);
}

TEST(ExpressionTree, ProductsAreNaryWithReciprocals) {
  const auto e = parse_expression("a/b*c");
  ASSERT_EQ(e->kind, Kind::product);
  ASSERT_EQ(e->children.size(), 3u);
  ASSERT_EQ(e->children[1]->kind, Kind::reciprocal);
  EXPECT_EQ(e->children[1]->position, 1u);
  EXPECT_EQ(e->children[1]->children[0]->name, "b");
  EXPECT_EQ(e->children[2]->name, "c");
}

TEST(ExpressionTree, PowerBindsTighterThanUnaryMinus) {
  const auto e = parse_expression("-x^2");
  ASSERT_EQ(e->kind, Kind::negate);
  const auto& p = *e->children[0];
  ASSERT_EQ(p.kind, Kind::power);
  EXPECT_EQ(p.exponent, 2u);
  EXPECT_EQ(p.position, 2u);
  EXPECT_EQ(p.children[0]->name, "x");
}

TEST(ExpressionTree, PowerBindsTighterThanDivision) {
  const auto e = parse_expression("s^2/1000");
  ASSERT_EQ(e->kind, Kind::product);
  ASSERT_EQ(e->children.size(), 2u);
  EXPECT_EQ(e->children[0]->kind, Kind::power);
  ASSERT_EQ(e->children[1]->kind, Kind::reciprocal);
  EXPECT_EQ(e->children[1]->children[0]->kind, Kind::number);
  EXPECT_EQ(e->children[1]->children[0]->value, Rational(1000));
}

TEST(ExpressionTree, DoubleStarIsCaret) {
  const auto e = parse_expression("x**3");
  ASSERT_EQ(e->kind, Kind::power);
  EXPECT_EQ(e->exponent, 3u);
  EXPECT_EQ(e->position, 1u);
}

TEST(ExpressionTree, NumberBeforeNameIsAProductAndTheNameKeepsItsExponent) {
  const auto e = parse_expression("2x^3");
  ASSERT_EQ(e->kind, Kind::product);
  ASSERT_EQ(e->children.size(), 2u);
  EXPECT_EQ(e->children[0]->value, Rational(2));
  ASSERT_EQ(e->children[1]->kind, Kind::power);
  EXPECT_EQ(e->children[1]->exponent, 3u);
  EXPECT_EQ(e->children[1]->children[0]->name, "x");
}

TEST(ExpressionTree, ExponentLetterIsOnlyScientificWhenADigitFollows) {
  const auto ex = parse_expression("2ex");
  ASSERT_EQ(ex->kind, Kind::product);
  EXPECT_EQ(ex->children[0]->value, Rational(2));
  EXPECT_EQ(ex->children[1]->name, "ex");

  const auto e = parse_expression("2e");
  ASSERT_EQ(e->kind, Kind::product);
  EXPECT_EQ(e->children[1]->name, "e");

  const auto sci = parse_expression("2e3");
  ASSERT_EQ(sci->kind, Kind::number);
  EXPECT_EQ(sci->value, Rational(2000));

  const auto sci_name = parse_expression("2e3x");
  ASSERT_EQ(sci_name->kind, Kind::product);
  EXPECT_EQ(sci_name->children[0]->value, Rational(2000));
  EXPECT_EQ(sci_name->children[1]->name, "x");
}

TEST(ExpressionTree, ExactNumbers) {
  auto value = [](const std::string& text) {
    const auto e = parse_expression(text);
    EXPECT_EQ(e->kind, Kind::number) << text;
    return e->value;
  };
  EXPECT_EQ(value("0.25"), Rational(1, 4));
  EXPECT_EQ(value(".5"), Rational(1, 2));
  EXPECT_EQ(value("1.50"), Rational(3, 2));
  EXPECT_EQ(value("1.5e2"), Rational(150));
  EXPECT_EQ(value("1.5E+2"), Rational(150));
  EXPECT_EQ(value("25e-2"), Rational(1, 4));
  EXPECT_EQ(value("0.0"), Rational(0));
  mpz_class ten30;
  mpz_ui_pow_ui(ten30.get_mpz_t(), 10, 30);
  EXPECT_EQ(value("1e-30"), to_rational(mpq_class(1, ten30)));
  EXPECT_EQ(value("1e30"), to_rational(ten30));
  const std::string big = "123456789012345678901234567890123456789012345678901234567890";
  EXPECT_EQ(value(big), to_rational(mpz_class(big)));
  mpz_class ten39;
  mpz_ui_pow_ui(ten39.get_mpz_t(), 10, 39);
  EXPECT_EQ(value("0." + std::string(38, '0') + "1"), to_rational(mpq_class(1, ten39)));
}

TEST(ExpressionTree, PositionsAreOffsetsOfTheTokens) {
  const auto e = parse_expression("  foo + 3*bar");
  ASSERT_EQ(e->kind, Kind::sum);
  EXPECT_EQ(e->children[0]->position, 2u);
  const auto& product = *e->children[1];
  ASSERT_EQ(product.kind, Kind::product);
  EXPECT_EQ(product.children[0]->position, 8u);
  EXPECT_EQ(product.children[1]->position, 10u);
}

TEST(ExpressionTree, UnaryPlusIsIgnored) {
  const auto e = parse_expression("+x");
  EXPECT_EQ(e->kind, Kind::identifier);
}

TEST(ExpressionTree, WhitespaceIsIgnored) {
  const auto e = parse_expression(" \t x \n * \r y ");
  ASSERT_EQ(e->kind, Kind::product);
  EXPECT_EQ(e->children[1]->name, "y");
}

TEST(CollectIdentifiers, InOrderOfFirstAppearanceWithoutDuplicates) {
  const auto e = parse_expression("t*s^2 + rx - t/(u_1 + s)");
  EXPECT_EQ(collect_identifiers(*e), (std::vector<std::string>{"t", "s", "rx", "u_1"}));
  EXPECT_TRUE(collect_identifiers(*parse_expression("1/2")).empty());
}

TEST(Identifier, FollowsTheContractSyntaxInAscii) {
  EXPECT_TRUE(is_identifier("s"));
  EXPECT_TRUE(is_identifier("_t1"));
  EXPECT_TRUE(is_identifier(std::string(32, 'a')));
  EXPECT_FALSE(is_identifier(std::string(33, 'a')));
  EXPECT_FALSE(is_identifier(""));
  EXPECT_FALSE(is_identifier("1t"));
  EXPECT_FALSE(is_identifier("s-t"));
  EXPECT_FALSE(is_identifier("\xe9t"));
  EXPECT_FALSE(is_identifier("t\xc3\xa9"));
}

TEST(ExpressionTree, CallsHoldTheirNameAndOneArgument) {
  auto e = parse_expression("2cos(2*u+v)^3");
  ASSERT_EQ(e->kind, Kind::product);
  const Expression& power = *e->children[1];
  ASSERT_EQ(power.kind, Kind::power);
  EXPECT_EQ(power.exponent, 3u);
  const Expression& call = *power.children[0];
  ASSERT_EQ(call.kind, Kind::call);
  EXPECT_EQ(call.name, "cos");
  EXPECT_EQ(call.position, 1u);
  ASSERT_EQ(call.children.size(), 1u);
  EXPECT_EQ(call.children[0]->kind, Kind::sum);
  for (const char* f : {"cos", "sin", "tan", "cosh", "sinh", "tanh"}) {
    EXPECT_TRUE(is_function_name(f));
    EXPECT_EQ(parse_expression(std::string(f) + "(u)")->kind, Kind::call);
  }
  // A function's name is not a parameter; a known name without '(' stays an identifier.
  EXPECT_EQ(collect_identifiers(*parse_expression("cos(u)*sinh(v)")), (std::vector<std::string>{"u", "v"}));
  EXPECT_EQ(parse_expression("cos")->kind, Kind::identifier);
}

}  // namespace
}  // namespace implicitizer
