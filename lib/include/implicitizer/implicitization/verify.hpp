#pragma once
/// \file
/// Exact verification: substitute the parametrization into the implicit equation.

#include <span>

#include "implicitizer/implicitization/parametrization.hpp"

namespace implicitizer {

/// Whether F(X, Y, Z) = 0 exactly (F(X, Y) = 0 for a plane parametrization: one
/// variable of F per coordinate), for F of degree d and X = ξ/ω,
/// Y = η/ω, Z = ζ/ω over the lcm ω of the denominators: decides whether the
/// polynomial G = ω^d·F(ξ/ω, η/ω, ζ/ω) of the parameters is zero.
///
/// G is not expanded. Its degree in parameter j is at most d·m_j (m_j the largest
/// degree in it among ξ, η, ζ, ω) and its total degree at most d·N (N the largest
/// total degree among them), so its exponents lie in the lower set
/// A = {α : α_j ≤ d·m_j, |α| ≤ d·N}, and G mod p is zero exactly when it vanishes
/// at the points (a_{α_1}, …, a_{α_k}), α ∈ A, for distinct values a_0, a_1, … (a
/// polynomial supported on a lower set is determined by its values there: its
/// Newton form ∏_j ∏_{i<α_j} (t_j − a_i) is triangular on A). That is the whole grid
/// of ∏(d·m_j + 1) points for a tensor-product patch and about half of it for a
/// triangular one; and |coefficients of G| ≤ B = Σ|f_α|·‖ξ‖₁^a·‖η‖₁^b·
/// ‖ζ‖₁^c·‖ω‖₁^(d−a−b−c), so G = 0 exactly when G ≡ 0 modulo primes whose product
/// exceeds 2B. Both facts make the answer a proof, not a probability; a single
/// non-zero value proves G ≠ 0. Grids of more than 4·10⁶ points fall back to
/// substitutes_to_zero_symbolic(). Checks `budget` at every grid line.
bool substitutes_to_zero(const Polynomial& implicit, const Parametrization& parametrization,
                         const Budget& budget = Budget());

/// The same decision for a caller that holds the parametrization's forms already:
/// `forms` are ω, ξ_1, …, ξ_n of common_denominator_form(parametrization) with
/// integer coefficients (scale_to_integers()), as the interpolation route keeps them;
/// recomputing them costs more than the whole check on a small surface.
bool substitutes_to_zero(const Polynomial& implicit, const Parametrization& parametrization,
                         std::span<const Polynomial> forms, const Budget& budget = Budget());

/// The same decision by expanding F(p1/q1, p2/q2, p3/q3)·q1^a·q2^b·q3^c (a, b, c
/// the degrees of F in x, y, z) as a polynomial in the parameters: slower (20 s
/// against a fraction of a second for a degree-18 patch) but independent of the
/// modular argument; the tests compare the two.
bool substitutes_to_zero_symbolic(const Polynomial& implicit, const Parametrization& parametrization,
                                  const Budget& budget = Budget());

}  // namespace implicitizer
