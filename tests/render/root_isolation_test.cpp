// Tests of lib/src/render/root_isolation.cpp: the first intersection of a ray with an
// algebraic surface, method `exact` of the renderer. Every answer is compared with
// the exact path (RootMethod::exact) and, where one exists, with a closed form.
//
// The documented behaviour (docs/render.md, "Exact intersection"), case by case, at
// the default relative tolerance 1e-12:
//  - A ray tangent to the unit sphere (q = (t − 3)², a double root) hits at the
//    tangency: the double path cannot certify a sign change that does not exist and
//    hands the ray to the exact one (uncertain_sign), whose square-free part has a
//    simple root there. A ray 1e-9 outside the tangent misses, decided in double. A
//    ray 1e-9 inside has two roots 4.5e-5 apart where |dq/dt| = 9e-5: the point bound
//    (about 1e-15) moves the root by about 1e-11, more than the tolerance, so the
//    exact path answers (ill_conditioned_root); at tolerance 1e-9, double.
//  - A ray through the handle of Whitney's umbrella (y²z − x² = 0, the negative
//    z-axis, where the surface is a line) or through the cone's apex (x² + y² − z²) is
//    a double root: found by the exact path. A ray along a line of the cone lies in
//    the surface (q ≡ 0): its first root is t_min.
//  - A ray from 10^6 away hits the unit sphere with |t − t*| ≤ tolerance·t*, in double
//    even at tolerance 1e-15: q's expanded coefficients cancel by 12 digits, but the
//    root is refined on F at points of the ray split exactly (two_product, two_sum).
//  - A ray starting inside the sphere answers its exit, not t = 0; a ray starting
//    on the surface answers t_min.
//  - A ray through the torus's x/y cross-section (4 roots) answers the first; with
//    t_min past it, the next; a segment ending before it misses.
//  - 1e30·sphere and 1e-30·(sphere of radius 1e-6, with scale 1e-6) answer what the
//    unit-size polynomials answer (coefficients are scaled by a power of two).
//  - Degree 18 (tp_33, ../shared/bench/surfaces_hard.json): random rays agree with
//    the exact path.
//  - Singular's Sturm counts (rootsur.lib) confirm, for twelve of these rays, that no
//    root lies before the answer and one lies at it.
//  - The public surfaces at 256×256 from the seed's camera agree with the exact path;
//    the test prints per-ray times and fallback rates (docs/render.md).

#include "implicitizer/render/root_isolation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "implicitization/surfaces.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/render/camera.hpp"
#include "oracle/oracle_support.hpp"
#include "sdf/sdf_support.hpp"

