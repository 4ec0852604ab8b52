#pragma once
/// \file
/// Multivariate gcd and exact division, delegated to FLINT's fmpz_mpoly (its
/// Brown/Zippel/Hensel gcd is far better than anything hand-written here).

#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// gcd(a, b) as a primitive integer polynomial with positive leading coefficient;
/// gcd(0, 0) = 0. FLINT's gcd cannot be interrupted; where the variables of one are a
/// proper subset of the other's, the larger is split into its coefficients in the
/// smaller's variables and `budget` is checked between the (smaller) gcds.
Polynomial gcd(const Polynomial& a, const Polynomial& b, const Budget& budget = Budget());
/// lcm(a, b), primitive with positive leading coefficient; 0 if either is 0. Its one
/// product is checked against `budget` (Polynomial::multiply).
Polynomial lcm(const Polynomial& a, const Polynomial& b, const Budget& budget = Budget());
/// The square-free part of `a` with respect to its variable `var`: a / gcd(a, ∂a/∂var),
/// primitive with positive leading coefficient. When a = c·f^l with f irreducible and
/// involving var, this is f (Theorem 1.13 of the seed thesis: f ∤ ∂f/∂var because the
/// derivative has smaller degree in var).
Polynomial square_free_part(const Polynomial& a, std::size_t var);

/// a / b when b divides a exactly (over ℚ); throws std::logic_error otherwise. Where
/// b's variables are a proper subset of a's, a is divided coefficient by coefficient
/// (as gcd()) with `budget` checked between.
Polynomial divide_exact(const Polynomial& a, const Polynomial& b, const Budget& budget = Budget());

}  // namespace implicitizer
