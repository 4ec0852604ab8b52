#pragma once
/// \file
/// The Sylvester matrix of two polynomials in one variable whose coefficients are
/// polynomials in the others, and its determinant by Bareiss' fraction-free
/// elimination. det Syl(f, g) is the resultant by definition; computing it this way
/// costs O((m+n)³) multiplications and exact divisions of ever larger polynomials,
/// so the library's resultant() uses the subresultant PRS (subresultant.hpp) and
/// this file is the slow, obviously correct twin the tests compare it with.

#include <cstddef>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/resultant/polynomial_matrix.hpp"

namespace implicitizer {

/// The coefficients c_0, …, c_d of f = Σ c_i·x^i as a polynomial in x = variable
/// `var` (d = f.degree_in(var)): polynomials of f's ring that do not involve `var`.
/// Returns d + 1 entries (inner ones may be zero, c_d never is); none for f = 0.
/// Throws std::invalid_argument when `var` is not a variable of the ring.
std::vector<Polynomial> coefficients_in(const Polynomial& f, std::size_t var);

/// The Sylvester matrix of f and g with respect to variable `var`: for
/// f = Σ_{i≤m} f_i x^i and g = Σ_{j≤n} g_j x^j (m, n their degrees in x), the
/// (m+n) × (m+n) matrix whose row r < n holds f_m, …, f_0 starting in column r and
/// whose row n + r (r < m) holds g_n, …, g_0 starting in column r. Its determinant
/// is Res(f, g) = lc(f)^n·∏ g(α) over the roots α of f, the convention of Singular,
/// Macaulay2 and FLINT; m = 0 gives f_0^n, and m = n = 0 the empty matrix
/// (determinant 1). Entries are in f's ring and do not involve `var`.
/// Throws std::invalid_argument when f or g is zero (its degree, hence the shape,
/// is not defined), when the rings differ, or when `var` is not a variable.
PolynomialMatrix sylvester_matrix(const Polynomial& f, const Polynomial& g, std::size_t var);

/// The determinant of a square matrix by Bareiss' fraction-free elimination:
/// a^(k)_ij = (a^(k-1)_kk·a^(k-1)_ij − a^(k-1)_ik·a^(k-1)_kj) / a^(k-2)_(k-1)(k-1),
/// where the division is exact because every a^(k)_ij is a (k+1)-minor of the input
/// (Sylvester's identity), so entries never grow beyond the minors' size. A zero
/// pivot is exchanged with a later row of the same column (changing the sign); a
/// column with no non-zero pivot makes the determinant 0. The empty matrix has
/// determinant 1. Checks `budget` at every entry (time, terms of each product).
/// Throws std::invalid_argument when the matrix is not square, LimitExceeded from
/// the budget.
Polynomial determinant_bareiss(const PolynomialMatrix& matrix, const Budget& budget = Budget());

}  // namespace implicitizer