namespace implicitizer {
namespace {

using testing::parse_xyz;
using Vec = std::array<double, 3>;

const Polynomial& unit_sphere() {
  static const Polynomial f = parse_xyz("x^2+y^2+z^2-1");
  return f;
}

RootIsolationParams exact_only(RootIsolationParams options = RootIsolationParams()) {
  options.method = RootMethod::exact;
  return options;
}

// Both paths on one ray; they must agree: both miss, or both hit within the sum of
// their tolerances (each is within tolerance·max(scale, t*) of the true root t*).
struct BothPaths {
  std::optional<RayRoot> automatic, exact;
};

BothPaths run_both(const RayPolynomialContext& context, const Vec& o, const Vec& d, double t_min, double t_max,
                   const RootIsolationParams& options = RootIsolationParams()) {
  BothPaths out;
  out.automatic = first_ray_root(context, o, d, t_min, t_max, options);
  out.exact = first_ray_root(context, o, d, t_min, t_max, exact_only(options));
  return out;
}

BothPaths run_both(const Polynomial& f, const Vec& o, const Vec& d, double t_min, double t_max,
                   const RootIsolationParams& options = RootIsolationParams()) {
  return run_both(RayPolynomialContext(f), o, d, t_min, t_max, options);
}

::testing::AssertionResult paths_agree(const BothPaths& r,
                                       const RootIsolationParams& options = RootIsolationParams()) {
  if (r.automatic.has_value() != r.exact.has_value()) {
    return ::testing::AssertionFailure() << "automatic " << (r.automatic ? "hits" : "misses") << ", exact "
                                         << (r.exact ? "hits" : "misses");
  }
  if (!r.exact) return ::testing::AssertionSuccess();
  if (r.exact->path != RootPath::exact) return ::testing::AssertionFailure() << "exact_only took the double path";
  const double allowed = 2 * options.relative_tolerance * std::max(options.scale, r.exact->t) + 4e-16 * r.exact->t;
  if (std::fabs(r.automatic->t - r.exact->t) > allowed) {
    return ::testing::AssertionFailure() << "automatic t = " << r.automatic->t << " (" << to_string(r.automatic->path)
                                         << "), exact t = " << r.exact->t << ", allowed " << allowed;
  }
  return ::testing::AssertionSuccess();
}

// |t − expected| ≤ tolerance·max(scale, expected) + a few ulps for the closed form.
void expect_close(double t, double expected, const RootIsolationParams& options = RootIsolationParams()) {
  EXPECT_LE(std::fabs(t - expected), options.relative_tolerance * std::max(options.scale, expected) + 4e-16 * expected)
      << "t = " << t << ", expected " << expected;
}

// sqrt of an exact rational, to double (for closed forms).
double sqrt_of(const Rational& q) { return std::sqrt(to_mpq(q).get_d()); }

TEST(RootIsolation, TangentRayHitsTheSphereAtTheTangency) {
  // o + t·d = (t − 3, 1, 0): |p|² − 1 = (t − 3)², a double root at 3.
  const BothPaths r = run_both(unit_sphere(), {-3, 1, 0}, {1, 0, 0}, 0, 10);
  ASSERT_TRUE(paths_agree(r));
  ASSERT_TRUE(r.automatic.has_value()) << "the grazing ray missed";
  expect_close(r.automatic->t, 3.0);
  EXPECT_EQ(r.automatic->path, RootPath::exact);
  EXPECT_EQ(r.automatic->fallback, FallbackReason::uncertain_sign);
}

TEST(RootIsolation, NearTangentRaysMissOrHitNearTheTangency) {
  // 1e-9 outside the tangent: min q = (1 + 1e-9)² − 1 ≈ 2e-9, far above the bound.
  const BothPaths miss = run_both(unit_sphere(), {-3, 1 + 1e-9, 0}, {1, 0, 0}, 0, 10);
  ASSERT_TRUE(paths_agree(miss));
  EXPECT_FALSE(miss.automatic.has_value());
  // 1e-9 inside: roots 3 ∓ sqrt(1 − y²), 4.5e-5 apart, where |dq/dt| = 9e-5. The
  // point bound there is about 1e-15, which moves the root by about 1e-11: more than
  // the tolerance 3e-12, so the exact path answers; with a tolerance of 1e-9, double.
  const double y = 1 - 1e-9;
  const double first = 3 - sqrt_of(Rational(1) - Rational(y) * Rational(y));
  const BothPaths hit = run_both(unit_sphere(), {-3, y, 0}, {1, 0, 0}, 0, 10);
  ASSERT_TRUE(paths_agree(hit));
  ASSERT_TRUE(hit.automatic.has_value());
  EXPECT_EQ(hit.automatic->path, RootPath::exact);
  EXPECT_EQ(hit.automatic->fallback, FallbackReason::ill_conditioned_root);
  expect_close(hit.automatic->t, first);
  RootIsolationParams loose;
  loose.relative_tolerance = 1e-9;
  const BothPaths loose_hit = run_both(unit_sphere(), {-3, y, 0}, {1, 0, 0}, 0, 10, loose);
  ASSERT_TRUE(paths_agree(loose_hit, loose));
  ASSERT_TRUE(loose_hit.automatic.has_value());
  EXPECT_EQ(loose_hit.automatic->path, RootPath::double_precision) << to_string(loose_hit.automatic->fallback);
  expect_close(loose_hit.automatic->t, first, loose);
}

TEST(RootIsolation, RayThroughWhitneyUmbrellaHandleHits) {
  // The bench's umbrella (x = s·t, y = s, z = t²): its equation from implicitize().
  Polynomial f(testing::xyz_ring());
  for (const testing::Surface& s :
       testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_public.json")) {
    if (s.name == "whitney_umbrella") f = implicitize(parse_parametrization(s.x, s.y, s.z)).implicit;
  }
  ASSERT_EQ(f, parse_xyz("y^2*z-x^2").primitive_part());
  // (1 − t, 2 − 2t, −2): F = (2 − 2t)²(−2) − (1 − t)² = −9(1 − t)², the handle at t = 1.
  const BothPaths handle = run_both(f, {1, 2, -2}, {-1, -2, 0}, 0, 10);
  ASSERT_TRUE(paths_agree(handle));
  ASSERT_TRUE(handle.automatic.has_value()) << "the ray through the handle missed";
  expect_close(handle.automatic->t, 1.0);
  EXPECT_EQ(handle.automatic->path, RootPath::exact);
  // A ray near the handle but not through it misses (the handle is a line).
  const BothPaths near = run_both(f, {1, 2, -2}, {-1, -2.001, 0}, 0, 10);
  ASSERT_TRUE(paths_agree(near));
  EXPECT_FALSE(near.automatic.has_value());
  // The sheet z ≥ 0 is an ordinary surface: (0.5, 1, 5 − t) hits where 5 − t = 0.25.
  const BothPaths sheet = run_both(f, {0.5, 1, 5}, {0, 0, -1}, 0, 10);
  ASSERT_TRUE(paths_agree(sheet));
  ASSERT_TRUE(sheet.automatic.has_value());
  EXPECT_EQ(sheet.automatic->path, RootPath::double_precision);
  expect_close(sheet.automatic->t, 4.75);
}

TEST(RootIsolation, RayThroughTheConesApexHits) {
  const Polynomial cone = parse_xyz("x^2+y^2-z^2");
  // (3 − 3t, 0, 4 − 4t): F = −7(1 − t)², the apex at t = 1, inside the cone on both sides.
  const BothPaths apex = run_both(cone, {3, 0, 4}, {-3, 0, -4}, 0, 10);
  ASSERT_TRUE(paths_agree(apex));
  ASSERT_TRUE(apex.automatic.has_value()) << "the ray through the apex missed";
  expect_close(apex.automatic->t, 1.0);
  EXPECT_EQ(apex.automatic->path, RootPath::exact);
  // Unit direction (−0.6, 0, −0.8) is rounded: the ray passes within 1e-16 of the apex.
  // Whatever the doubles decide, the hit is at the apex up to that offset.
  const BothPaths unit = run_both(cone, {3, 0, 4}, {-0.6, 0, -0.8}, 0, 10);
  ASSERT_TRUE(paths_agree(unit));
  ASSERT_TRUE(unit.automatic.has_value());
  EXPECT_NEAR(unit.automatic->t, 5.0, 1e-7);
  // Along a line of the cone the ray lies in the surface: t_min.
  const BothPaths line = run_both(cone, {3, 0, 3}, {-1, 0, -1}, 0.5, 10);
  ASSERT_TRUE(paths_agree(line));
  ASSERT_TRUE(line.automatic.has_value());
  EXPECT_EQ(line.automatic->t, 0.5);
}

TEST(RootIsolation, RayFromAMillionAwayKeepsRelativeAccuracy) {
  // (1e6 − t, 0.5, 0): t* = 1e6 − sqrt(0.75). q's coefficients cancel by 12 digits,
  // but the root is refined on F at points of the ray split exactly into s + r
  // (ray_polynomial.hpp), where F's terms are of size 1: double, even at relative
  // tolerance 1e-15 (1e-9 here, 9 ulps of t).
  for (const double tolerance : {1e-12, 1e-15}) {
    RootIsolationParams options;
    options.relative_tolerance = tolerance;
    const BothPaths axis = run_both(unit_sphere(), {1e6, 0.5, 0}, {-1, 0, 0}, 0, 2e6, options);
    ASSERT_TRUE(paths_agree(axis, options));
    ASSERT_TRUE(axis.automatic.has_value());
    expect_close(axis.automatic->t, 1e6 - std::sqrt(0.75), options);
    EXPECT_EQ(axis.automatic->path, RootPath::double_precision) << to_string(axis.automatic->fallback);
  }
  // A diagonal ray: t* = −b − sqrt(b² − c), b = o·d, c = |o|² − 1 (exact rationals).
  const Vec o{6e5, -8e5, 1e5};
  const double n = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
  const Vec d{-o[0] / n, -o[1] / n + 1e-7, -o[2] / n};
  Rational b(0), c(-1), dd(0);
  for (std::size_t i = 0; i < 3; ++i) {
    b += Rational(o[i]) * Rational(d[i]);
    c += Rational(o[i]) * Rational(o[i]);
    dd += Rational(d[i]) * Rational(d[i]);
  }
  // |d| ≠ 1 after rounding: t* = (−b − sqrt(b² − dd·c)) / dd.
  const Rational disc = b * b - dd * c;
  ASSERT_GT(disc, Rational(0));
  const double expected = (-to_mpq(b).get_d() - sqrt_of(disc)) / to_mpq(dd).get_d();
  const BothPaths diagonal = run_both(unit_sphere(), o, d, 0, 2e6);
  ASSERT_TRUE(paths_agree(diagonal));
  ASSERT_TRUE(diagonal.automatic.has_value());
  expect_close(diagonal.automatic->t, expected);
}

TEST(RootIsolation, RayStartingInsideAnswersTheExit) {
  // |o|² = 0.14: the exit at t = sqrt(1 − 0.04 − 0.09) − 0.1, not t = 0.
  const BothPaths r = run_both(unit_sphere(), {0.1, 0.2, 0.3}, {1, 0, 0}, 0, 10);
  ASSERT_TRUE(paths_agree(r));
  ASSERT_TRUE(r.automatic.has_value());
  EXPECT_EQ(r.automatic->path, RootPath::double_precision);
  const Rational y(0.2), z(0.3);
  expect_close(r.automatic->t, sqrt_of(Rational(1) - y * y - z * z) - 0.1);
  // Starting on the surface answers t_min (here through the exact path: q(0) = 0).
  const BothPaths on = run_both(unit_sphere(), {1, 0, 0}, {-1, 0, 0}, 0, 10);
  ASSERT_TRUE(paths_agree(on));
  ASSERT_TRUE(on.automatic.has_value());
  EXPECT_EQ(on.automatic->t, 0.0);
}

TEST(RootIsolation, TorusCrossSectionAnswersTheFirstOfFourRoots) {
  const Polynomial torus = parse_xyz("(x^2+y^2+z^2+3)^2-16*(x^2+y^2)");
  // y = 0.5, z = 0: hits at x = ±sqrt(9 − 0.25), ±sqrt(1 − 0.25); from x = −5 the first
  // at t = 5 − sqrt(8.75), then 5 − sqrt(0.75), 5 + sqrt(0.75), 5 + sqrt(8.75).
  const RayPolynomialContext context(torus);
  const BothPaths first = run_both(context, {-5, 0.5, 0}, {1, 0, 0}, 0, 20);
  ASSERT_TRUE(paths_agree(first));
  ASSERT_TRUE(first.automatic.has_value());
  EXPECT_EQ(first.automatic->path, RootPath::double_precision) << to_string(first.automatic->fallback);
  expect_close(first.automatic->t, 5 - std::sqrt(8.75));
  // From t_min = 3 (inside the hole) the next root.
  const BothPaths second = run_both(context, {-5, 0.5, 0}, {1, 0, 0}, 3, 20);
  ASSERT_TRUE(paths_agree(second));
  ASSERT_TRUE(second.automatic.has_value());
  expect_close(second.automatic->t, 5 - std::sqrt(0.75));
  // A segment that ends before the first root misses.
  const BothPaths short_segment = run_both(context, {-5, 0.5, 0}, {1, 0, 0}, 0, 2);
  ASSERT_TRUE(paths_agree(short_segment));
  EXPECT_FALSE(short_segment.automatic.has_value());
}

TEST(RootIsolation, HugeAndTinyCoefficientsAnswerLikeUnitOnes) {
  // 1e30·sphere: the same first root as the sphere.
  const BothPaths huge = run_both(parse_xyz("10^30*(x^2+y^2+z^2-1)"), {0.1, 0.2, 5}, {0, 0, -1}, 0, 10);
  ASSERT_TRUE(paths_agree(huge));
  ASSERT_TRUE(huge.automatic.has_value());
  EXPECT_EQ(huge.automatic->path, RootPath::double_precision);
  expect_close(huge.automatic->t,
               5 - sqrt_of(Rational(1) - Rational(0.1) * Rational(0.1) - Rational(0.2) * Rational(0.2)));
  // 1e-30·(sphere of radius 1e-6): scale 1e-6 makes the tolerance relative to the size.
  RootIsolationParams micro;
  micro.scale = 1e-6;
  const Polynomial tiny = parse_xyz("(x^2+y^2+z^2-1/10^12)/10^30");
  const Vec o{-1e-5, 2e-7, 0};
  const BothPaths r = run_both(tiny, o, {1, 0, 0}, 0, 1e-4, micro);
  ASSERT_TRUE(paths_agree(r, micro));
  ASSERT_TRUE(r.automatic.has_value());
  const Rational r2 = Rational(1, 1000000) * Rational(1, 1000000);
  expect_close(r.automatic->t, 1e-5 - sqrt_of(r2 - Rational(o[1]) * Rational(o[1])), micro);
}

TEST(RootIsolation, DegreeEighteenAgreesWithTheExactPath) {
  const Polynomial& f = testing::tp33_implicit();
  ASSERT_EQ(f.total_degree(), 18);
  const RayPolynomialContext context(f);
  // Rays from outside tp_33's box [−8, 8]×[−10, 6]×[−18, 4] towards random points in it.
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> ux(-8, 8), uy(-10, 6), uz(-18, 4);
  RootIsolationStats stats;
  int hits = 0;
  const int rays = 24;
  double automatic_seconds = 0, exact_seconds = 0;
  for (int i = 0; i < rays; ++i) {
    const Vec o{30, 25, 40};
    const Vec target{ux(rng), uy(rng), uz(rng)};
    Vec d{target[0] - o[0], target[1] - o[1], target[2] - o[2]};
    const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& x : d) x /= n;
    BothPaths r;
    const auto t0 = std::chrono::steady_clock::now();
    r.automatic = first_ray_root(context, o, d, 0, 100, RootIsolationParams(), &stats);
    const auto t1 = std::chrono::steady_clock::now();
    r.exact = first_ray_root(context, o, d, 0, 100, exact_only());
    const auto t2 = std::chrono::steady_clock::now();
    automatic_seconds += std::chrono::duration<double>(t1 - t0).count();
    exact_seconds += std::chrono::duration<double>(t2 - t1).count();
    EXPECT_TRUE(paths_agree(r)) << "ray " << i;
    hits += r.exact ? 1 : 0;
  }
  std::string reasons;
  for (std::size_t r = 1; r < kFallbackReasons; ++r) {
    reasons += std::string(" ") + to_string(static_cast<FallbackReason>(r)) + "=" + std::to_string(stats.fallbacks[r]);
  }
  std::printf(
      "[tp_33] %zu terms, %d rays, %d hits, %zu answered exactly:%s; per ray: automatic %.0f us, exact %.0f us\n",
      f.num_terms(), rays, hits, stats.exact_rays, reasons.c_str(), 1e6 * automatic_seconds / rays,
      1e6 * exact_seconds / rays);
  EXPECT_GT(hits, 0);
}

// Random rays through random low-degree surfaces: the two paths always agree.
TEST(RootIsolation, RandomRaysAgreeWithTheExactPath) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  const std::vector<std::string> surfaces = {
      "x^2+y^2+z^2-1", "x^2+y^2-z^2", "y^2*z-x^2", "(x^2+y^2+z^2+3)^2-16*(x^2+y^2)", "x^2*y^2+y^2*z^2+z^2*x^2-x*y*z",
      "x^3-3*x*y^2-z", "x*y*z-1/10"};
  RootIsolationStats stats;
  for (const std::string& text : surfaces) {
    const RayPolynomialContext context(parse_xyz(text));
    for (int i = 0; i < 150; ++i) {
      const Vec o{4 * unit(rng), 4 * unit(rng), 4 * unit(rng)};
      const Vec d{unit(rng), unit(rng), unit(rng)};
      BothPaths r;
      r.automatic = first_ray_root(context, o, d, 0, 20, RootIsolationParams(), &stats);
      r.exact = first_ray_root(context, o, d, 0, 20, exact_only());
      EXPECT_TRUE(paths_agree(r)) << text << " ray " << i;
    }
  }
  EXPECT_EQ(stats.rays, 7u * 150u);
}

