#pragma once
/// \file
/// The syntax tree of the input language (contract, "Polynomial and rational-function
/// syntax"). Parsing builds it once; evaluators turn it into a Polynomial (division by
/// constants only) or a RationalFunction, and report errors at the node's position.

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
  enum class Kind { number, identifier, sum, product, negate, reciprocal, power };
  Kind kind = Kind::number;
  Rational value;          ///< for number
  std::string name;        ///< for identifier
  unsigned exponent = 0;   ///< for power (children[0] ^ exponent)
  std::size_t position = 0;  ///< 0-based offset of the token (operator or operand) in the input
  /// Operands (sum, product), or the single operand (negate, reciprocal, power).
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
/// `exponent_too_large`, `chained_exponent`, `nesting_too_deep`, `input_too_long`.
std::unique_ptr<Expression> parse_expression(std::string_view text, const ParseParams& limits = {});

/// The identifiers of `e` in order of first appearance.
std::vector<std::string> collect_identifiers(const Expression& e);

/// The identifiers of all `expressions`, in order of first appearance across them
/// (the default variables of a request that names none).
std::vector<std::string> collect_identifiers(const std::vector<std::unique_ptr<Expression>>& expressions);

/// Whether `name` is an identifier of the contract's syntax: [A-Za-z_][A-Za-z0-9_]*
/// (ASCII, whatever the C locale) of at most `max_length` characters.
bool is_identifier(std::string_view name, std::size_t max_length = ParseParams().max_identifier);

}  // namespace implicitizer
