#pragma once
/// \file
/// The true distance D(p) from a point p to the zero set of F inside a box, computed
/// as honestly as double and long double allow: the yardstick against which
/// tests/sdf/reference_distance_test.cpp and bench/sdf_accuracy.cpp measure the
/// distance estimates of lib/sdf (fast, safe).
///
/// Two ways, both here:
///   - closed forms (recognise_closed_form): planes, spheres, cylinders and cones
///     around the z axis, tori around the z axis, recognised by comparing F exactly
///     with the expanded equation, each clipped to the box as the formula says;
///   - everywhere else, a dense point cloud ON the zero set inside the box, then
///     projections onto it (ReferenceDistance):
///       1. roots of F along axis-parallel lines through an odd grid of the box (the
///          box's faces, edges and centre are grid lines): F restricted to a line is
///          a univariate polynomial P, computed exactly; its square-free part
///          P / gcd(P, P') (exact, FLINT) has the same real roots, all simple, so a
///          line through a curve where F touches 0 without changing sign still
///          shows a sign change; the roots in the box are isolated between
///          consecutive critical points (roots of the derivatives, recursively) and
///          bisected to long double precision. A line on which P is identically 0
///          lies in the zero set: it is kept as a segment, its distance exact;
///       2. dense (s, t) samples of the parametrization, s = tan α over the whole
///          real line, mapped to space: on the surface by construction, including
///          the singular curves of its image;
///       3. singular curves that no line meets and no real parameter reaches (as
///          Whitney's handle): where a line passes near such a curve, P has a local
///          extremum with |P| <= |P''|·step²; from there Gauss–Newton on ∇F = 0
///          (least-norm steps) runs to the curve, and the point is kept when ∇F and F
///          vanish there to rounding;
///       4. for a query p, the distance to the nearest cloud point is an upper bound
///          of D (every cloud point is on the zero set and in the box, up to the
///          root's rounding). It is lowered by a descent on the surface from the
///          `starts` nearest cloud points (step along the tangential part of p − q,
///          back onto F = 0, halve until |q − p| decreases: only local minima can
///          stop it), each polished by Lagrange–Newton (minimise |q − p|² with
///          F(q) = 0, box faces that q reaches held fixed), by Lagrange–Newton from
///          p itself, and by the same descent along singular curves from the
///          nearest singular points. A point q counts only when it is in the box
///          and on the zero set: |F(q)|/|∇F(q)| below 1e-12·h, or, on a singular
///          curve, |∇F|/‖∇²F‖ below 1e-12·h and |F| below 1e-13 of Σ|terms|.
///
/// What it guarantees: every candidate is a point of the zero set in the box (to
/// ~1e-12·h), so the reference is an upper bound of D up to that; it equals D when
/// one start lies in the basin of the nearest point. Measured
/// (reference_distance_test.cpp, docs/sdf.md): within 3e-13 relative of the closed
/// forms on the public plane, sphere, cylinder, cone and torus, and of the distance
/// to Whitney's handle off the grid; the cloud alone is within 0.006·h. It can be
/// too large (never too small) near a part of the zero set that neither the grid's
/// lines, their extrema nor the parametrization reach (a component smaller than
/// the grid step, an isolated real point), and at isolated singular points, where
/// the cloud's spacing (the grid step, h/32 by default) is the resolution.
///
/// Test support compiled once (reference_distance.cpp) into the static library
/// implicitizer_test_support that the sdf tests and the accuracy benches link. It is
/// declared in the top-level CMakeLists.txt, not in tests/, because bench/ is built
/// also when BUILD_TESTING is off and tests/ is not configured at all.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/sdf/scene_frame.hpp"

namespace implicitizer::testing {

/// A point of space in double.
using Point3 = std::array<double, 3>;

/// The box [lo, hi] in double. Invariant: lo[i] < hi[i].
struct DistanceBox {
  Point3 lo{};  ///< lower corner
  Point3 hi{};  ///< upper corner

  /// The box of a SceneBox, rounded to double. Throws InputError `invalid_box`
  /// (field "box") unless lo < hi on every axis after rounding.
  static DistanceBox from_scene_box(const SceneBox& box);
  /// The centre.
  Point3 centre() const { return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}; }
  /// The largest half side: the scale h of the scene frame.
  double half_extent() const { return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / 2; }
  /// Whether p is in the closed box.
  bool contains(const Point3& p) const;
};

