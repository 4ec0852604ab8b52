#pragma once
// The certified half of the two-sided bound: every point of X(S) lies within a proven
// distance of {q = 0}, in exact rational arithmetic (docs/sdf.md, "Approximate
// implicitization", has the proof).
//
// On a sub-piece P of S (Bernstein coefficients over P, exact):
//   1. e = max_J |N_J / W_J| with N = ω^m·q(ξ/ω) and W = ω^m (W's coefficients all of
//      one sign): |q(X(p))| <= e on P, the convex-hull property (ω = 1: W = 1).
//   2. B = the Bernstein hull of X(P) (ratios ξ_J/ω_J, ω's coefficients one-signed),
//      widened by δ = the target distance and rounded outwards to doubles.
//   3. n = ∇q(X(centre of P)) scaled so that max |n_i| = 1, rounded to multiples of
//      2^-16 (a dyadic vector, exact), ν >= |n| a rational upper bound.
//   4. g = min of the Bernstein coefficients over B of ∇q·n (a trivariate polynomial).
// If g > 0 and e·ν <= g·δ, for every p in X(P) the function λ ↦ q(p + λn) has slope
// >= g while p + λn stays in B (|λ| <= δ, as |n_i| <= 1), so it has a zero at some
// |λ| <= |q(p)|/g <= e/g: a point of {q = 0} within e·ν/g <= δ of p. Otherwise P is
// bisected (longer parameter side) up to `max_depth` times.

#include <cstddef>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/bernstein.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer::approximation {

/// The outcome of certify_patch_to_surface().
struct Certificate {
  bool proven = false;     ///< every sub-piece met the test of the file comment
  double bound = 0;        ///< when proven: max over sub-pieces of e·ν/g, rounded up (absolute)
  std::size_t pieces = 0;  ///< sub-pieces the proof used
};

/// Proves max_{p ∈ X(piece)} dist(p, {q = 0}) <= target, or says it could not.
/// `forms`: ω, ξ_x, ξ_y, ξ_z over the parameter ring; q in x, y, z.
Certificate certify_patch_to_surface(const Polynomial& q, const std::vector<Polynomial>& forms,
                                     const BernsteinBox& piece, double target, std::size_t max_depth,
                                     const Budget& budget);

}  // namespace implicitizer::approximation
