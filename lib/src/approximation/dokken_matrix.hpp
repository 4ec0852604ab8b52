#pragma once
// Dokken's matrix for one piece and one degree, its SVD (Eigen) and the equation q
// read from the right singular vector of the smallest singular value.
//
// Basis: the tensor Chebyshev polynomials T_i(u)·T_j(v)·T_k(w), i + j + k <= m, in the
// frame coordinates u = (x − c_x)/h, … of the piece's box (c its centre, h its largest
// half side, so the box lies in [−1, 1]³). They span the polynomials of total degree
// <= m, every one has max-norm 1 on the cube, and they are orthogonal there: the
// columns of the matrix are comparable, and rounding b to doubles moves q by at most
// Σ|δb_j| on the box (unlike monomials of [−1, 1]³, whose change of basis to a
// well-spread set grows like 2^m, and unlike monomials in x, y, z, which depend on
// where the box lies).
//
// Rows: the Bernstein coefficients over the piece S (bidegree m·(d_s, d_t)) of
// ω^m·φ_j(ξ/ω) for each column φ_j, computed in double by products of Bernstein forms
// from the exact Bernstein coefficients of ω and ξ rounded to doubles. For ‖b‖ = 1,
// ‖D·b‖_2 = σ bounds every coefficient, hence max_S |ω^m q(X)| <= σ (the convex-hull
// property); the certificate (certificate.cpp) proves a bound on q itself exactly.

#include <array>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/bernstein.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "patch_evaluator.hpp"
#include "regular_choice.hpp"

namespace implicitizer::approximation {

/// The equation of one (piece, degree).
struct DokkenEquation {
  Polynomial equation;  ///< q in x, y, z, exact, largest |coefficient| 1
  double sigma = 0;     ///< the smallest singular value of the matrix
};

/// How to choose in the near null space (regular_choice.hpp).
struct DokkenChoice {
  double threshold = 0;  ///< singular values up to this count as near null
  PatchSamples samples;  ///< patch points and unit normals in frame coordinates
};

/// `forms`: ω, ξ_x, ξ_y, ξ_z over the parameter ring; `piece`: S; `space`: the ring
/// x, y, z of the equation. Checks `budget` per column.
DokkenEquation dokken_equation(const std::vector<Polynomial>& forms, const BernsteinBox& piece, const Frame& frame,
                               int degree, const DokkenChoice& choice, const RingPtr& space, const Budget& budget);

}  // namespace implicitizer::approximation