/// A polynomial as a list of terms with long double coefficients, for evaluation
/// with derivatives. The coefficients are F's, divided by the largest in magnitude
/// when `normalise` (the zero set and |F|/|∇F| do not change).
class FloatingPolynomial {
 public:
  /// The value, gradient and Hessian at a point of space (three variables).
  struct Derivatives {
    long double value = 0;                                ///< F(q)
    std::array<long double, 3> gradient{};                ///< ∇F(q)
    std::array<std::array<long double, 3>, 3> hessian{};  ///< ∇²F(q)
  };

  FloatingPolynomial() = default;

  /// The terms of `f`, in any ring (the variables in ring order).
  explicit FloatingPolynomial(const Polynomial& f, bool normalise);

  /// The value at `x` (one coordinate per variable).
  long double value(const long double* x) const;

  /// Σ |c|·|q^e|: the scale of F's rounding at q (three variables).
  long double magnitude(const std::array<long double, 3>& q) const;

  /// Value, gradient and Hessian at q. Precondition: three variables.
  Derivatives derivatives(const std::array<long double, 3>& q) const;

 private:
  std::int32_t exponent(std::size_t t, std::size_t i) const { return exponents_[t * variables_ + i]; }
  std::vector<long double> power_table(const long double* x) const;

  std::size_t variables_ = 0;
  std::int32_t degree_ = 0;
  std::vector<long double> coefficients_;
  std::vector<std::int32_t> exponents_;  ///< variables_ per term
};

/// A surface whose distance has a closed form, clipped to a box. Kinds and the
/// equations they recognise (up to a constant factor, exactly):
///   plane     a·x + b·y + c·z + d                 (any linear F)
///   sphere    x² + y² + z² + linear terms + const (centre and radius read off)
///   cylinder  x² + y² − r²                        (axis z)
///   cone      x² + y² − k²·z²                     (apex 0, axis z, two nappes)
///   torus     (x² + y² + z² + R² − r²)² − 4R²(x² + y²), R > r > 0 (axis z)
struct ClosedForm {
  /// Which shape.
  enum class Kind { plane, sphere, cylinder, cone, torus };
  Kind kind = Kind::plane;
  Point3 centre{};              ///< sphere
  double radius = 0;            ///< sphere, cylinder; the torus's tube radius r
  double major = 0;             ///< torus: the distance R of the tube's centre circle from the axis
  double slope = 0;             ///< cone: k
  Point3 normal{};              ///< plane: unit normal n, the plane being n·p + offset = 0
  double offset = 0;            ///< plane
  DistanceBox box;              ///< the clip
  std::vector<Point3> polygon;  ///< plane: the convex polygon plane ∩ box, in order

  /// The distance from p to the shape inside the box.
  ///   plane: the plane ∩ box is a convex polygon: the orthogonal projection when it
  ///     falls in the box, else the nearest point of the polygon's boundary;
  ///   sphere, torus: wholly inside the box (recognise_closed_form checks), so no clip;
  ///   cylinder, cone: surfaces of revolution, so the nearest point lies in p's
  ///     meridian half-plane, where the shape is a segment (cylinder: ρ = r for z in
  ///     the box's z range; cone: from the apex to (k·z_end, z_end) on each nappe).
  double distance(const Point3& p) const;

  /// A short description, e.g. "torus R=2 r=1".
  std::string describe() const;

  /// Distance from p to the segment [a, b] in space.
  static double segment_distance(const Point3& p, const Point3& a, const Point3& b);

 private:
  static double segment_distance_2d(double px, double py, double ax, double ay, double bx, double by);
};

/// The closed form of f's zero set clipped to `box`, when f is one of
/// ClosedForm's shapes exactly (compared term by term in rational arithmetic) and
/// the clip is one the formula handles (sphere and torus inside the box; the
/// cylinder's and the cone's circles inside the box's x–y square; the cone's apex
/// in its z range). Precondition: f in a ring of three variables x, y, z.
std::optional<ClosedForm> recognise_closed_form(const Polynomial& f, const DistanceBox& box);

