#pragma once
/// \file
/// Reduced Gröbner bases and the two checks the tests lean on.

#include <cstddef>
#include <span>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// From any Gröbner basis, the reduced one: drop elements whose leading monomial is
/// divisible by another's, reduce every tail by the rest, make monic; sorted by
/// increasing leading monomial. Unique for the ideal and order (CLO Thm 2.7.5). The
/// tails are reduced independently, shared among `threads` threads.
std::vector<Polynomial> reduce_basis(std::span<const Polynomial> groebner_basis, const Budget& budget = Budget(),
                                     std::size_t threads = 1);

/// Whether every S-polynomial of `basis` reduces to zero (Buchberger's criterion).
/// Deliberately uses no pair criterion: it is the slow, obviously right twin of the
/// optimized driver.
bool is_groebner(std::span<const Polynomial> basis, const Budget& budget = Budget());

/// Whether `basis` is reduced: every element monic, no term of any element divisible
/// by the leading monomial of another, no zero element.
bool is_reduced(std::span<const Polynomial> basis);

}  // namespace implicitizer
