#pragma once
/// \file
/// The first intersection of a ray with an algebraic surface F = 0: the smallest
/// root of q(s) = F(o + (t_min + s·(t_max − t_min))·d) in [0, 1] (ray_polynomial.hpp),
/// the accuracy reference of the preview renderer (method `exact`, docs/render.md).
///
/// Two paths, the first certified, the second exact:
///  - double (isolate_first_root_bernstein): q's Bernstein coefficients on [0, 1],
///    each with an error bound ε·m_j + band (m_j the majorant's coefficients) carried
///    from the expansion through every de Casteljau halving. Descartes' rule on
///    Bernstein coefficients (the number of roots in the open interval is the number
///    of sign variations minus an even number) decides a subinterval only from what
///    the bounds certify: no root when every coefficient is certified of one sign,
///    exactly one when the end coefficients are certified of opposite signs and no
///    choice of signs inside the error bands gives more than one variation. The
///    search goes leftmost subinterval first, so the first subinterval proven to
///    hold exactly one root holds the first root. A subinterval whose signs stay
///    uncertain is re-expanded on its own piece of the ray (ray_polynomial.hpp: the
///    majorant becomes that of F near the piece, not near o: for tp_33, degree 18,
///    seen from 55 units away, 1.6·10^7 times smaller on the piece [25, 50] around
///    the hit than on [0, 100], tests/render/ray_polynomial_test.cpp). The root is
///    then refined by Newton's method on F at points of the ray (evaluate_double,
///    whose bound is the running error at the point), inside a bracket whose
///    endpoint signs are certified, until the bracket is at most 2·tolerance wide.
///  - exact (isolate_first_root_descartes): the integer polynomial of the same
///    segment, its square-free part (p / gcd(p, p'), so that a double root — a
///    tangent ray, a ray through a singular point — becomes a simple one, which
///    changes sign), then Descartes' rule with bisection on dyadic subintervals
///    (Vincent–Collins–Akritas, by Taylor shifts of fmpz_poly), and exact bisection
///    of the isolating interval to the tolerance.
///
/// The double path gives up, and first_ray_root falls back to the exact one, when
/// it cannot certify its answer (FallbackReason): a subinterval narrower than the
/// tolerance whose signs the bounds cannot decide (tangency, grazing rays, singular
/// points: a double root never changes sign), certified signs with several
/// variations on such a subinterval (roots closer than the tolerance), a root whose
/// bracket the bounds cannot shrink to the tolerance (ill-conditioned: |dq/dt| small
/// against the evaluation error, e.g. a ray 1e-9 inside a tangent), a subdivision
/// limit, or coefficients outside double's range.
/// Either way the answer satisfies |t − t*| ≤ relative_tolerance·max(scale, t*), t* the
/// exact first root of the ray as given by its doubles, up to the final rounding
/// of t to double (≤ 3 ulps of t).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/render/ray_polynomial.hpp"

namespace implicitizer {

/// Which arithmetic answered.
enum class RootPath : std::uint8_t {
  double_precision,  ///< certified double (Bernstein subdivision)
  exact,             ///< integers (square-free part, Descartes, exact bisection)
};

/// How first_ray_root answers.
enum class RootMethod : std::uint8_t {
  automatic,  ///< double, and exact where double cannot certify its answer
  exact,      ///< exact only (the reference; tests compare against it)
};

/// Why the double path handed a ray to the exact one.
enum class FallbackReason : std::uint8_t {
  none,                  ///< it did not (or method exact was asked for)
  out_of_range,          ///< coefficients not finite, or the majorant underflows
  uncertain_sign,        ///< a subinterval narrower than the tolerance with undecidable signs
  root_cluster,          ///< certified signs, several variations, narrower than the tolerance
  ill_conditioned_root,  ///< an isolated root the bounds cannot pin to the tolerance
  subdivision_limit,     ///< more than max_subdivisions subintervals
};
/// Number of FallbackReason values (for per-reason counters).
inline constexpr std::size_t kFallbackReasons = 6;

/// "double" or "exact".
const char* to_string(RootPath path);
/// "none", "out_of_range", "uncertain_sign", "root_cluster", "ill_conditioned_root"
/// or "subdivision_limit".
const char* to_string(FallbackReason reason);

/// Tolerance and limits.
struct RootIsolationParams {
  /// The answer t is within relative_tolerance·max(scale, t*) of the first root t*.
  /// Must be in [1e-15, 1e-1] (below, double's own rounding of t dominates).
  double relative_tolerance = 1e-12;
  /// The length below which the tolerance stops shrinking with t (an absolute
  /// tolerance relative_tolerance·scale near the origin); > 0 and finite. 1 suits
  /// scenes of unit size; a scene of size 1e-6 wants 1e-6.
  double scale = 1;
  /// double-then-exact, or exact only.
  RootMethod method = RootMethod::automatic;
  /// Subintervals the double path may visit before it falls back (each costs
  /// O(n²) flops); ≥ 1.
  int max_subdivisions = 2048;
};

/// The first intersection found.
struct RayRoot {
  double t = 0;                                    ///< the parameter of the hit, t_min ≤ t ≤ t_max
  RootPath path = RootPath::double_precision;      ///< which path answered
  int subdivisions = 0;                            ///< subintervals (double) plus nodes and bisections (exact)
  FallbackReason fallback = FallbackReason::none;  ///< why exact answered, if the double path was tried
};

/// Counters over many rays (a render). Not thread-safe: one per thread, then add().
struct RootIsolationStats {
  std::size_t rays = 0;                                   ///< queries answered
  std::size_t hits = 0;                                   ///< queries with a root
  std::size_t exact_rays = 0;                             ///< queries the exact path answered
  std::size_t double_subdivisions = 0;                    ///< subintervals visited by the double path
  std::size_t exact_subdivisions = 0;                     ///< Descartes nodes and bisections of the exact path
  std::array<std::size_t, kFallbackReasons> fallbacks{};  ///< exact_rays by FallbackReason

