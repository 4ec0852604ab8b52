#pragma once
/// \file
/// The decision behind shape `automatic` (sdf_shape.hpp): does the zero set of F
/// inside a box enclose a region that stays away from the box's boundary? Then the
/// surface is drawn as a solid, oriented so that the enclosed region is its inside;
/// otherwise as a sheet (docs/sdf.md, "Shapes").
///
/// The proof, in exact rational arithmetic:
///   1. F has no zero on the boundary of the box B and one strict sign σ there. On
///      each facet (a face of a 3-D box, an edge of a 2-D one) F restricted to the
///      facet is a polynomial in the facet's free coordinates; on a sub-box P of the
///      facet, written in the tensor Bernstein basis of P, it is a convex combination
///      of its Bernstein coefficients (B_J >= 0, Σ B_J = 1), so if every coefficient
///      has the strict sign σ, F has sign σ on all of P. Pieces whose coefficients
///      mix signs are bisected along their longest side, up to a bounded depth and
///      number of pieces. The coefficient at a corner of P is F's value there, so a
///      zero corner, or a corner of the other sign than one seen before, proves that
///      F vanishes on the boundary (it is connected and F continuous): decided, no.
///   2. F takes the sign −σ at some point q inside B. Candidates are found on a grid
///      of B in double (2^k + 1 points per axis, k = 1, 2, …), and each is confirmed
///      by evaluating F exactly at the rational grid point.
/// With both, the open set {σF < 0} ∩ B is nonempty and its closure does not meet
/// ∂B: the solid {σF <= 0} ∩ B has no caps on the box's faces. Its inside is the
/// region the surface encloses, so σ = −1 asks the caller to negate F.
///
/// Fails (answers sheet, saying "undecided") when the surface comes closer to the
/// boundary than the bisection depth resolves, when the subdivision runs past its
/// piece limit, or when the enclosed region is too thin for the grid to hit (between
/// grid points of the finest level). Those answers are honest: a sheet is always a
/// correct picture of the surface, it only loses the inside.

#include <cstddef>
#include <span>
#include <string>
#include <utility>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer {

/// How hard decide_enclosure() tries before answering sheet.
struct EnclosureParams {
  /// Bisections of one facet piece (each halves its longest side).
  std::size_t max_depth = 12;
  /// Pieces examined per facet.
  std::size_t max_pieces = 2048;
  /// The finest interior grid has 2^max_grid_level + 1 points per axis.
  std::size_t max_grid_level = 5;
};

/// What decide_enclosure() found.
struct Enclosure {
  SdfShape shape = SdfShape::sheet;  ///< solid or sheet, never automatic
  /// Solid only: F < 0 on the boundary, so the solid is −F <= 0 (the enclosed region).
  bool negate = false;
  /// Why, in a sentence (e.g. "F vanishes on the boundary at (x, y, z) = (1, 0, 0)").
  std::string reason;
};

/// Decides shape `automatic` for F = 0 in `box`: one closed interval [lo, hi] (lo <
/// hi) per variable, for the first box.size() variables of F's ring (2: a plane curve
/// in x, y; 3: a surface in x, y, z); F must not involve the others. Solid iff steps
/// 1 and 2 of the file comment succeed; sheet otherwise (reason says why). Throws
/// std::invalid_argument on a malformed box, LimitExceeded from `budget`.
Enclosure decide_enclosure(const Polynomial& f, std::span<const std::pair<Rational, Rational>> box,
                           const Budget& budget = Budget(), const EnclosureParams& params = EnclosureParams());

}  // namespace implicitizer
