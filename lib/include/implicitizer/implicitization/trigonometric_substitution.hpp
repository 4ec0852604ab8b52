#pragma once
/// \file
/// Trigonometric and hyperbolic parametrizations made rational, exactly.
///
/// The substitution. A parameter θ that appears only inside cos, sin, tan (as an
/// integer combination k_1·θ_1 + … + k_m·θ_m of such parameters) is replaced by
/// t = tan(θ/2), for which cos θ = (1 − t²)/(1 + t²) and sin θ = 2t/(1 + t²), that is
/// cos θ + i·sin θ = (1 + i·t)²/(1 + t²). Then
///   cos(Σ k_j θ_j) + i·sin(Σ k_j θ_j) = Π_j (1 ± i·t_j)^(2|k_j|) / (1 + t_j²)^|k_j|
/// (de Moivre; the sign is that of k_j), so the real and imaginary parts are the
/// Chebyshev and addition formulas in one product, exact over ℚ, and tan = sin/cos.
/// A parameter θ that appears only inside cosh, sinh, tanh is replaced by e = exp(θ):
/// with E = Π_j e_j^(k_j), cosh = (E + 1/E)/2, sinh = (E − 1/E)/2, tanh = (E² − 1)/(E² + 1).
/// Parameters outside every function are kept.
///
/// Why the implicit equation is the same. θ ↦ tan(θ/2) maps (−π, π) onto ℝ and
/// θ ↦ exp(θ) maps ℝ onto (0, ∞); both are bijections onto open dense parts of the
/// rational parameter space, so the image of the converted parametrization is the image
/// of the original with at most the curves θ = π removed (t = ∞), and the two images have
/// the same Zariski closure, hence the same implicit equation. The points at θ = π are
/// the limits t → ±∞ of the rational form.
///
/// What is refused (InputError, with the field, the position of the call and the
/// function's name in the message): `parameter_inside_and_outside` (u·cos(u): not
/// rational in any substitution), `mixed_function_kinds` (one parameter inside both a
/// trigonometric and a hyperbolic function), `nonlinear_argument` (cos(s·t), cos(u²),
/// cos(cos(u))), `non_integer_argument` (cos(u/2), cos(u + 1): their values at rational
/// t are not rational functions of t), `multiple_too_large` (a multiple above 1000).
/// sqrt, exp, log and unknown names are refused by the parser (expression.hpp).

#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/expression.hpp"
#include "implicitizer/polynomial/rational_function.hpp"

namespace implicitizer {

// patch_bounds.hpp, which includes this header through parametrization.hpp.
struct ParameterDomain;

/// How one parameter of the input was replaced by a rational one.
struct ParameterSubstitution {
  enum class Kind {
    half_angle,   ///< variable = tan(parameter/2): parameter in (−π, π) ↔ variable in ℝ
    exponential,  ///< variable = exp(parameter): parameter in ℝ ↔ variable in (0, ∞)
  };
  Kind kind = Kind::half_angle;
  std::string parameter;  ///< θ as the input names it
  std::string variable;   ///< the rational parameter that replaces it
};

/// "half_angle" or "exponential".
const char* to_string(ParameterSubstitution::Kind kind);

/// The substitution as a formula: "tu = tan(u/2)" or "eu = exp(u)".
std::string to_string(const ParameterSubstitution& substitution);

/// A parametrization after the substitution: the rational parameters (the input's, in
/// the input's order, each replaced one renamed) and the coordinates in them.
struct RationalizedCoordinates {
  RingPtr parameter_ring;                            ///< grevlex, like parse_parametrization's
  std::vector<RationalFunction> coordinates;         ///< one per input coordinate, lowest terms
  std::vector<ParameterSubstitution> substitutions;  ///< the replaced parameters, in ring order
};

/// Whether `e` contains a function call.
bool contains_call(const Expression& e);

/// Converts the coordinate trees `coordinates` (field names `fields`, e.g. "x", "y",
/// "z") over the parameters of `parameters` into rational functions by the file
/// comment's substitution. The new variable of θ is `tθ` (half angle) or `eθ`
/// (exponential: `eu` for u), with 1, 2, … appended while that name is taken. Throws InputError (the
/// file comment's codes, and the evaluator's `unknown_variable`, `division_by_zero`)
/// with the field set; LimitExceeded from `budget`.
RationalizedCoordinates substitute_trigonometric(const std::vector<const Expression*>& coordinates,
                                                 const std::vector<std::string>& fields, const RingPtr& parameters,
                                                 const Budget& budget = Budget());

/// `domain` (one interval per parameter, in the input's parameters: angles for a half
/// angle) mapped through `substitutions` onto the parameters of `rational_parameters`:
/// θ in [lo, hi] becomes t in [tan(lo/2), tan(hi/2)] (θ ↦ tan(θ/2) increases on
/// (−π, π)) or e in [exp(lo), exp(hi)]; other parameters keep their interval. The new
/// ends are the doubles nearest the true ones (tan and exp of a non-zero rational are
/// irrational), so the patch drawn is within one rounding of the one asked for. An
/// angle interval must lie strictly inside (−π, π): θ = ±π is t = ∞, which no finite
/// box holds (the whole circle is the default domain, the whole plane of t). Throws
/// InputError `domain_out_of_range` (field "domain") otherwise, or when exp overflows.
ParameterDomain map_parameter_domain(const std::vector<ParameterSubstitution>& substitutions,
                                     const Ring& rational_parameters, const ParameterDomain& domain);

}  // namespace implicitizer