  /// Adds `other`'s counters to these.
  void add(const RootIsolationStats& other);
};

/// The outcome of one path on one segment.
struct SegmentRootSearch {
  /// root: `t` holds it; no_root: none in [t_begin, t_end]; undecided: the double
  /// path could not certify either (`reason` says why).
  enum class Outcome : std::uint8_t { root, no_root, undecided };
  Outcome outcome = Outcome::no_root;            ///< see Outcome
  double t = 0;                                  ///< the root, when outcome == root
  FallbackReason reason = FallbackReason::none;  ///< when outcome == undecided
  int subdivisions = 0;                          ///< work done, as in RayRoot
};

/// The double path on `segment` of the context's F, given q = its expand_double:
/// root, certified no_root, or undecided. Subintervals are decided on q's Bernstein
/// coefficients; the isolated root is refined on F itself at points of the ray
/// (evaluate_double), whose bound depends on |p| rather than on |o| + |t·d|. Never
/// allocates once its thread's buffers have grown to the degree. Preconditions:
/// q is the segment's, 0 ≤ t_begin ≤ t_end finite, options valid.
SegmentRootSearch isolate_first_root_bernstein(const RayPolynomialContext& context, const RaySegment& segment,
                                               const DoubleRayPolynomial& q, const RootIsolationParams& options);

/// The exact path on q of the segment [t_begin, t_end] (from expand_exact: integer
/// coefficients, index k for s^k; empty for q ≡ 0, whose first root is t_begin):
/// root or no_root, never undecided. Roots of any multiplicity are found (the
/// square-free part has the same roots, all simple) and reported once. Checks
/// `budget` at every node and bisection (LimitExceeded when it runs out).
SegmentRootSearch isolate_first_root_descartes(const std::vector<Integer>& q, double t_begin, double t_end,
                                               const RootIsolationParams& options, const Budget& budget = Budget());

/// The first t in [t_min, t_max] with F(o + t·d) = 0, F the context's polynomial and
/// o, d, t exactly the doubles given; std::nullopt when the ray misses. A ray lying
/// in the surface (q ≡ 0) and a ray starting on it both answer t_min; a ray starting
/// inside a closed surface answers its first root ahead (the exit). Counts into
/// `stats` when given. Throws InputError `invalid_ray` (field "origin", "direction",
/// "t_min" or "t_max") unless all are finite, d ≠ 0 and 0 ≤ t_min ≤ t_max, and
/// `invalid_value` (field "relative_tolerance", "scale" or "max_subdivisions") for options
/// out of range; LimitExceeded from `budget` (exact path only: the double path is
/// bounded by max_subdivisions).
std::optional<RayRoot> first_ray_root(const RayPolynomialContext& context, const std::array<double, 3>& origin,
                                      const std::array<double, 3>& direction, double t_min, double t_max,
                                      const RootIsolationParams& options = RootIsolationParams(),
                                      RootIsolationStats* stats = nullptr, const Budget& budget = Budget());

/// The same for a polynomial `f` (builds its context: for one ray; a render builds
/// the context once). Also throws the context's InputErrors.
std::optional<RayRoot> first_ray_root(const Polynomial& f, const std::array<double, 3>& origin,
                                      const std::array<double, 3>& direction, double t_min, double t_max,
                                      const RootIsolationParams& options = RootIsolationParams(),
                                      RootIsolationStats* stats = nullptr, const Budget& budget = Budget());

}  // namespace implicitizer
