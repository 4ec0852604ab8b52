#pragma once
/// \file
/// Implicitization by interpolation on a predicted support (implicit_support.hpp)
/// instead of every monomial of degree ≤ the dense bound: for x = s^7 + t, y = t^7 + s,
/// z = s·t^3 (degree 49) 48 kernels of about 180 columns instead of one of 22,100.
///
/// Why the answer is the implicit equation. Let G be the implicit equation (primitive,
/// irreducible: V is a surface, check_image_dimension), B the box and C_1, …, C_m its
/// classes. G lies in B (fact 1 of implicit_support.hpp) and in one class (fact 2).
///   1. A class whose kernel modulo some prime p is zero holds no integer polynomial
///      vanishing on V: such a polynomial, primitive, is non-zero modulo p and vanishes
///      at the image points modulo p, so it lies in that kernel. Hence G lies in the
///      one class C left (every other had a zero kernel at some prime).
///   2. At a prime p where C's kernel is one-dimensional, G mod p spans it. The
///      candidate F, in C by construction and vanishing on V exactly
///      (substitutes_to_zero), has F mod p in the kernel, so F ≡ λ·G (mod p), λ ≠ 0
///      (F is primitive). G divides F over ℤ (Gauss), F = G·H, and when p does not
///      divide F's leading coefficients (deg (F mod p) = deg F), deg H = 0: F is G
///      up to a constant.
/// The check's size is that of the classes, not of the dense degree bound. A box too
/// loose (a map of degree > 1 lets multiples of G fit) leaves a kernel of dimension > 1
/// or several non-zero classes at every prime tried: the route then answers nullopt,
/// and the caller falls back to another route. A wrong prediction (impossible by the
/// two facts, but cheap to survive) also leaves no class or no verified candidate.

#include <cstddef>
#include <optional>

#include "implicitizer/implicitization/implicit_support.hpp"
#include "implicitizer/implicitization/interpolation.hpp"

namespace implicitizer {

/// How many primes a class with a non-zero kernel gets before the prediction is given
/// up: a prime is unlucky (kernel too large) with probability about columns/p, so a
/// second one almost always settles a class that is empty over ℚ.
inline constexpr std::size_t kSparseScanPrimes = 3;

/// The routes that try the predicted support before another answer (auto's rule 3b, and
/// interpolation where the dense matrix is too large) take it only when its kernels add
/// up to at most this many cubed columns: about a second of row reductions per prime,
/// so that a prediction that falls back (a map of degree > 1) costs little.
inline constexpr double kSparseMaxCubedColumns = 2e9;

/// The implicit equation of a surface in two parameters by interpolation on
/// `support` (predict_implicit_support(parametrization)), proven as the header says;
/// `options` as for implicitize_by_interpolation() (budget, primes, seed, max_columns
/// against the largest class, max_primes, tamper_candidate). nullopt when the
/// prediction does not single out one class with a one-dimensional kernel, or no
/// candidate verifies within max_primes primes: the caller falls back. Throws
/// NoSingleEquation when the image is not a surface, LimitExceeded (size: a class
/// larger than max_columns; time, cancelled), std::invalid_argument unless there are
/// three coordinates and two parameters. In the stats, degree_bound is the box's total
/// degree, degree_probes the kernels of the scan over the classes, search_ms its time,
/// columns the class of the answer.
std::optional<InterpolationResult> implicitize_by_sparse_interpolation(const Parametrization& parametrization,
                                                                       const ImplicitSupport& support,
                                                                       const InterpolationParams& options = {});

/// The minimality half of check_implicit_equation() on a predicted support: whether
/// `candidate` (primitive, vanishing on the image, which is a surface) is the implicit
/// equation by the header's argument, with the kernels of `support`'s classes modulo
/// options.primes. False when the argument does not go through (a candidate outside
/// the box or the class left, or a box too loose), which may be unlucky.
bool is_minimal_on_support(const Polynomial& candidate, const Parametrization& parametrization,
                           const ImplicitSupport& support, const InterpolationParams& options = {});

}  // namespace implicitizer
