#pragma once
/// \file
/// A convex polytope that provably holds a sub-patch X(S): what an approximated piece
/// q_k = 0 can be trimmed to in a handful of plane tests, instead of a box cover of
/// dozens of boxes (docs/sdf.md, "Trimming a piece to a polytope").
///
/// Ten planes n_i·x <= c_i: ±ν, ν the unit normal of X at S's centre, and per edge of
/// S two planes, through the chords of X along the edge's two halves, that contain ν,
/// facing away from the centre (two chords follow a curved edge four times closer than
/// one).
/// The directions are chosen in double; each offset c_i is then the exact maximum
/// bound of n_i·X over S (bound_patch() of the patch with coordinates n_i·X, the n_i
/// read as exact rationals), rounded up: X(S) lies in the polytope whatever the
/// directions' rounding. Around a nearly flat piece the polytope is a thin slab whose
/// sides stand across the surface at S's edges, so q's continuation past an edge
/// leaves it at once; the approximation measures what it keeps (surface_distance.hpp).

#include <array>
#include <optional>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"

namespace implicitizer {

/// {x : n_i·x <= c_i for every i}.
struct TrimPolytope {
  std::vector<std::array<double, 3>> normals;  ///< unit up to double rounding
  std::vector<double> offsets;                 ///< c_i, at least the exact maximum of n_i·x over X(S)

  /// max_i (n_i·x − c_i): <= 0 on X(S) (up to this double arithmetic's rounding), and
  /// outside the polytope at most the distance to it (the n_i are unit).
  double excess(const std::array<double, 3>& x) const;
};

/// The polytope of the file comment for X(`piece`) (a surface: three coordinates, two
/// parameters; no denominator vanishes on `piece`); none where the normal at the
/// centre or an edge's chord degenerates (a singular point, a collapsed edge). Throws
/// InputError `unbounded_patch` as bound_patch() does, LimitExceeded from `budget`.
std::optional<TrimPolytope> bound_piece_polytope(const Parametrization& parametrization, const ParameterDomain& piece,
                                                 const Budget& budget);

}  // namespace implicitizer
