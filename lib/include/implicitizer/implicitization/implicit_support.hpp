#pragma once
/// \file
/// A predicted support for the implicit equation of a surface in two parameters, far
/// smaller than the monomials of degree ≤ the dense bound when the parametrization is
/// sparse. Two facts, each a theorem for every input (no genericity is assumed):
///
///   1. Degrees by mixed volumes. The degree of F in z is the number of points of the
///      surface on a general line x = a, y = b, each the image of deg φ parameter points
///      (a general line misses the images of curves and base points), so
///      deg_z F · deg φ ≤ the number of isolated zeros in the torus of
///      ξ_1 − a·ω = ξ_2 − b·ω = 0, which Bernstein's theorem bounds by the mixed volume
///      MV(P_1, P_2) of their Newton polygons (P_i = conv(supp ξ_i ∪ supp ω)); a general
///      point (a, b) of the plane is not the image of a point on a coordinate axis of
///      the parameters, so every fibre point lies in the torus. Likewise for x, y, and
///      for the total degree with two general planes: MV(P, P) = 2·area(P) for
///      P = conv(supp ω ∪ supp ξ_1 ∪ supp ξ_2 ∪ supp ξ_3).
///   2. A grading. Let L ⊂ ℤ² be the lattice spanned by the differences of exponents
///      within each of ω, ξ_1, ξ_2, ξ_3. Each form is homogeneous for the grading by
///      G = ℤ²/L, of degree g_i, so ω^d·F(ξ/ω) splits into the parts of F whose
///      monomials x^α share the class Σ α_i·(g_i − g_0), and each part vanishes on the
///      image by itself. The implicit equation is irreducible, so it has one class
///      (a part is a multiple of it of no larger support). For x = s^7 + t, y = t^7 + s,
///      z = s·t^3, G = ℤ/48: the box of fact 1 (8,602 monomials) splits into 48 classes
///      of about 180.
///
/// The equation lies in one class of the box; which one, the kernels decide
/// (sparse_interpolation.hpp). A map of degree > 1 only makes the box larger.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/parametrization.hpp"

namespace implicitizer {

/// The box of fact 1 split into the classes of fact 2.
struct ImplicitSupport {
  std::array<std::int32_t, 3> degree_in{};  ///< bounds on the degrees in x, y, z
  std::int32_t total_degree = 0;            ///< bound on the total degree
  /// |G| (0 when G is infinite: the lattice has rank below 2, the map is quasi-homogeneous).
  std::size_t group_order = 0;
  /// The monomials of the box, one list per class (3 exponents per monomial), each in
  /// no particular order; classes with no monomial are absent.
  std::vector<std::vector<std::int32_t>> classes;
  /// Monomials of the box (all classes).
  std::size_t columns = 0;
  /// Monomials of the largest class.
  std::size_t largest_class = 0;
  /// Σ over classes of (monomials)³: the cost, in the units of one dense row reduction's
  /// cube, of a kernel per class.
  double cubed_columns = 0;
};

/// The largest box enumerated: beyond it the prediction is refused (nullopt), as no
/// class of it could be a kernel of useful size anyway.
inline constexpr double kMaxPredictedBox = 2e6;

/// C(d + 3, 3): the monomials of degree ≤ d in space, the dense kernel's columns that a
/// prediction is compared with (a double: bounds in the millions do not overflow).
double space_monomial_count(std::int32_t d);

/// The predicted support of the implicit equation of a surface in two parameters
/// (three coordinates), as the header describes. nullopt for other parametrizations
/// and when the box has more than kMaxPredictedBox monomials. A box near that size
/// outlasts a short deadline, so `budget` is checked as it goes (stops name "the
/// predicted support").
std::optional<ImplicitSupport> predict_implicit_support(const Parametrization& parametrization,
                                                        const Budget& budget = Budget());

/// The mixed volume MV(P, Q) of two lattice polygons given by points (2 coordinates
/// each; the polygons are their convex hulls), normalised so that MV(P, P) = 2·area(P):
/// Bernstein's bound on the isolated zeros in the torus of two polynomials with these
/// Newton polygons. Exposed for tests.
std::int64_t mixed_volume(const std::vector<std::array<std::int64_t, 2>>& p,
                          const std::vector<std::array<std::int64_t, 2>>& q);

}  // namespace implicitizer
