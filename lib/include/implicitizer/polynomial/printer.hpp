#pragma once
/// \file
/// The contract's output syntax: expanded, decreasing order, explicit `*` and `^`,
/// no spaces, rationals as `3/4*x^2`. Parses back with parser.hpp, Singular,
/// Macaulay2 and SymPy (after `^` → `**`).

#include <string>

#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/polynomial/rational_function.hpp"

namespace implicitizer {

/// Prints `p`; zero prints as `0`.
std::string to_string(const Polynomial& p);

/// Prints `f` as `n` when its denominator is 1, else `(n)/(d)` (a single-term `n`
/// and a constant `d` without parentheses): text that parses back to `f`.
std::string to_string(const RationalFunction& f);

}  // namespace implicitizer