/// A k-d tree over points, for the few nearest neighbours of a query.
class PointTree {
 public:
  PointTree() = default;
  /// Builds the tree (the points are reordered inside).
  explicit PointTree(std::vector<Point3> points);

  /// The points, in the tree's order.
  const std::vector<Point3>& points() const { return points_; }

  /// Up to k nearest points as (index into points(), squared distance), nearest first.
  std::vector<std::pair<std::size_t, double>> nearest(const Point3& p, std::size_t k) const;

 private:
  struct Node {
    std::size_t begin = 0, end = 0;
    std::size_t axis = 0;
    double split = 0;
    std::size_t left = 0, right = 0;  // 0: leaf (the root is never a child)
  };
  static constexpr std::size_t kLeaf = 8;

  std::size_t build(std::size_t begin, std::size_t end);

  void search(std::size_t id, const Point3& p, std::size_t k,
              std::priority_queue<std::pair<double, std::size_t>>& heap) const;

  std::vector<Point3> points_;
  std::vector<Node> nodes_;
};

/// How dense the cloud is and how hard the projection tries.
struct ReferenceOptions {
  /// Grid lines per axis (odd, so that the box's centre is a grid line; the
  /// faces are grid lines too): 3·n² lines, spacing 2h/(n − 1).
  int lines_per_axis = 65;
  /// Samples of each parameter (s = tan α, α uniform in (−π/2, π/2)): n² points.
  int parameter_samples = 256;
  /// Nearest cloud points (and nearest singular points) the descents start from;
  /// Lagrange–Newton from p itself is one more.
  std::size_t starts = 6;
};

/// The reference distance to the zero set of F inside a box (see the file comment).
class ReferenceDistance {
 public:
  /// A projected point is accepted when |F(q)|/|∇F(q)| <= kSurfaceTolerance·h (on a
  /// singular curve: |∇F|/‖∇²F‖ <= kSurfaceTolerance·h, see on_critical_zero).
  static constexpr double kSurfaceTolerance = 1e-12;

  /// Builds the cloud of `f` (three variables x, y, z) in `box`, with the dense
  /// samples of `parametrization` when given (its image should be f's zero set), and
  /// recognises a closed form. Throws InputError `invalid_box`, `constant_polynomial`
  /// (field "f"), `invalid_options` (lines_per_axis < 3 or even, parameter_samples < 0);
  /// LimitExceeded when `budget` runs out.
  static ReferenceDistance build(const Polynomial& f, const Parametrization* parametrization, const SceneBox& box,
                                 const ReferenceOptions& options = {}, const Budget& budget = Budget());

  /// D(p): the closed form when one was recognised, else refined_distance(p).
  double distance(const Point3& p) const { return closed_form_ ? closed_form_->distance(p) : refined_distance(p); }

  /// The cloud's answer: the smallest distance to a nearest cloud point, a zero
  /// line, or an accepted point of a descent or Lagrange–Newton projection (file
  /// comment, step 4). An upper bound of D up to kSurfaceTolerance·h; infinity
  /// when the zero set has no point in the box that the cloud found.
  double refined_distance(const Point3& p) const;

  /// The distance to the nearest cloud point or zero line, without refinement: an
  /// upper bound of D, larger by up to the cloud's spacing.
  double cloud_distance(const Point3& p) const;

  /// The unit normal ∇F/|∇F| at q, when |∇F(q)| is above 1e-8 (F's coefficients
  /// normalised to at most 1, lengths in units of h): nullopt at (nearly) singular points.
  std::optional<Point3> unit_normal(const Point3& q) const;

  /// The recognised closed form, if any.
  const std::optional<ClosedForm>& closed_form() const { return closed_form_; }
  /// The cloud (line roots, singular points and parameter samples, in the tree's order).
  const std::vector<Point3>& cloud() const { return tree_.points(); }
  /// Axis-parallel segments of the box on which F is identically 0.
  const std::vector<std::pair<Point3, Point3>>& zero_lines() const { return zero_lines_; }
  /// Cloud points from the grid lines: roots, and the singular points their extrema led to.
  std::size_t line_points() const { return line_points_; }
  /// Cloud points from the parametrization.
  std::size_t parameter_points() const { return parameter_points_; }
  /// Cloud points where ∇F = 0 (singular curves and points), found from the
  /// grid lines' extrema; included in line_points().
  const std::vector<Point3>& singular_points() const { return singular_; }
  /// The box.
  const DistanceBox& box() const { return box_; }

