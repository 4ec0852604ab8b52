#pragma once
/// \file
/// The contract's output syntax: expanded, decreasing order, explicit `*` and `^`,
/// no spaces, rationals as `3/4*x^2`. Parses back with parser.hpp, Singular,
/// Macaulay2 and SymPy (after `^` → `**`).

#include <string>

#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// Prints `p`; zero prints as `0`.
std::string to_string(const Polynomial& p);

}  // namespace implicitizer
