#pragma once
// Which vector of Dokken's near null space to keep. Above the degree a piece needs,
// the matrix has several tiny singular values: if q approximates X(S), so does q·r for
// any r of the remaining degree, and the smallest singular vector mixes such products
// in. Their extra sheets r = 0 pass anywhere, often through the part of space the
// trimming keeps (measured: tri_quartic pieces whose degree-6 equation has
// σ ≈ 1e-13 and a first-order error ≈ 1e-9 of the diagonal, yet a sheet 0.16 away).
//
// Among b = V·c, V the right singular vectors whose σ is at most `threshold` (at
// least the smallest), the choice is the least-squares fit of q to a signed distance
// in the tube the trimming keeps: q(P_k + λ·ν_k) ≈ λ for patch samples P_k with unit
// normals ν_k and λ ∈ {±0.05, ±0.1} (frame units, 0.1 = 0.1·h), q(P_k) ≈ 0 weighted
// ten times. A product q·r whose extra sheet r = 0 crosses the tube cannot fit it, so
// a combination without such a sheet is preferred when the space holds one; the gates
// of the driver still measure and certify whatever comes out.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "patch_evaluator.hpp"

namespace implicitizer::approximation {

/// The exponent triples (i, j, k), i + j + k <= m, of the tensor Chebyshev basis in
/// the order of the matrix's columns.
std::vector<std::array<int, 3>> basis_indices(int m);

/// Patch samples in frame coordinates with unit normals.
struct PatchSamples {
  std::vector<Point> points, normals;
};

/// See the file comment; `singular_values` ascending with V's columns in the same
/// order.
Eigen::VectorXd regular_combination(const Eigen::MatrixXd& v, const Eigen::VectorXd& singular_values, double threshold,
                                    int degree, const PatchSamples& samples);

}  // namespace implicitizer::approximation