 private:
  using LongPoint = std::array<long double, 3>;

  // Roots of F on the 3·n² grid lines. F is substituted exactly (rational grid
  // coordinates), the result's square-free part taken exactly, then its roots
  // isolated in long double.
  std::vector<Point3> line_roots(const Polynomial& f, const SceneBox& box, const ReferenceOptions& options,
                                 const Budget& budget);

  // Where a line passes near a curve on which F touches 0 without changing sign
  // (F ≈ c·d², d the distance to the curve), P = F on the line has a local
  // extremum with |P(t*)| ≈ c·δ² <= |P''(t*)|·spacing², δ the line's distance from
  // the curve. Such extrema are seeds for to_critical_set.
  void seed_singular_points(const Polynomial& line, std::size_t along, const Point3& base, double spacing,
                            std::vector<LongPoint>& seeds) const;

  // (H² + μI)⁻¹·H·x with μ = 1e-24·‖H‖²: the least-squares solution of H·y = x that
  // ignores the directions H does not see (the tangent of a singular curve, where
  // H is singular). Returns false when H is 0.
  static bool regularised_solve(const std::array<std::array<long double, 3>, 3>& hessian,
                                const std::array<long double, 3>& x, std::array<long double, 3>& y);

  // Whether q is (to rounding) a point of the zero set where ∇F = 0: the
  // first-order distance |∇F|/‖H‖ to the critical set below kSurfaceTolerance·h,
  // and |F| below 1e-13 of Σ|terms| (long double evaluates F to about 1e-18 of
  // it, so a critical point with a nonzero value fails).
  bool on_critical_zero(const LongPoint& q, const FloatingPolynomial::Derivatives& d) const;

  // Gauss–Newton on ∇F = 0 with least-norm steps (regularised_solve): from a point
  // near a singular curve (or an isolated singular point) to its nearest point on
  // it. Returns whether q ends on the critical zero set in the box.
  bool to_critical_set(LongPoint& q) const;

  // Descent along a singular curve: the part of p − q that H does not see is the
  // curve's tangent; step along it, back onto the curve by to_critical_set, halving
  // the step until |q − p| decreases. At an isolated singular point the tangent is
  // 0 and q stays.
  double descend_curve(const Point3& p, LongPoint q) const;

  // Parameter samples mapped to space, kept when inside the box.
  void add_parameter_samples(const Parametrization& parametrization, const ReferenceOptions& options,
                             const Budget& budget, std::vector<Point3>& cloud) const;

  // Whether q is on the zero set to kSurfaceTolerance·h, measured by F's
  // first-order distance along the free coordinates.
  bool on_surface(const FloatingPolynomial::Derivatives& d, const std::array<bool, 3>& held) const;

  // Newton along the free part of the gradient onto F = 0 (q ← q − F·g/|g|²); a
  // coordinate that leaves the box is clamped and held. Returns whether q ends on
  // the surface.
  bool reproject(LongPoint& q, std::array<bool, 3>& held) const;

  // A point of the zero set and its distance from p.
  struct Descent {
    LongPoint q;
    double distance;
  };

  // Descent on the surface: from q (a cloud point), step along the tangential
  // part of p − q, back onto the surface by reproject, halving the step until
  // |q − p| decreases. Every iterate is on the surface and in the box and the
  // distance only decreases, so this finds a local minimum of |q − p| on the zero
  // set where Newton on the optimality conditions may run to a maximum or a saddle,
  // or away (near a fold or a singular curve). Linear convergence: project() then
  // polishes. A coordinate at a face that the step would push outward is held.
  std::optional<Descent> descend(const Point3& p, LongPoint q) const;

