#pragma once
/// \file
/// The syntax tree of the input language (contract, "Polynomial and rational-function
/// syntax"). Parsing builds it once; evaluators turn it into a Polynomial (division by
/// constants only) or a RationalFunction, and report errors at the node's position.
/// Function calls (`cos(u)`) are part of the syntax so that they can be named in
/// errors and converted by trigonometric_substitution.hpp; the evaluators refuse them.

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "implicitizer/core/rational.hpp"

namespace implicitizer {

/// One node of an expression tree. Sums and products are n-ary (a chain
/// `a-b+c` is one `sum` node whose middle child is a `negate`, `a/b*c` one `product`
/// with a `reciprocal` child), so the tree's depth is bounded by the nesting of
/// parentheses and unary operators, never by the length of the input.
struct Expression {
  enum class Kind { number, identifier, sum, product, negate, reciprocal, power, call };
  Kind kind = Kind::number;
  Rational value;            ///< for number
  std::string name;          ///< for identifier, and the function's name for call
  unsigned exponent = 0;     ///< for power (children[0] ^ exponent)
  std::size_t position = 0;  ///< 0-based offset of the token (operator, operand, function name) in the input
  /// Operands (sum, product), or the single operand (negate, reciprocal, power), or the
  /// single argument (call).
  std::vector<std::unique_ptr<Expression>> children;
};

/// Limits of the parser; defaults are the contract's.
struct ParseParams {
  unsigned max_exponent = 1000;      ///< largest exponent literal
  std::size_t max_depth = 256;       ///< deepest nesting of parentheses and operators
  std::size_t max_identifier = 32;   ///< longest identifier
  std::size_t max_length = 1 << 20;  ///< longest input in bytes
};

/// Parses `text`. Throws InputError with a stable code and position:
/// `empty_input`, `unexpected_character`, `unexpected_token`, `unexpected_end`,
/// `missing_parenthesis`, `identifier_too_long`, `exponent_not_integer`,
/// `exponent_too_large`, `chained_exponent`, `nesting_too_deep`, `input_too_long`,
/// and for a name followed by `(`: `unknown_function` (not one of
/// is_function_name()'s), `function_not_rational` (sqrt, exp, log, ln: no exact
/// rational form exists), both at the name with the name in the message.
std::unique_ptr<Expression> parse_expression(std::string_view text, const ParseParams& limits = {});

/// The identifiers of `e` in order of first appearance.
std::vector<std::string> collect_identifiers(const Expression& e);

/// The identifiers of all `expressions`, in order of first appearance across them
/// (the default variables of a request that names none).
std::vector<std::string> collect_identifiers(const std::vector<std::unique_ptr<Expression>>& expressions);

/// Whether `name` is a function the parser accepts in a call: cos, sin, tan, cosh,
/// sinh, tanh (the functions trigonometric_substitution.hpp makes rational).
bool is_function_name(std::string_view name);

/// Whether `name` is an identifier of the contract's syntax: [A-Za-z_][A-Za-z0-9_]*
/// (ASCII, whatever the C locale) of at most `max_length` characters.
bool is_identifier(std::string_view name, std::size_t max_length = ParseParams().max_identifier);

}  // namespace implicitizer
