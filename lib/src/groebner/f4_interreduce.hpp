#pragma once
// Private to the groebner module: the reduced basis modulo p of a Gröbner basis, by
// one Macaulay matrix (F4's final step). The rows are the minimal basis's elements
// and, from symbolic preprocessing (macaulay_rows.hpp), one multiple u·g for every
// monomial of a tail that a leading monomial divides; each element's tail is then
// eliminated left to right in a dense accumulator (f4_row_echelon.hpp). Its leading
// term stays: no other element's leading monomial divides it (the basis is minimal),
// and its own divides no monomial of its tail (they are smaller).
//
// Why a matrix: the polynomial interreduction (ModularArithmetic::reduce_basis)
// merges term lists at every step and builds a reducer list per element
// (docs/algorithms.md, "F4 modulo primes", item 8, has what it cost).

#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "mod_polynomial.hpp"

namespace implicitizer::detail {

// What ModularArithmetic::reduce_basis gives (minimal, interreduced, monic, sorted by
// increasing leading monomial), for a Gröbner basis modulo arithmetic.prime().
// Checks `budget` as F4 does.
std::vector<ModPolynomial> reduce_basis_by_matrix(const Ring& ring, const ModularArithmetic& arithmetic,
                                                  std::vector<ModPolynomial> basis, const Budget& budget);

}  // namespace implicitizer::detail