  // Lagrange–Newton for min |q − p|² subject to F(q) = 0 and q in the box, from
  // `start`. Unknowns: the free coordinates of q and λ; equations
  // (q − p)_i + λ·∂_iF(q) = 0 for free i, F(q) = 0; Jacobian [[I + λ∇²F, ∇F], [∇Fᵀ, 0]]
  // restricted to the free coordinates. A coordinate that leaves the box is clamped
  // to the face and held there (the minimum then lies on the face's curve).
  // Returns |p − q| when q is accepted (see kSurfaceTolerance), else nullopt.
  std::optional<double> project(const Point3& p, std::array<long double, 3> q) const;

  // Gaussian elimination with partial pivoting on the n×(n + 1) augmented matrix.
  static bool solve(long double (&a)[4][5], std::size_t n, std::array<long double, 4>& x);

  DistanceBox box_;
  double h_ = 1;
  FloatingPolynomial f_;
  std::optional<ClosedForm> closed_form_;
  PointTree tree_;
  std::vector<Point3> singular_;  // points of the zero set where ∇F = 0 (to_critical_set)
  PointTree singular_tree_;
  std::vector<std::pair<Point3, Point3>> zero_lines_;
  std::size_t line_points_ = 0, parameter_points_ = 0, starts_ = 6;
  double spacing_ = 1;  // the grid step
};

/// The box that frames a surface of ../shared/bench/surfaces_public.json in the
/// accuracy test and bench: a cube (the scene frame is one: its h is the largest half
/// side) with a power-of-two half side and an integer centre, so that the frame's
/// float centre and scale are exact and its cube is exactly this box. Chosen to hold
/// the surface's interesting part: [−2, 2]³ by default (the unit sphere, cylinder,
/// cone, Whitney's umbrella with its handle, the graphs near their saddles);
/// [−4, 4]³ for the torus (outer radius 3) and Enneper's surface (its
/// self-intersections lie within |x|, |y| <= 3.75 for |s|, |t| <= 1.5); [−1, 1]³ for
/// Steiner's surface (within [−1/2, 1/2]³, its axes run to the faces); for the
/// biquadratic patch the cube of half side 4 around (2, 0, 0), which holds the image
/// of [−1, 1]² (x in [−1, 5], y in [−3, 3], z in [−2.25, 1]).
SceneBox public_surface_box(const std::string& name);

/// `count` sample points in the box for the accuracy measurements: half uniform in
/// the box, half in a shell around the surface (a random cloud point with a
/// regular normal n, moved to q + σ·δ·2h·n, σ = ±1, δ log-uniform in [1e-3, 1e-1]:
/// 1e-3 to 1e-1 of the box's size), the shell points kept only inside the box.
/// Every coordinate is rounded to float, the type a shader receives, so that an
/// fp32 estimate and the reference see the same point. Deterministic for a given
/// seed. Precondition: the cloud is not empty.
std::vector<Point3> accuracy_samples(const ReferenceDistance& reference, std::size_t count, unsigned seed);

/// What the accuracy table says about a distance estimate v against the reference
/// D at sample points.
struct EstimateStatistics {
  /// |v| may exceed D by this relative amount before it counts as "over": the
  /// reference's own rounding (projections are accepted at 1e-12·h) is far below it.
  static constexpr double kOverRelative = 1e-6;
  /// ... plus this times h: fp32 resolves positions near the box to about 1e-7·h, so
  /// no fp32 estimate can mean anything finer.
  static constexpr double kOverAbsolute = 1e-7;
  /// Below this times h, D is too small for |v|/D to mean anything; such points count
  /// for `over` but not for the ratios.
  static constexpr double kRatioFloor = 1e-9;

  std::size_t points = 0;   ///< sample points
  std::size_t over = 0;     ///< points where |v| > D·(1 + kOverRelative) + kOverAbsolute·h
  std::size_t ratios = 0;   ///< points with D >= kRatioFloor·h, over which the ratios are taken
  double median_ratio = 0;  ///< median of |v|/D
  double p5_ratio = 0;      ///< 5th percentile of |v|/D (nearest rank)
  double max_ratio = 0;     ///< largest |v|/D
};

/// The statistics of estimates `values` against reference distances `distances`
/// (same length), h the box's half extent.
EstimateStatistics summarise_estimates(const std::vector<double>& values, const std::vector<double>& distances,
                                       double h);

}  // namespace implicitizer::testing
