#pragma once
/// \file
/// The auxiliary resultant of a plane rational curve x = ξ(t)/ω(t), y = η(t)/ω(t):
/// Res_t(ξ − xω, η − yω), the univariate case of Section 1.7.1 of the first seed
/// thesis. Like the surface case it is c·f^l with f the implicit curve and l the
/// degree of the map, and it is computed the same way: the Sylvester matrix is a
/// pencil affine in (x, y), its determinant is interpolated modulo primes.

#include <array>

#include "implicitizer/modular/pencil_determinant.hpp"
#include "implicitizer/resultant/auxiliary_resultant.hpp"

namespace implicitizer {

/// The Sylvester matrix of f = ξ − xω and g = η − yω, both taken with the formal
/// degree n = max(deg ξ, deg η, deg ω), as a pencil in (x, y): rows 0..n−1 hold the
/// shifts t^i·f, rows n..2n−1 the shifts t^i·g, columns the powers t^(2n−1)..t^0.
/// With the same formal degree, a common root at t = ∞ would need ω, ξ and η all
/// of degree below n, so the determinant is the resultant on P¹ and has total
/// degree at most n in (x, y) (the argument of docs/algorithms.md). `wxy` holds
/// ω, ξ, η: integer polynomials in a ring with exactly one variable t, n ≥ 1.
MatrixPencil curve_sylvester_pencil(const std::array<Polynomial, 3>& wxy);

/// Res_t(ξ − xω, η − yω) in `plane` (the ring x, y), from `wxy` = (ω, ξ, η) with
/// rational coefficients in one parameter. Zero when ξ, η and ω have a common
/// root or the image is a point (the caller reports it). The determinant is
/// computed with primes up to its proven coefficient bound: exact by construction.
AuxiliaryResultant curve_auxiliary_resultant(const std::array<Polynomial, 3>& wxy, const RingPtr& plane,
                                             const AuxiliaryResultantParams& options = {});

}  // namespace implicitizer
