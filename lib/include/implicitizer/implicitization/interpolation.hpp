#pragma once
/// \file
/// Implicitization by interpolation: the implicit equation is the kernel of the
/// matrix of monomials of degree ≤ d evaluated at points of the image, computed
/// modulo word-size primes and lifted by Chinese remaindering and rational
/// reconstruction, then verified by exact substitution. Needs no resultant, so base
/// points (which make the auxiliary resultant vanish) only lower the degree.
///
/// Why the answer is the implicit equation. Let V be the closure of the image in
/// ℚⁿ (n = 2 or 3 coordinates) and F ≠ 0 the candidate, of degree e, primitive.
///   1. F vanishes on V: substitutes_to_zero() decides ω^e·F(ξ/ω) = 0 exactly.
///   2. No non-zero polynomial of degree < e vanishes on V. Modulo a prime p, at
///      parameter points a with ω(a) ≢ 0, the matrix of the monomials of degree ≤ e
///      at the points ξ(a)/ω(a) had a one-dimensional kernel spanned by a vector of
///      degree exactly e. A primitive integer G of degree < e vanishing on V has
///      ω^deg G·G(ξ/ω) = 0 in ℤ[params], so G mod p (not zero: G is primitive)
///      vanishes at those points and lies in that kernel, which has no non-zero
///      vector of degree < e: there is no such G.
///   3. V is a hypersurface: the Jacobian of the map has rank n − 1 at some point
///      modulo p (so over ℚ: a minor that is non-zero mod p is non-zero), so
///      dim V ≥ n − 1, and F ≠ 0 vanishes on V, so dim V ≤ n − 1.
/// By 3 the ideal of V is (G) with G irreducible; G divides F by 1 and has degree
/// ≥ e by 2, so F is G up to a constant. Every prime used has property 2; the
/// substitution of 1 is the only expensive check, and a candidate that fails it is
/// never returned: more primes are taken instead.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/modular/prime_sequence.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// How implicitize_by_interpolation() works and when it stops.
struct InterpolationParams {
  /// Time, cancellation and the term limit (against the number of columns), checked
  /// at every evaluation row and between primes. One modular row reduction cannot be
  /// interrupted (FLINT's nmod_mat_rref): a deadline may be overrun by one of them,
  /// about 1.3 s for the 1338×1330 matrix of degree 18.
  Budget budget;
  /// The primes of the kernels (tests force small ones to make unlucky primes happen).
  PrimeSequence primes{};
  /// Seeds the evaluation points (reproducible runs).
  std::uint64_t seed = 0x1a7e4b01;
  /// Threads for independent primes; 0 means one per core (at most 4) when a kernel
  /// has at least kParallelColumns columns, else one.
  unsigned threads = 0;
  /// The largest matrix, in columns (monomials); a degree needing more throws
  /// LimitExceeded (size). 3000 columns is degree 24 in space: 72 MB per thread and,
  /// by the cube of the columns, about 15 s per prime.
  std::size_t max_columns = 3000;
  /// More primes than this (lucky or not) throws LimitExceeded (size).
  std::size_t max_primes = 1000;
  /// For tests: called on each candidate before its verification, so that a test can
  /// corrupt one and see it rejected. Empty in every other use.
  std::function<void(Polynomial&)> tamper_candidate;
};

/// Kernels with at least this many columns (degree 7 in space) run a prime per
/// thread: below it a prime takes a millisecond or two, which a new thread can spend
/// waiting for the scheduler (bicubic_graph, 84 columns: 1.4 ms alone, 2.5 ms on two
/// threads; tp_22, 165 columns and two primes: 13.5 ms alone, 9.9 ms on two).
inline constexpr std::size_t kParallelColumns = 120;

/// What implicitize_by_interpolation() did.
struct InterpolationStats {
  std::int32_t degree_bound = 0;        ///< the bound of implicit_degree_bound()
  std::int32_t degree = 0;              ///< the degree found (that of the answer)
  std::size_t rows = 0;                 ///< evaluation points of the final matrix
  std::size_t columns = 0;              ///< monomials of degree ≤ degree
  std::size_t primes = 0;               ///< images combined into the answer
  std::size_t unlucky_primes = 0;       ///< primes dropped (kernel too large, leading term lost, no points)
  std::size_t degree_probes = 0;        ///< kernels computed while searching the degree
  std::size_t rejected_points = 0;      ///< parameter points where ω vanished modulo the prime
  std::size_t rejected_candidates = 0;  ///< reconstructions that failed the verification
  std::size_t modulus_bits = 0;         ///< bits of the product of the primes combined
  unsigned threads = 1;                 ///< threads of the largest batch
  double search_ms = 0;                 ///< the Jacobian rank and the degree search
  double images_ms = 0;                 ///< kernels at the degree found (wall time)
  double reconstruction_ms = 0;         ///< Chinese remaindering and rational reconstruction
  double verify_ms = 0;                 ///< exact substitution of the candidates
};

/// The answer and how it was found.
struct InterpolationResult {
  Polynomial implicit;  ///< primitive, positive leading coefficient, in implicit_ring(n), verified
  InterpolationStats stats;
};

