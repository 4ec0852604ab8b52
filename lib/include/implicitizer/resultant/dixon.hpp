#pragma once
/// \file
/// The Dixon (Cayley–Dixon, Bézout) matrix of the auxiliary system of a
/// tensor-product surface: for x = ξ/ω, y = η/ω, z = ζ/ω with ξ, η, ζ, ω of
/// bidegree at most (m, n) in (s, t), the resultant of
/// ξ − xω, η − yω, ζ − zω on P¹×P¹ is, up to sign, the determinant of a 2mn × 2mn
/// matrix whose entries are affine in x, y, z (Dixon 1908; Chionh and Goldman,
/// "Using multivariate resultants to find the implicit equation of a rational
/// surface", The Visual Computer 8, 1992).

#include <array>
#include <cstdint>

#include "implicitizer/modular/pencil_determinant.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// The Dixon matrix as a pencil in (x, y, z). `wxyz` holds ω, ξ, η, ζ: integer
/// polynomials (content 1 up to sign is not required, only integrality) in a ring
/// with exactly two variables (s, t), of degree at most m in s and n in t, m, n ≥ 1.
///
/// Construction: the Dixon polynomial
///   Δ(s,t,α,β) = det[ P_i(s,t) ; P_i(α,t) ; P_i(α,β) ]_{i=1..3} / ((s−α)(t−β)),
/// P_i = ξ_i − x_i ω, is a bilinear form in the monomials s^i t^j (i < m, j < 2n) and
/// α^k β^l (k < 2m, l < n); its coefficient matrix is the Dixon matrix. Because the
/// determinant is multilinear and two columns equal to ω cancel, Δ = Δ_0 + xΔ_x +
/// yΔ_y + zΔ_z with four determinants free of x, y, z: the entries are affine.
/// Throws std::invalid_argument when the inputs do not fit.
MatrixPencil dixon_pencil(const std::array<Polynomial, 4>& wxyz, std::int32_t m, std::int32_t n);

}  // namespace implicitizer