TEST(RootIsolation, RefusesInvalidRaysAndOptions) {
  const RayPolynomialContext context(unit_sphere());
  auto code_of = [&](const Vec& o, const Vec& d, double t0, double t1, const RootIsolationParams& options) {
    try {
      first_ray_root(context, o, d, t0, t1, options);
    } catch (const InputError& e) {
      return e.code() + "/" + e.field();
    }
    return std::string("accepted");
  };
  const RootIsolationParams ok;
  EXPECT_EQ(code_of({NAN, 0, 0}, {1, 0, 0}, 0, 1, ok), "invalid_ray/origin");
  EXPECT_EQ(code_of({0, 0, 0}, {0, 0, 0}, 0, 1, ok), "invalid_ray/direction");
  EXPECT_EQ(code_of({0, 0, 0}, {INFINITY, 0, 0}, 0, 1, ok), "invalid_ray/direction");
  EXPECT_EQ(code_of({0, 0, 0}, {1, 0, 0}, -1, 1, ok), "invalid_ray/t_min");
  EXPECT_EQ(code_of({0, 0, 0}, {1, 0, 0}, 2, 1, ok), "invalid_ray/t_max");
  EXPECT_EQ(code_of({0, 0, 0}, {1, 0, 0}, 0, INFINITY, ok), "invalid_ray/t_max");
  RootIsolationParams bad = ok;
  bad.relative_tolerance = 0;
  EXPECT_EQ(code_of({0, 0, 0}, {1, 0, 0}, 0, 1, bad), "invalid_value/relative_tolerance");
  bad = ok;
  bad.scale = 0;
  EXPECT_EQ(code_of({0, 0, 0}, {1, 0, 0}, 0, 1, bad), "invalid_value/scale");
  bad = ok;
  bad.max_subdivisions = 0;
  EXPECT_EQ(code_of({0, 0, 0}, {1, 0, 0}, 0, 1, bad), "invalid_value/max_subdivisions");
  EXPECT_EQ(code_of({0, 0, 0}, {1, 0, 0}, 0, 1, ok), "accepted");
}

