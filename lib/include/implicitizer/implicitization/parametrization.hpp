#pragma once
/// \file
/// A rational parametrization x = X(params), y = Y(params), z = Z(params) read from
/// the contract's syntax.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/rational_function.hpp"

namespace implicitizer {

/// Three rational functions in the parameters, each in lowest terms.
struct Parametrization {
  RingPtr parameter_ring;                        ///< the parameters, grevlex
  std::array<RationalFunction, 3> coordinates;   ///< x, y, z
  std::array<std::string, 3> sources;            ///< the texts they were read from
};

/// Reads x, y, z. Parameters default to every identifier other than x, y, z, in order
/// of first appearance (x's text first); `parameters` names them explicitly.
/// Throws InputError with the field ("x", "y", "z", "parameters") set:
/// parse errors, `parameter_is_space_variable` (x, y or z used as a parameter),
/// `unknown_variable` (an identifier not among explicit parameters),
/// `division_by_zero` (a denominator that is identically zero).
Parametrization parse_parametrization(const std::string& x, const std::string& y, const std::string& z,
                                      const std::optional<std::vector<std::string>>& parameters = std::nullopt,
                                      const Budget& budget = Budget());

}  // namespace implicitizer