/// A proven bound on the degree of the implicit equation of a parametrization with
/// k parameters and n = 2 or 3 coordinates, from its common_denominator_form
/// (ω, ξ_1, …, ξ_n), whenever its image is a hypersurface. The image's degree is the
/// number of its points on a general line, each the image of an isolated common zero
/// of n − 1 general combinations Σ a_i·ξ_i − a_0·ω (a general line misses the images
/// of the common zeros of ω and the ξ_i and of contracted curves). Hence, with N the
/// largest total degree among them:
///   - k = n − 1: at most N^(n−1) such zeros (Bézout on P^(n−1), Fulton's refined
///     form: the isolated points of an intersection of hypersurfaces of degrees N
///     number at most N^(n−1));
///   - k = 2, n = 3, also at most 2·m1·m2 (m_j the largest degree in parameter j):
///     two curves of bidegree (m1, m2) on P¹×P¹ meet in 2·m1·m2 points (their
///     intersection number; Bernstein's bound for the rectangle);
///   - k > n − 1: restricted to a general affine (n−1)-plane of parameters the map
///     still covers the image (its general fibre, of dimension k − n + 1, meets a
///     general plane of that codimension) and the total degree does not grow: N^(n−1).
/// The bound is that of the resultant route (2mn, n², n); base points and a map of
/// degree l > 1 make the true degree smaller (degree·l ≤ the bound). Returns 0 for
/// k < n − 1, where the image cannot be a hypersurface. The common denominator it
/// reads is checked against `budget` (common_denominator_form()).
std::int32_t implicit_degree_bound(const Parametrization& parametrization, const Budget& budget = Budget());

/// The implicit equation of the image by interpolation, as the header describes:
///   1. the Jacobian's rank at a random point modulo a prime (and, when it is below
///      n − 1 there, its minors expanded exactly) decides that the image has
///      dimension n − 1, or fills space (NoSingleEquation, no generators), or is
///      smaller (NoSingleEquation; this route does not compute the generators of the
///      ideal, method groebner lists them);
///   2. the degree e is searched from below while a kernel costs at most an eighth of
///      the one at the bound D (its matrix has at most half the columns), else read
///      from the kernel at D, of dimension C(D − e + n, n): the multiples of F of
///      degree ≤ D. A zero kernel at degree d proves e > d; a kernel modulo p only
///      ever contains the true one, so a larger one only underestimates e;
///   3. primes, one per thread when the matrix has kParallelColumns columns or more,
///      give kernels at degree e; one of dimension > 1, or whose leading monomial
///      (grevlex, x > y > z) is smaller than another prime's (p divides F's leading
///      coefficient), is dropped as unlucky;
///   4. each kernel vector, scaled to leading coefficient 1, is combined by Chinese
///      remaindering; each coefficient is reconstructed as a rational number (with 20
///      bits to spare) and checked against every later prime; as soon as every
///      coefficient has a value, the candidate (denominators cleared, primitive) is
///      verified by substitutes_to_zero(); a rejected one waits for a prime that
///      changes it.
/// Returns the primitive equation with positive leading coefficient in
/// implicit_ring(n), verified. Throws NoSingleEquation as above, LimitExceeded
/// (time, cancelled, or size: the matrix would exceed max_columns, or max_primes
/// primes did not suffice), std::invalid_argument unless there are 2 or 3 coordinates.
InterpolationResult implicitize_by_interpolation(const Parametrization& parametrization,
                                                 const InterpolationParams& options = {});

/// The same route limited to degrees ≤ `max_degree`: the equation when its degree
/// is at most that (the answer of implicitize_by_interpolation()), nullopt when a
/// zero kernel proved that no non-zero polynomial of degree ≤ max_degree vanishes on
/// the image. Costs the kernels of at most C(max_degree + n, n) columns whatever the
/// degree bound, so that `auto` can try it first: with max_degree 4 (35 columns) it
/// answers the torus in 0.6 ms and gives up on a surface of degree 9 in about 0.2 ms
/// (docs/algorithms.md). With max_degree ≥ the degree bound it is the whole route and
/// throws as it does.
std::optional<InterpolationResult> implicitize_by_interpolation_up_to(const Parametrization& parametrization,
                                                                      std::int32_t max_degree,
                                                                      const InterpolationParams& options = {});

/// The two checks of the header for any candidate F, each independent of how F was
/// found: the slow twin of the route's bookkeeping, for tests and for equations
/// obtained elsewhere.
struct ImplicitEquationCheck {
  bool vanishes = false;  ///< F(ξ/ω) = 0 exactly (substitutes_to_zero)
  /// Modulo one prime of options.primes: the kernel of the monomials of degree ≤ deg F
  /// at the points of the image is spanned by F mod p, and the Jacobian has rank n − 1
  /// there (a hypersurface). False for a wrong F, a multiple of the equation, or an
  /// unlucky prime; true for the equation modulo all but finitely many primes.
  bool minimal = false;
};

/// Checks `candidate` (in implicit_ring(n)) against `parametrization`, with the
/// points, budget and primes of `options` (the next prime of the sequence). Where the
/// monomials of degree ≤ deg F would exceed options.max_columns, a surface in two
/// parameters is checked on the classes of its predicted support instead
/// (is_minimal_on_support(), sparse_interpolation.hpp), whose size follows the
/// equation's sparsity; LimitExceeded (size) when those too exceed it.
ImplicitEquationCheck check_implicit_equation(const Polynomial& candidate, const Parametrization& parametrization,
                                              const InterpolationParams& options = {});

}  // namespace implicitizer
