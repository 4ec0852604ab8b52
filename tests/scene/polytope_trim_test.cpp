// Tests of lib/src/scene/polytope_trim.cpp: the trimmed value is |d| inside the
// polytope and the box, never above the distance to any point of polytope ∩ box
// (float and double, at random points near and far, the set sampled by the test in
// long double), close to the true distance where a single plane decides it, and its
// box bound is below the value everywhere (what lets a union skip the piece).

#include "implicitizer/scene/polytope_trim.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace implicitizer {
namespace {

using P = std::array<long double, 3>;

// A thin tilted slab: the plane through (1, 2, 3) with normal (2, −1, 2)/3, the patch
// the square of half side 1 in it (edges along u = (1, 2, 0)/√5 and w = n × u), as
// six planes, in the box around that square.
struct Slab {
  TrimPolytope polytope;
  PatchBounds box;
  P centre{1, 2, 3}, n, u, w;
  long double thickness = 0.01L;
};

P cross(const P& a, const P& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
long double dot(const P& a, const P& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Slab make_slab() {
  Slab s;
  s.n = {2.0L / 3, -1.0L / 3, 2.0L / 3};
  s.u = {1 / std::sqrt(5.0L), 2 / std::sqrt(5.0L), 0};
  s.u = {s.u[0] - dot(s.u, s.n) * s.n[0], s.u[1] - dot(s.u, s.n) * s.n[1], s.u[2] - dot(s.u, s.n) * s.n[2]};
  const long double lu = std::sqrt(dot(s.u, s.u));
  s.u = {s.u[0] / lu, s.u[1] / lu, s.u[2] / lu};
  s.w = cross(s.n, s.u);
  for (const P& d :
       {s.n, P{-s.n[0], -s.n[1], -s.n[2]}, s.u, P{-s.u[0], -s.u[1], -s.u[2]}, s.w, P{-s.w[0], -s.w[1], -s.w[2]}}) {
    const std::array<double, 3> nd{double(d[0]), double(d[1]), double(d[2])};
    s.polytope.normals.push_back(nd);
    // The largest of nd·x over the slab's square and thickness, rounded up.
    long double top = -1e30L;
    for (int a : {-1, 1}) {
      for (int b : {-1, 1}) {
        for (int c : {-1, 1}) {
          P x;
          for (int i = 0; i < 3; ++i) x[i] = s.centre[i] + a * s.u[i] + b * s.w[i] + c * s.thickness / 2 * s.n[i];
          top = std::max(top, nd[0] * x[0] + nd[1] * x[1] + nd[2] * x[2]);
        }
      }
    }
    s.polytope.offsets.push_back(double(top + 1e-15L));
  }
  for (int i = 0; i < 3; ++i) {
    const long double reach = std::abs(s.u[i]) + std::abs(s.w[i]) + s.thickness / 2 * std::abs(s.n[i]);
    s.box.lo.push_back(Rational(double(s.centre[i] - reach - 1e-12L)));
    s.box.hi.push_back(Rational(double(s.centre[i] + reach + 1e-12L)));
  }
  return s;
}

// Points of the slab's square (the middle sheet) on a 41×41 grid.
std::vector<P> square_points(const Slab& s) {
  std::vector<P> points;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) {
      const long double a = -1 + i / 20.0L, b = -1 + j / 20.0L;
      points.push_back({s.centre[0] + a * s.u[0] + b * s.w[0], s.centre[1] + a * s.u[1] + b * s.w[1],
                        s.centre[2] + a * s.u[2] + b * s.w[2]});
    }
  }
  return points;
}

long double distance(const P& a, const P& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(PolytopeTrim, IsTheDistanceEstimateOnThePatch) {
  const Slab s = make_slab();
  const PolytopeTrim trim(s.polytope, s.box);
  for (const P& x : square_points(s)) {
    const Vec3<float> pf{float(x[0]), float(x[1]), float(x[2])};
    const Vec3<double> pd{double(x[0]), double(x[1]), double(x[2])};
    EXPECT_EQ(trim.distance_lower_bound(pf, -0.25f), 0.25f);
    EXPECT_EQ(trim.distance_lower_bound(pd, 0.0), 0.0);
  }
}

TEST(PolytopeTrim, NeverExceedsTheDistanceToTheTrimmedRegion) {
  const Slab s = make_slab();
  const PolytopeTrim trim(s.polytope, s.box);
  const std::vector<P> inside = square_points(s);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> near(-2, 2), far(-50, 50);
  for (int k = 0; k < 3000; ++k) {
    const bool is_far = k % 3 == 0;
    const P p{s.centre[0] + (is_far ? far(random) : near(random)), s.centre[1] + (is_far ? far(random) : near(random)),
              s.centre[2] + (is_far ? far(random) : near(random))};
    long double nearest = 1e30L;
    for (const P& x : inside) nearest = std::min(nearest, distance(p, x));
    const float vf = trim.distance_lower_bound(Vec3<float>{float(p[0]), float(p[1]), float(p[2])}, 0.0f);
    const double vd = trim.distance_lower_bound(Vec3<double>{double(p[0]), double(p[1]), double(p[2])}, 0.0);
    EXPECT_LE(vf, nearest);
    EXPECT_LE(vd, nearest);
    EXPECT_LE(trim.hull_distance_lower_bound(Vec3<float>{float(p[0]), float(p[1]), float(p[2])}), vf);
    // Straight above the square's middle only the top plane matters: the bound is
    // the height above the slab, to float's slack.
  }
  const P above{s.centre[0] + 0.5L * s.n[0], s.centre[1] + 0.5L * s.n[1], s.centre[2] + 0.5L * s.n[2]};
  const float v = trim.distance_lower_bound(Vec3<float>{float(above[0]), float(above[1]), float(above[2])}, 0.0f);
  EXPECT_NEAR(v, 0.5 - double(s.thickness) / 2, 1e-4);
}

TEST(PolytopeTrim, GlslStatesThePlanesThreeAtATimeAndTheBox) {
  const Slab s = make_slab();
  const PolytopeTrim trim(s.polytope, s.box);
  const std::string glsl = trim.to_glsl("piece_trim");
  EXPECT_NE(glsl.find("float piece_trim(vec3 p, float d) {"), std::string::npos);
  EXPECT_EQ(std::count(glsl.begin(), glsl.end(), '\n'), 9);
  EXPECT_NE(trim.hull_glsl("p").find("sqrt(dot("), std::string::npos);
}

TEST(PolytopeTrim, RefusesNoPlanesTooManyPlanesAndAPlaneBox) {
  const PatchBounds box{{Rational(0), Rational(0), Rational(0)}, {Rational(1), Rational(1), Rational(1)}};
  EXPECT_THROW(PolytopeTrim(TrimPolytope{}, box), std::invalid_argument);
  TrimPolytope many;
  many.normals.assign(PolytopeTrim::kMaxPlanes + 1, {1, 0, 0});
  many.offsets.assign(PolytopeTrim::kMaxPlanes + 1, 0);
  EXPECT_THROW(PolytopeTrim(many, box), std::invalid_argument);
  TrimPolytope one;
  one.normals.assign(1, {1, 0, 0});
  one.offsets.assign(1, 0);
  EXPECT_THROW(PolytopeTrim(one, PatchBounds{{Rational(0), Rational(0)}, {Rational(1), Rational(1)}}),
               std::invalid_argument);
  // One plane is padded to a group of three in the GLSL.
  EXPECT_NE(PolytopeTrim(one, box).to_glsl("f").find("polytope of 3 planes"), std::string::npos);
}

}  // namespace
}  // namespace implicitizer
