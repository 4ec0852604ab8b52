#pragma once
/// \file
/// Macaulay's matrix of the auxiliary system of a triangular (total-degree) surface:
/// for x = ξ/ω, y = η/ω, z = ζ/ω with ξ, η, ζ, ω of total degree at most n in (s, t),
/// homogenized with r, the resultant of the three ternary forms f_1 = ξ − xω,
/// f_2 = η − yω, f_3 = ζ − zω of degree n is det M / det E (Macaulay, "On some
/// formulae in elimination", Proc. London Math. Soc. 35, 1902; Cox, Little and
/// O'Shea, Using Algebraic Geometry, 2nd ed., Ch. 3 §4, Theorem 4.9).

#include <array>
#include <cstdint>
#include <vector>

#include "implicitizer/modular/pencil_determinant.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// Macaulay's matrix and the rows/columns of its extraneous factor.
struct MacaulayPencil {
  MatrixPencil matrix;                   ///< M, affine in (x, y, z)
  std::vector<std::size_t> extraneous;   ///< E = M restricted to these rows and columns
};

/// M is indexed (rows and columns alike) by the monomials r^a s^b t^c of degree
/// d = 3n − 2. The row of a monomial μ holds the coefficients of (μ / r^n)·f_1 if r^n
/// divides μ, else of (μ / s^n)·f_2 if s^n divides μ, else of (μ / t^n)·f_3 (every μ
/// of degree 3n − 2 is divisible by one of them). The extraneous factor E keeps the
/// rows and columns of the monomials divisible by at least two of r^n, s^n, t^n.
/// `wxyz` holds ω, ξ, η, ζ: integer polynomials in a ring with exactly two
/// variables (s, t), of total degree at most n ≥ 1.
MacaulayPencil macaulay_pencil(const std::array<Polynomial, 4>& wxyz, std::int32_t n);

}  // namespace implicitizer
