#pragma once
/// \file
/// Exact verification: substitute the parametrization into the implicit equation.

#include "implicitizer/implicitization/parametrization.hpp"

namespace implicitizer {

/// Whether F(X, Y, Z) = 0 exactly, for F in ℚ[x,y,z] and the rational functions
/// X = p1/q1, Y = p2/q2, Z = p3/q3: computes F(p1/q1, p2/q2, p3/q3)·q1^a q2^b q3^c
/// (a, b, c the degrees of F in x, y, z) as a polynomial in the parameters.
bool substitutes_to_zero(const Polynomial& implicit, const Parametrization& parametrization,
                         const Budget& budget = Budget());

}  // namespace implicitizer