TEST(RootIsolation, ExactPathStopsOnItsBudget) {
  const RayPolynomialContext context(testing::tp33_implicit());
  Budget budget;
  budget.cancel();
  EXPECT_THROW(first_ray_root(context, {30, 25, 40}, {-0.6, -0.5, -0.8}, 0, 100, exact_only(), nullptr, budget),
               LimitExceeded);
}

// An outside oracle for the isolation: Singular substitutes the ray into F itself
// (exact rationals: every double is one) and counts distinct real roots of g(t) in
// ]a, b] with Sturm sequences (rootsur.lib's sturm). For every answer t: none in
// ]t_min, t − w] and at least one in ]t − w, t + w], w = 4·tolerance·max(1, t); for a
// miss, none in ]t_min, t_max].
TEST(RootIsolation, SingularSturmCountsAgree) {
  if (!testing::is_runnable(testing::kSingular)) GTEST_SKIP() << "Singular not found (" << testing::kSingular << ")";
  struct Case {
    std::string name;
    Polynomial f;
    Vec o, d;
    double t_min, t_max;
  };
  const Polynomial torus = parse_xyz("(x^2+y^2+z^2+3)^2-16*(x^2+y^2)");
  const Polynomial enneper =
      parse_xyz(testing::read_text(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/expected/enneper.txt"));
  const Camera camera(CameraSpec(), 256, 256);
  const Ray e1 = camera.ray_through(249.5, 28.5), e2 = camera.ray_through(128.5, 128.5),
            e3 = camera.ray_through(3.5, 200.5);
  std::vector<Case> cases = {
      {"tangent", unit_sphere(), {-3, 1, 0}, {1, 0, 0}, 0, 10},
      {"near_miss", unit_sphere(), {-3, 1 + 1e-9, 0}, {1, 0, 0}, 0, 10},
      {"near_hit", unit_sphere(), {-3, 1 - 1e-9, 0}, {1, 0, 0}, 0, 10},
      {"far", unit_sphere(), {1e6, 0.5, 0}, {-1, 0, 0}, 0, 2e6},
      {"torus", torus, {-5, 0.5, 0}, {1, 0, 0}, 0, 20},
      {"torus_from_3", torus, {-5, 0.5, 0}, {1, 0, 0}, 3, 20},
      {"umbrella_handle", parse_xyz("y^2*z-x^2"), {1, 2, -2}, {-1, -2, 0}, 0, 10},
      {"cone_apex", parse_xyz("x^2+y^2-z^2"), {3, 0, 4}, {-0.6, 0, -0.8}, 0, 10},
      {"enneper_1", enneper, e1.origin, e1.direction, 0, 100},
      {"enneper_2", enneper, e2.origin, e2.direction, 0, 100},
      {"enneper_3", enneper, e3.origin, e3.direction, 0, 100},
      {"tp_33", testing::tp33_implicit(), {30, 25, 40}, {-0.6, -0.5, -0.62}, 0, 100},
  };
  auto rational = [](double x) { return "(" + to_string(Rational(x)) + ")"; };
  std::string script = "LIB \"rootsur.lib\";\nring r = 0, (x,y,z,t), dp;\n";
  std::vector<std::optional<RayRoot>> answers;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Case& c = cases[k];
    answers.push_back(first_ray_root(c.f, c.o, c.d, c.t_min, c.t_max));
    script += "poly g" + std::to_string(k) + " = subst(subst(subst(" + to_string(c.f) + ", x, " + rational(c.o[0]) +
              "+t*" + rational(c.d[0]) + "), y, " + rational(c.o[1]) + "+t*" + rational(c.d[1]) + "), z, " +
              rational(c.o[2]) + "+t*" + rational(c.d[2]) + ");\n";
  }
  script += "ring s = 0, t, dp;\n";
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string g = "g" + std::to_string(k);
    script += "poly " + g + " = imap(r, " + g + ");\n";
    script += "print(\"" + testing::section_marker(cases[k].name) + "\");\n";
    if (answers[k]) {
      const double t = answers[k]->t;
      const double w = 4e-12 * std::max(1.0, t);
      script += "sturm(" + g + ", " + rational(cases[k].t_min) + ", " + rational(t - w) + ");\n";
      script += "sturm(" + g + ", " + rational(t - w) + ", " + rational(t + w) + ");\n";
    } else {
      script += "sturm(" + g + ", " + rational(cases[k].t_min) + ", " + rational(cases[k].t_max) + ");\n";
    }
  }
  script += "quit;\n";
  const testing::ScriptRun run = testing::run_singular(script, 120);
  ASSERT_EQ(run.exit_code, 0) << run.describe();
  const auto sections = testing::split_sections(run.out);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto it = sections.find(cases[k].name);
    ASSERT_NE(it, sections.end()) << cases[k].name << "\n" << run.describe();
    const std::vector<std::string>& lines = it->second;
    if (answers[k]) {
      ASSERT_EQ(lines.size(), 2u) << cases[k].name << "\n" << run.describe();
      EXPECT_EQ(lines[0], "0") << cases[k].name << ": a root before t = " << answers[k]->t;
      EXPECT_GE(std::stoi(lines[1]), 1) << cases[k].name << ": no root near t = " << answers[k]->t;
    } else {
      ASSERT_EQ(lines.size(), 1u) << cases[k].name << "\n" << run.describe();
      EXPECT_EQ(lines[0], "0") << cases[k].name << ": missed a root";
    }
  }
}

