// The primitives against distances computed independently (closest points found by
// other means: clamping per axis, segments in the 2D profile, root finding for the
// ellipsoid), at many points, in double.

#include "implicitizer/scene/primitives.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace implicitizer {
namespace {

using V = Vec3<double>;

std::vector<V> sample(std::size_t n, double lo, double hi, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> c(lo, hi);
  std::vector<V> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back({c(random), c(random), c(random)});
  return out;
}

double norm(const V& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

// Distance from (x, y) to the 2D segment [a, b].
double segment_distance_2d(double x, double y, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double t = std::clamp(((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

constexpr double kExact = 1e-12;

TEST(Primitives, SphereIsTheDistance) {
  for (const V& p : sample(2000, -3, 3, 1)) EXPECT_NEAR(sdf_sphere(p, 1.25), norm(p) - 1.25, kExact);
}

TEST(Primitives, BoxIsTheDistance) {
  const V b{1.0, 0.5, 2.0};
  for (const V& p : sample(4000, -4, 4, 2)) {
    // Outside: distance to the clamped point; inside: to the nearest face.
    const V c{std::clamp(p.x, -b.x, b.x), std::clamp(p.y, -b.y, b.y), std::clamp(p.z, -b.z, b.z)};
    const bool inside = std::fabs(p.x) <= b.x && std::fabs(p.y) <= b.y && std::fabs(p.z) <= b.z;
    const double expected =
        inside ? -std::min({b.x - std::fabs(p.x), b.y - std::fabs(p.y), b.z - std::fabs(p.z)}) : norm(p - c);
    EXPECT_NEAR(sdf_box(p, b), expected, kExact) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(Primitives, RoundBoxIsTheDistanceToTheInnerBoxMinusTheRadius) {
  const V b{1.0, 0.5, 2.0};
  const double r = 0.25;
  const V inner{b.x - r, b.y - r, b.z - r};
  for (const V& p : sample(4000, -4, 4, 3)) {
    EXPECT_NEAR(sdf_round_box(p, b, r), sdf_box(p, inner) - r, kExact);
  }
  // On the flat part of a face the rounding does not matter: distance to the face.
  EXPECT_NEAR(sdf_round_box(V{0, 0, 3}, b, r), 1.0, kExact);
  // Off a corner: distance to the corner sphere of the inner box.
  EXPECT_NEAR(sdf_round_box(V{2, 2, 3}, b, r), norm(V{2, 2, 3} - inner) - r, kExact);
}

TEST(Primitives, TorusAroundZIsTheDistanceToItsCoreCircleMinusTheTube) {
  // The nearest point of the core circle found by sampling 2000 angles, then a
  // ternary search between the best sample's neighbours (the distance is unimodal
  // there).
  const double major = 2, minor = 0.5;
  for (const V& p : sample(500, -3, 3, 4)) {
    const auto at = [&](double t) { return norm(p - V{major * std::cos(t), major * std::sin(t), 0}); };
    const double step = 2 * M_PI / 2000;
    double best = 0;
    for (int i = 1; i < 2000; ++i) {
      if (at(i * step) < at(best)) best = i * step;
    }
    double lo = best - step, hi = best + step;
    for (int i = 0; i < 200; ++i) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (at(m1) < at(m2))
        hi = m2;
      else
        lo = m1;
    }
    EXPECT_NEAR(sdf_torus(p, major, minor), at((lo + hi) / 2) - minor, 1e-12);
  }
  EXPECT_NEAR(sdf_torus(V{2, 0, 0}, major, minor), -0.5, kExact);                  // on the core circle
  EXPECT_NEAR(sdf_torus(V{0, 0, 0}, major, minor), 1.5, kExact);                   // the hole's centre
  EXPECT_NEAR(sdf_torus(V{0, 3, 0}, major, minor), 0.5, kExact);                   // in the xy plane, outside
  EXPECT_NEAR(sdf_torus(V{0, 0, 2}, major, minor), std::sqrt(8.0) - 0.5, kExact);  // on the axis
}

TEST(Primitives, PlaneIsTheSignedDistanceToTheHalfSpace) {
  const V n = V{1, 2, 2} / 3.0;
  for (const V& p : sample(1000, -3, 3, 5)) EXPECT_NEAR(sdf_plane(p, n, 0.5), dot(p, n) - 0.5, kExact);
  EXPECT_NEAR(sdf_plane(V{1, 2, 2}, n, 0.5), 2.5, kExact);
}

TEST(Primitives, CapsuleIsTheDistanceToItsSegmentMinusTheRadius) {
  const V a{-1, 0.5, 0}, b{1, -0.5, 1};
  for (const V& p : sample(2000, -3, 3, 6)) {
    // Closest point by minimising |p - (a + t(b - a))|² over t ∈ [0, 1] with a
    // ternary search (the function is convex in t).
    double lo = 0, hi = 1;
    const auto f = [&](double t) { return norm(p - (a + (b - a) * t)); };
    for (int i = 0; i < 200; ++i) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (f(m1) < f(m2))
        hi = m2;
      else
        lo = m1;
    }
    EXPECT_NEAR(sdf_capsule(p, a, b, 0.3), f((lo + hi) / 2) - 0.3, 1e-9);
  }
  // a = b is a sphere, not 0/0.
  EXPECT_NEAR(sdf_capsule(V{0, 3, 4}, V{0, 0, 0}, V{0, 0, 0}, 1.0), 4.0, kExact);
}

TEST(Primitives, ConeIsTheDistanceToTheSolidOfRevolutionOfItsProfile) {
  // Profile in (ρ, z): the triangle (0, 0), (R, 0), (0, h), R = h·tan θ. The surface
  // is swept by the slanted side and the base; inside means z ≥ 0, ρ ≤ R(1 − z/h).
  const double angle = 0.5, h = 1.5, radius = h * std::tan(angle);
  for (const V& p : sample(4000, -2.5, 2.5, 7)) {
    const double rho = std::hypot(p.x, p.y), z = p.z;
    const double side = segment_distance_2d(rho, z, 0, h, radius, 0);
    const double base = segment_distance_2d(rho, z, 0, 0, radius, 0);
    const bool inside = z >= 0 && z <= h && rho <= radius * (1 - z / h);
    const double expected = inside ? -std::min(side, base) : std::min(side, base);
    EXPECT_NEAR(sdf_cone(p, h, h * std::tan(angle), -h), expected, 1e-12) << p.x << " " << p.y << " " << p.z;
  }
  EXPECT_NEAR(sdf_cone(V{0, 0, 2}, h, radius, -h), 0.5, kExact);   // above the apex
  EXPECT_NEAR(sdf_cone(V{0, 0, -1}, h, radius, -h), 1.0, kExact);  // below the base
}

TEST(Primitives, CylinderIsTheDistanceToTheAxisMinusTheRadius) {
  for (const V& p : sample(1000, -3, 3, 8)) {
    EXPECT_NEAR(sdf_cylinder(p, 0.75), std::hypot(p.x, p.y) - 0.75, kExact);
  }
}

// Distance from p to the ellipsoid surface with radii r: the closest point is
// x_i = r_i²·p_i/(t + r_i²) with t the root of Σ (r_i·p_i/(t + r_i²))² = 1 on
// (−min r_i², ∞), where the left side decreases from +∞ to 0 (|p_i| > 0 on the
// smallest axis); bisection to double precision.
double ellipsoid_distance(const V& p, const V& r) {
  const double rr[3] = {r.x * r.x, r.y * r.y, r.z * r.z};
  const double q[3] = {std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)};
  const auto f = [&](double t) {
    double s = 0;
    for (int i = 0; i < 3; ++i) {
      const double v = std::sqrt(rr[i]) * q[i] / (t + rr[i]);
      s += v * v;
    }
    return s - 1;
  };
  double lo = -std::min({rr[0], rr[1], rr[2]}), hi = 1;
  while (f(hi) > 0) hi *= 2;
  for (int i = 0; i < 300; ++i) {
    const double m = (lo + hi) / 2;
    if (m == lo || m == hi) break;
    (f(m) > 0 ? lo : hi) = m;
  }
  const double t = (lo + hi) / 2;
  double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double x = rr[i] * q[i] / (t + rr[i]);
    d2 += (q[i] - x) * (q[i] - x);
  }
  return std::sqrt(d2);
}

TEST(Primitives, SafeEllipsoidIsABoundWithTheRightSign) {
  const V r{2.0, 1.0, 0.5};
  std::size_t points = 0;
  double worst_ratio = 1;  // smallest |bound| / distance: how conservative it gets
  for (const V& p : sample(4000, -3, 3, 9)) {
    const double inside = (p.x / r.x) * (p.x / r.x) + (p.y / r.y) * (p.y / r.y) + (p.z / r.z) * (p.z / r.z) - 1;
    const double distance = ellipsoid_distance(p, r);
    const double bound = sdf_ellipsoid_bound(p, r);
    EXPECT_EQ(bound < 0, inside < 0);
    EXPECT_LE(std::fabs(bound), distance * (1 + 1e-12) + 1e-12) << p.x << " " << p.y << " " << p.z;
    if (distance > 1e-3) worst_ratio = std::min(worst_ratio, std::fabs(bound) / distance);
    ++points;
  }
  EXPECT_EQ(points, 4000u);
  EXPECT_GT(worst_ratio, 0.0);
  // On a sphere the bound is the distance.
  for (const V& p : sample(200, -3, 3, 10)) {
    EXPECT_NEAR(sdf_ellipsoid_bound(p, V{1.5, 1.5, 1.5}), norm(p) - 1.5, kExact);
    EXPECT_NEAR(sdf_ellipsoid_estimate(p, V{1.5, 1.5, 1.5}), norm(p) - 1.5, 1e-12);
  }
  // The estimate is not a bound: somewhere it exceeds the distance.
  bool overshoots = false;
  for (const V& p : sample(4000, -3, 3, 11)) {
    if (std::fabs(sdf_ellipsoid_estimate(p, r)) > ellipsoid_distance(p, r) * (1 + 1e-6)) overshoots = true;
  }
  EXPECT_TRUE(overshoots);
  // Never NaN at the centre.
  EXPECT_FALSE(std::isnan(sdf_ellipsoid_estimate(V{0, 0, 0}, r)));
}

TEST(Primitives, FloatTwinsStayWithinAFewUlpsOfDouble) {
  // The float runs are what the GPU computes; they must not lose more than rounding.
  for (const V& p : sample(500, -3, 3, 12)) {
    const Vec3<float> q{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
    const V pd{q.x, q.y, q.z};
    EXPECT_NEAR(sdf_torus(q, 2.0f, 0.5f), sdf_torus(pd, 2.0, 0.5), 1e-6);
    EXPECT_NEAR(sdf_box(q, Vec3<float>{1, 0.5f, 2}), sdf_box(pd, V{1, 0.5, 2}), 1e-6);
  }
}

}  // namespace
}  // namespace implicitizer
