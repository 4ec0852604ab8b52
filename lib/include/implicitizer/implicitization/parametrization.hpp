#pragma once
/// \file
/// A rational parametrization x = X(params), y = Y(params)[, z = Z(params)] read from
/// the contract's syntax: a surface (or any image) in space, or a plane curve.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/trigonometric_substitution.hpp"
#include "implicitizer/polynomial/rational_function.hpp"

namespace implicitizer {

/// Two or three rational functions in the parameters, each in lowest terms: the
/// coordinates x, y (and z) of the image.
struct Parametrization {
  RingPtr parameter_ring;                     ///< the parameters, grevlex
  std::vector<RationalFunction> coordinates;  ///< x, y and, in space, z
  std::vector<std::string> sources;           ///< the texts they were read from
  /// The parameters of the texts that were replaced to make them rational (empty when
  /// the texts have no function call): `parameter_ring` then names the new parameters
  /// (trigonometric_substitution.hpp).
  std::vector<ParameterSubstitution> substitutions;
};

/// ω = lcm of the coordinates' denominators. It grows as the product of coprime
/// denominators, so its products are checked against `budget`, and a limit names this
/// phase ("the common denominator of the parametrization").
Polynomial common_denominator(const Parametrization& parametrization, const Budget& budget = Budget());

/// ω, ξ_1, …, ξ_n with x_v = ξ_v / ω over one denominator: ω the lcm of the
/// coordinates' denominators q_v, ξ_v = p_v·(ω / q_v). The form the resultant route
/// and the verification work with. Its products are checked against `budget`, and a
/// limit names the phase of common_denominator().
std::vector<Polynomial> common_denominator_form(const Parametrization& parametrization,
                                                const Budget& budget = Budget());

/// The names of the coordinates of a parametrization with `count` (2 or 3)
/// coordinates: x, y and z.
std::vector<std::string> coordinate_names(std::size_t count);

/// Reads x, y, z. Parameters default to every identifier other than x, y, z, in order
/// of first appearance (x's text first); `parameters` names them explicitly.
/// Throws InputError with the field ("x", "y", "z", "parameters") set:
/// parse errors, `parameter_is_space_variable` (x, y or z used as a parameter),
/// `unknown_variable` (an identifier not among explicit parameters),
/// `division_by_zero` (a denominator that is identically zero), and for texts with
/// cos, sin, tan, cosh, sinh, tanh the refusals of substitute_trigonometric(), which
/// makes them rational (then `substitutions` says how).
Parametrization parse_parametrization(const std::string& x, const std::string& y, const std::string& z,
                                      const std::optional<std::vector<std::string>>& parameters = std::nullopt,
                                      const Budget& budget = Budget());

/// The same for two or three coordinate texts (x, y[, z]): two make a plane
/// parametrization, whose implicit equation is a curve f(x, y). Throws
/// std::invalid_argument for another count.
Parametrization parse_parametrization(const std::vector<std::string>& coordinates,
                                      const std::optional<std::vector<std::string>>& parameters = std::nullopt,
                                      const Budget& budget = Budget());

}  // namespace implicitizer