// The public surfaces at 256×256 from the seed's camera (eye (3, 3, 5) looking at the
// origin, focal distance 1: camera.hpp), t ∈ [0, 100]: every ray through the automatic
// path at relative tolerance 1e-12 (and, for the trade-off, 1e-9 and 1e-15), every 16th
// also through the exact path at 1e-12 (they must agree). Prints the numbers
// docs/render.md quotes. Times are wall-clock on a shared machine: the test asserts
// none of them.
TEST(RootIsolation, PublicSurfacesAt256x256) {
  const std::size_t size = 256, stride = 16;
  const Camera camera(CameraSpec(), size, size);
  std::vector<Ray> rays;
  for (std::size_t j = 0; j < size; ++j) {
    for (std::size_t i = 0; i < size; ++i) {
      rays.push_back(camera.ray_through(static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5));
    }
  }
  std::printf(
      "[render exact] %-21s %3s %5s %6s | automatic, us/ray (exact fallbacks) at tolerance    | exact  | max |t_auto - "
      "t_exact|\n",
      "surface", "deg", "terms", "hits");
  std::printf("[render exact] %-21s %3s %5s %6s | %-19s %-19s %-19s | us/ray | / max(1, t), at 1e-12\n", "", "", "", "",
              "1e-12", "1e-9", "1e-15");
  for (const testing::Surface& s :
       testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_public.json")) {
    const Polynomial f = implicitize(parse_parametrization(s.x, s.y, s.z)).implicit;
    const RayPolynomialContext context(f);
    std::vector<std::optional<RayRoot>> automatic(rays.size());
    std::array<double, 3> fallback_percent{}, micros{};
    std::array<RootIsolationStats, 3> stats;
    const std::array<double, 3> tolerances{1e-12, 1e-9, 1e-15};
    for (std::size_t m = 0; m < tolerances.size(); ++m) {
      RootIsolationParams options;
      options.relative_tolerance = tolerances[m];
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t k = 0; k < rays.size(); ++k) {
        const std::optional<RayRoot> r =
            first_ray_root(context, rays[k].origin, rays[k].direction, 0, 100, options, &stats[m]);
        if (m == 0) automatic[k] = r;
      }
      micros[m] = 1e6 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                  static_cast<double>(rays.size());
      fallback_percent[m] = 100.0 * static_cast<double>(stats[m].exact_rays) / static_cast<double>(stats[m].rays);
      EXPECT_EQ(stats[m].rays, rays.size());
    }
    double worst = 0;
    std::size_t sampled = 0;
    const auto exact_start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < rays.size(); k += stride) {
      BothPaths r;
      r.automatic = automatic[k];
      r.exact = first_ray_root(context, rays[k].origin, rays[k].direction, 0, 100, exact_only());
      ++sampled;
      EXPECT_TRUE(paths_agree(r)) << s.name << " pixel " << k;
      if (r.automatic && r.exact)
        worst = std::max(worst, std::fabs(r.automatic->t - r.exact->t) / std::max(1.0, r.exact->t));
    }
    const double exact_micros = 1e6 *
                                std::chrono::duration<double>(std::chrono::steady_clock::now() - exact_start).count() /
                                static_cast<double>(sampled);
    std::printf(
        "[render exact] %-21s %3d %5zu %6zu | %6.2f (%7.3f%%)   %6.2f (%7.3f%%)   %6.2f (%7.3f%%)  | %6.1f | %.2g\n",
        s.name.c_str(), f.total_degree(), f.num_terms(), stats[0].hits, micros[0], fallback_percent[0], micros[1],
        fallback_percent[1], micros[2], fallback_percent[2], exact_micros, worst);
    std::string reasons;
    for (std::size_t r = 1; r < kFallbackReasons; ++r) {
      if (stats[0].fallbacks[r] > 0) {
        reasons +=
            std::string(" ") + to_string(static_cast<FallbackReason>(r)) + "=" + std::to_string(stats[0].fallbacks[r]);
      }
    }
    if (!reasons.empty()) std::printf("[render exact] %-21s fallbacks at 1e-12:%s\n", s.name.c_str(), reasons.c_str());
  }
}

}  // namespace
}  // namespace implicitizer
