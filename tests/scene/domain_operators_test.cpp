// The domain operators on their own (lib/src/scene/domain_operators.cpp): the fast
// formulas at hand-computed points; the safe values against true distances (dense
// samples of the warped surface, refined, for twist, bend and displacement; closed
// forms of spheres and boxes for round, elongate, symmetry and repetition); the
// constants of the proofs checked numerically (Jacobian norms); the GLSL compiled
// by glslangValidator in both dialects and run on llvmpipe against the C++ float
// twin; then the operators as node kinds of a scene (classes, refusals, bounding
// boxes, uniforms). Lines starting with "[measure]" are the numbers docs/sdf.md quotes.

#include "implicitizer/scene/domain_operators.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/scene/compiled_scene.hpp"
#include "implicitizer/scene/primitives.hpp"
#include "scene/scene_support.hpp"
#include "sdf/gles_runner.hpp"
#include "sdf/sdf_support.hpp"

namespace implicitizer {
namespace {

using V = Vec3<double>;
using F = Vec3<float>;
constexpr double kPi = 3.14159265358979323846;
constexpr double kFloatEps = 1.0 / 16777216.0;  // 2^-24

double norm(const V& v) { return length(v); }
F to_float(const V& v) { return {float(v.x), float(v.y), float(v.z)}; }
V to_double(const F& v) { return {v.x, v.y, v.z}; }

// GLSL literals of exactly the float the C++ float twin uses.
std::string lit(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.8e", static_cast<double>(static_cast<float>(x)));
  return buffer;
}
std::string lit(const V& v) { return "vec3(" + lit(v.x) + ", " + lit(v.y) + ", " + lit(v.z) + ")"; }

// ---------------------------------------------------------------------------
// Children: a sphere or a box (exact distances, 1-Lipschitz) at a centre.
// ---------------------------------------------------------------------------

struct Child {
  bool is_box = false;
  V centre{};
  V size{};  // box half extents
  double radius = 0;

  template <typename T>
  T value(const Vec3<T>& p) const {
    const Vec3<T> c{T(centre.x), T(centre.y), T(centre.z)};
    if (is_box) return sdf_box(p - c, Vec3<T>{T(size.x), T(size.y), T(size.z)});
    return sdf_sphere(p - c, T(radius));
  }
  // `float t_child(vec3 p)`, the same operations as value<float>.
  std::string glsl() const {
    std::string out = is_box ? box_glsl("t") : sphere_glsl("t");
    out += "float t_child(vec3 p) {\n  return ";
    out += is_box ? "t_box(p - " + lit(centre) + ", " + lit(size) + ");\n}\n"
                  : "t_sphere(p - " + lit(centre) + ", " + lit(radius) + ");\n}\n";
    return out;
  }
  V lo() const { return is_box ? centre - size : centre - V{radius, radius, radius}; }
  V hi() const { return is_box ? centre + size : centre + V{radius, radius, radius}; }
  int patches() const { return is_box ? 6 : 1; }
  // The surface: patch `k`, (u, v) ∈ [0, 1]².
  V surface(int k, double u, double v) const {
    if (!is_box) {
      const double theta = kPi * u, phi = 2 * kPi * v;
      return centre + V{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)} * radius;
    }
    const int axis = k / 2;
    const double side = k % 2 == 0 ? -1.0 : 1.0;
    const double b[3] = {size.x, size.y, size.z};
    double c[3] = {0, 0, 0};
    c[axis] = side * b[axis];
    c[(axis + 1) % 3] = (2 * u - 1) * b[(axis + 1) % 3];
    c[(axis + 2) % 3] = (2 * v - 1) * b[(axis + 2) % 3];
    return centre + V{c[0], c[1], c[2]};
  }
};

Child sphere(V centre, double r) { return Child{false, centre, {}, r}; }
Child box(V centre, V size) { return Child{true, centre, size, 0}; }

// ---------------------------------------------------------------------------
// A surface known by a parametrization: its distance by dense sampling, then the
// best samples refined by pattern search in the parameters (the value is the
// distance to a point of the surface, so at least the true distance; the refinement
// makes it equal up to ~1e-10 when the samples are dense enough to find the basin).
// ---------------------------------------------------------------------------

class SampledSurface {
 public:
  using Map = std::function<V(int, double, double)>;

  SampledSurface(int patches, Map map, int n) : map_(std::move(map)), step_(1.0 / n) {
    for (int k = 0; k < patches; ++k) {
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
          const double u = double(i) / n, v = double(j) / n;
          points_.push_back(map_(k, u, v));
          params_.push_back({double(k), u, v});
        }
      }
    }
  }

  double distance(const V& p) const {
    std::vector<std::pair<double, std::size_t>> d(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const V e = points_[i] - p;
      d[i] = {dot(e, e), i};
    }
    const std::size_t keep = std::min<std::size_t>(8, d.size());
    std::partial_sort(d.begin(), d.begin() + std::ptrdiff_t(keep), d.end());
    double best = std::sqrt(d[0].first);
    for (std::size_t i = 0; i < keep; ++i) best = std::min(best, refine(params_[d[i].second], p));
    return best;
  }

  const std::vector<V>& points() const { return points_; }

 private:
  double refine(const std::array<double, 3>& start, const V& p) const {
    const int k = int(start[0]);
    double u = start[1], v = start[2];
    const auto d2 = [&](double a, double b) {
      const V e = map_(k, a, b) - p;
      return dot(e, e);
    };
    double best = d2(u, v);
    for (double h = step_; h > 1e-13;) {
      bool moved = false;
      for (int du = -1; du <= 1; ++du) {
        for (int dv = -1; dv <= 1; ++dv) {
          if (du == 0 && dv == 0) continue;
          const double a = std::clamp(u + du * h, 0.0, 1.0), b = std::clamp(v + dv * h, 0.0, 1.0);
          const double t = d2(a, b);
          if (t < best) {
            best = t;
            u = a;
            v = b;
            moved = true;
          }
        }
      }
      // Grow the step after a move (the start may be a few samples away from the
      // minimum), halve it when no neighbour is better.
      h = moved ? std::min(2 * h, step_) : 0.5 * h;
    }
    return std::sqrt(best);
  }

  Map map_;
  double step_;
  std::vector<V> points_;
  std::vector<std::array<double, 3>> params_;
};

// Points to test: uniform in [lo, hi], and near the surface (a sample moved by
// 1e-3 to 0.5 in a random direction).
std::vector<V> test_points(const SampledSurface& surface, const V& lo, const V& hi, int uniform, int near,
                           unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> normal;
  std::vector<V> out;
  for (int i = 0; i < uniform; ++i) {
    out.push_back({lo.x + (hi.x - lo.x) * unit(random), lo.y + (hi.y - lo.y) * unit(random),
                   lo.z + (hi.z - lo.z) * unit(random)});
  }
  const auto& s = surface.points();
  for (int i = 0; i < near; ++i) {
    const V base = s[std::size_t(unit(random) * double(s.size() - 1))];
    V dir{normal(random), normal(random), normal(random)};
    dir = dir / norm(dir);
    out.push_back(base + dir * std::pow(10.0, -3 + 2.7 * unit(random)));
  }
  return out;
}

// What a safe value achieved against the true distance.
struct Tightness {
  int points = 0, violations = 0, wrong_signs = 0;
  std::vector<double> ratios;  // |safe| / true
  double fast_over = 0;        // max |fast| / true
  void add(double safe, double fast, double truth, double child_sign_value) {
    ++points;
    if (std::abs(safe) > truth * (1 + 1e-9) + 1e-9) ++violations;
    if (std::abs(child_sign_value) > 1e-9 && (safe < 0) != (child_sign_value < 0)) ++wrong_signs;
    if (truth > 1e-6) {
      ratios.push_back(std::abs(safe) / truth);
      fast_over = std::max(fast_over, std::abs(fast) / truth);
    }
  }
  void report(const std::string& name) {
    std::sort(ratios.begin(), ratios.end());
    std::cout << "[measure] " << name << ": " << points << " points, safe/true min " << ratios.front() << " median "
              << ratios[ratios.size() / 2] << " max " << ratios.back() << "; fast/true max " << fast_over << "\n";
  }
};

// ---------------------------------------------------------------------------
// Fast formulas at hand-computed points.
// ---------------------------------------------------------------------------

void expect_near(const V& a, const V& b, double tolerance = 1e-15) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(DomainOperators, TwistAboutYWithoutSwap) {
  // k = 0 is the identity (the seeds' R_z(ky)·(x, z, y) would swap y and z).
  expect_near(twist_point(V{1, 2, 3}, 0.0), V{1, 2, 3});
  // k·y = π/2: (x, z) rotated by 90°: (−z, x).
  expect_near(twist_point(V{1, 1, 0}, kPi / 2), V{0, 1, 1});
  expect_near(twist_point(V{2, 1, 0.5}, kPi / 2), V{-0.5, 1, 2});
  // k·y = π/4: c = s = √2/2: (√2/2·(2 − 1), 0.5, √2/2·(2 + 1)).
  const double h = std::sqrt(0.5);
  expect_near(twist_point(V{2, 0.5, 1}, kPi / 2), V{h, 0.5, 3 * h});
  // A unit sphere's fast value there: |q| − 1.
  EXPECT_NEAR(sdf_sphere(twist_point(V{2, 0.5, 1}, kPi / 2), 1.0), std::sqrt(0.5 + 0.25 + 4.5) - 1, 1e-15);
}

TEST(DomainOperators, BendInTheXyPlane) {
  expect_near(bend_point(V{1, 2, 3}, 0.0), V{1, 2, 3});
  // k·x = π/2: (x, y) → (−y, x).
  expect_near(bend_point(V{1, 2, 3}, kPi / 2), V{-2, 1, 3});
  // k·x = π: (x, y) → (−x, −y).
  expect_near(bend_point(V{0.5, -1, 7}, 2 * kPi), V{-0.5, 1, 7});
}

TEST(DomainOperators, RoundElongateSymmetry) {
  EXPECT_EQ(round_value(0.75, 0.25), 0.5);
  expect_near(elongate_point(V{3, 0.5, -1}, V{1, 0, 2}), V{2, 0.5, 0});
  expect_near(elongate_point(V{-3, 0.5, -2.5}, V{1, 0, 2}), V{-2, 0.5, -0.5});
  expect_near(mirror_point(V{-1, -2, -3}, AxisSet{true, false, true}), V{1, -2, 3});
  expect_near(mirror_point(V{-1, -2, -3}, AxisSet{false, true, false}), V{-1, 2, -3});
  // Safe elongation of a unit sphere by h = (1, 2, 3) at the origin: inside the core
  // box, 1 + (distance to the box's boundary = 1) deep; fast says only −1.
  EXPECT_EQ(elongate_bound(V{0, 0, 0}, V{1, 2, 3}, sdf_sphere(elongate_point(V{0, 0, 0}, V{1, 2, 3}), 1.0)), -2.0);
  EXPECT_EQ(sdf_sphere(elongate_point(V{0, 0, 0}, V{1, 2, 3}), 1.0), -1.0);
}

TEST(DomainOperators, RepetitionCellsRoundHalfUp) {
  const V s{3, 0, 0};
  const AxisSet x{true, false, false};
  expect_near(repeat_point(V{4.4, 1, 2}, s, x), V{4.4 - 3, 1, 2}, 1e-15);
  expect_near(repeat_point(V{-4.6, 1, 2}, s, x), V{-4.6 + 6, 1, 2}, 1e-15);
  // Ties go up in both back ends: floor(x + 0.5).
  expect_near(repeat_point(V{1.5, 0, 0}, s, x), V{-1.5, 0, 0});
  expect_near(repeat_point(V{-1.5, 0, 0}, s, x), V{-1.5, 0, 0});
  // Finite: copies −2..2, so x = 10 maps to the copy at 6.
  expect_near(repeat_finite_point(V{10, 0, 0}, s, V{2, 0, 0}, x), V{4, 0, 0});
  expect_near(repeat_finite_point(V{-10, 5, 0}, s, V{2, 0, 0}, x), V{-4, 5, 0});
  // Cells of the safe version: cell 0 is the own one, cell 1 the neighbour on p's side.
  expect_near(repeat_cell_point(V{4.4, 0, 0}, s, x, 0), V{4.4 - 3, 0, 0}, 1e-15);
  expect_near(repeat_cell_point(V{4.4, 0, 0}, s, x, 1), V{4.4 - 6, 0, 0}, 1e-15);
  expect_near(repeat_cell_point(V{2.6, 0, 0}, s, x, 1), V{2.6, 0, 0}, 1e-15);
  // At the last copy the neighbour beyond does not exist: the own cell again.
  expect_near(repeat_finite_cell_point(V{7, 0, 0}, s, V{2, 0, 0}, x, 1), V{1, 0, 0});
  // Two axes: cell 3 moves both.
  expect_near(repeat_cell_point(V{1, 0, -1}, V{3, 0, 3}, AxisSet{true, false, true}, 3), V{-2, 0, 2});
}

TEST(DomainOperators, DisplacementFormula) {
  // sin(π/2)³ = 1: the value rises by a.
  EXPECT_NEAR(displace_value(V{0.5, 0.5, 0.5}, 0.1, kPi, 0.25), 0.35, 1e-15);
  EXPECT_NEAR(displace_value(V{0.5, -0.5, 0.5}, 0.1, kPi, 0.25), 0.15, 1e-15);
  EXPECT_NEAR(displace_bound(V{0.5, -0.5, 0.5}, 0.1, kPi, 0.25), 0.15 / (1 + 0.1 * kPi), 1e-15);
}

// ---------------------------------------------------------------------------
// The constants of the proofs, checked numerically.
// ---------------------------------------------------------------------------

// The largest singular value of the Jacobian of `map` at p: central differences,
// then the largest eigenvalue of JᵀJ by cyclic Jacobi rotations (power iteration
// converges too slowly when the two largest singular values are close).
double jacobian_norm(const std::function<V(const V&)>& map, const V& p) {
  const double h = 1e-6;
  V columns[3];
  const V e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i) columns[i] = (map(p + e[i] * h) - map(p - e[i] * h)) / (2 * h);
  double a[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a[i][j] = dot(columns[i], columns[j]);
  }
  for (int sweep = 0; sweep < 50; ++sweep) {
    for (int i = 0; i < 3; ++i) {
      for (int j = i + 1; j < 3; ++j) {
        if (std::abs(a[i][j]) < 1e-300) continue;
        const double theta = 0.5 * std::atan2(2 * a[i][j], a[j][j] - a[i][i]);
        const double c = std::cos(theta), s = std::sin(theta);
        for (int k = 0; k < 3; ++k) {  // columns i, j
          const double aki = a[k][i], akj = a[k][j];
          a[k][i] = c * aki - s * akj;
          a[k][j] = s * aki + c * akj;
        }
        for (int k = 0; k < 3; ++k) {  // rows i, j
          const double aik = a[i][k], ajk = a[j][k];
          a[i][k] = c * aik - s * ajk;
          a[j][k] = s * aik + c * ajk;
        }
      }
    }
  }
  return std::sqrt(std::max(a[0][0], std::max(a[1][1], a[2][2])));
}

TEST(DomainOperators, TwistJacobianNormIsExactlyTheProofsConstant) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-3, 3);
  double worst = 0, column_short = 1e9;
  for (int i = 0; i < 300; ++i) {
    const V p{coordinate(random), coordinate(random), coordinate(random)};
    const double k = 0.5 * coordinate(random);
    const double a = std::abs(k) * std::sqrt(p.x * p.x + p.z * p.z);
    const double proof = (a + std::sqrt(a * a + 4)) / 2;
    const double actual = jacobian_norm([k](const V& q) { return twist_point(q, k); }, p);
    worst = std::max(worst, std::abs(actual - proof) / proof);
    // sqrt(1 + a²), the norm of one column, is too small wherever a > 0.
    if (a > 0.1) column_short = std::min(column_short, actual / std::sqrt(1 + a * a));
  }
  EXPECT_LT(worst, 1e-7);
  EXPECT_GT(column_short, 1.0);
  std::cout << "[measure] twist: |J| = (a + sqrt(a^2 + 4))/2 within " << worst
            << " relative at 300 points; |J| / sqrt(1 + a^2) >= " << column_short << " (a > 0.1)\n";
}

TEST(DomainOperators, BendJacobianNormIsAtMostOnePlusKRho) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> coordinate(-3, 3);
  double worst = 0;
  for (int i = 0; i < 300; ++i) {
    V p{coordinate(random), coordinate(random), coordinate(random)};
    const double k = 0.5 * coordinate(random);
    // Where the bound is attained: x = 0 and k·y < 0 (|Jv|² = v_x²(1 − ky)² + v_y² there).
    if (i % 3 == 0) {
      p.x = 0;
      if (k * p.y > 0) p.y = -p.y;
    }
    const double bound = 1 + std::abs(k) * std::sqrt(p.x * p.x + p.y * p.y);
    const double actual = jacobian_norm([k](const V& q) { return bend_point(q, k); }, p);
    EXPECT_LE(actual, bound * (1 + 1e-7));
    if (i % 3 == 0) {
      EXPECT_NEAR(actual, bound, 1e-6 * bound);
    }
    worst = std::max(worst, actual / bound);
  }
  std::cout << "[measure] bend: max |J| / (1 + |k| rho) = " << worst << " at 300 points (= 1 where x = 0, ky < 0)\n";
}

TEST(DomainOperators, DisplacementIsExactlyAOmegaLipschitz) {
  // |∇δ| / |aω| over a dense grid of one period: at most 1, and 1 is reached.
  const double a = 0.3, w = 2.0;
  double worst = 0;
  const int n = 60;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      for (int k = 0; k <= n; ++k) {
        const V p = V{double(i), double(j), double(k)} * (kPi / w / n);
        const double sx = std::sin(w * p.x), sy = std::sin(w * p.y), sz = std::sin(w * p.z);
        const double cx = std::cos(w * p.x), cy = std::cos(w * p.y), cz = std::cos(w * p.z);
        const V gradient = V{cx * sy * sz, sx * cy * sz, sx * sy * cz} * (a * w);
        worst = std::max(worst, norm(gradient) / std::abs(a * w));
      }
    }
  }
  EXPECT_LE(worst, 1 + 1e-12);
  EXPECT_GE(worst, 1 - 1e-12);
  std::cout << "[measure] displacement: max |grad delta| / |a w| = " << worst << " on a 61^3 grid\n";
}

// ---------------------------------------------------------------------------
// Safe values never exceed the true distance: warps.
// ---------------------------------------------------------------------------

// The preimage of a child point c under the twist: (x, z) = R(−k·c_y)(c_x, c_z).
V twist_preimage(const V& c, double k) {
  const double co = std::cos(k * c.y), si = std::sin(k * c.y);
  return {co * c.x + si * c.z, c.y, -si * c.x + co * c.z};
}

// The preimage under the bend when |k|·ρ < 1 (then x ↦ x − cos(kx)c_x − sin(kx)c_y is
// increasing, one root in [−ρ, ρ]): safeguarded Newton.
V bend_preimage(const V& c, double k) {
  const double rho = std::sqrt(c.x * c.x + c.y * c.y);
  double lo = -rho - 1e-12, hi = rho + 1e-12, x = std::clamp(c.x, lo, hi);
  for (int it = 0; it < 100; ++it) {
    const double h = x - std::cos(k * x) * c.x - std::sin(k * x) * c.y;
    if (std::abs(h) <= 1e-15) break;
    (h < 0 ? lo : hi) = x;
    const double dh = 1 + k * std::sin(k * x) * c.x - k * std::cos(k * x) * c.y;
    double next = x - h / dh;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) < 1e-16) break;
    x = next;
  }
  return {x, -std::sin(k * x) * c.x + std::cos(k * x) * c.y, c.z};
}

TEST(DomainOperators, SampledReferenceFindsExactDistances) {
  // The reference of the warp tests, without a warp: it must find the exact distances
  // of a box and a sphere (else the warp tests would compare with the wrong thing).
  const Child b = box({0.1, -0.2, 0.3}, {0.5, 1.5, 0.3}), s = sphere({0.8, 0, 0}, 0.5);
  const SampledSurface box_surface(
      6, [&](int k, double u, double v) { return b.surface(k, u, v); }, 100);
  const SampledSurface sphere_surface(
      1, [&](int k, double u, double v) { return s.surface(k, u, v); }, 240);
  double worst = 0;
  for (const V& p : test_points(box_surface, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5}, 100, 100, 10)) {
    worst = std::max(worst, std::abs(box_surface.distance(p) - std::abs(b.value(p))));
    worst = std::max(worst, std::abs(sphere_surface.distance(p) - std::abs(s.value(p))));
  }
  EXPECT_LT(worst, 1e-9);
  std::cout << "[measure] sampled reference vs exact box/sphere distance: max error " << worst << "\n";
}

TEST(DomainOperators, SafeTwistNeverExceedsTheTrueDistance) {
  struct Case {
    Child child;
    double k;
  };
  const Case cases[] = {{box({0, 0, 0}, {0.5, 1.5, 0.3}), 1.2},
                        {sphere({0.8, 0, 0}, 0.5), 2.0},
                        {box({0.3, 0.2, -0.4}, {0.6, 0.8, 0.2}), -0.7}};
  for (const Case& c : cases) {
    const SampledSurface surface(
        c.child.patches(),
        [&](int patch, double u, double v) { return twist_preimage(c.child.surface(patch, u, v), c.k); },
        c.child.is_box ? 100 : 240);
    std::vector<V> points = test_points(surface, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5}, 250, 250, 11);
    for (double far : {6.0, 12.0, 25.0}) points.push_back(V{far, 0.3 * far, -0.2 * far});
    Tightness t;
    for (const V& p : points) {
      const double d = c.child.value(twist_point(p, c.k));
      t.add(twist_bound(p, c.k, d), d, surface.distance(p), d);
    }
    EXPECT_EQ(t.violations, 0);
    EXPECT_EQ(t.wrong_signs, 0);
    t.report("twist k=" + std::to_string(c.k) + (c.child.is_box ? " box" : " sphere"));
  }
}

TEST(DomainOperators, SafeBendNeverExceedsTheTrueDistance) {
  struct Case {
    Child child;
    double k;
  };
  // |k|·ρ < 1 on the child's surface, so the preimage is one point.
  const Case cases[] = {{box({0, 0, 0}, {1.2, 0.2, 0.4}), 0.5},
                        {sphere({0, 0.8, 0}, 0.4), 0.6},
                        {box({0.2, -0.3, 0.1}, {0.7, 0.3, 0.5}), -0.8}};
  for (const Case& c : cases) {
    const SampledSurface surface(
        c.child.patches(),
        [&](int patch, double u, double v) { return bend_preimage(c.child.surface(patch, u, v), c.k); },
        c.child.is_box ? 100 : 240);
    // The preimage really maps back (the test's inverse is right).
    for (std::size_t i = 0; i < surface.points().size(); i += 97) {
      EXPECT_NEAR(c.child.value(bend_point(surface.points()[i], c.k)), 0.0, 1e-12);
    }
    std::vector<V> points = test_points(surface, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5}, 250, 250, 12);
    for (double far : {6.0, 12.0, 25.0}) points.push_back(V{far, 0.3 * far, -0.2 * far});
    Tightness t;
    for (const V& p : points) {
      const double d = c.child.value(bend_point(p, c.k));
      t.add(bend_bound(p, c.k, d), d, surface.distance(p), d);
    }
    EXPECT_EQ(t.violations, 0);
    EXPECT_EQ(t.wrong_signs, 0);
    t.report("bend k=" + std::to_string(c.k) + (c.child.is_box ? " box" : " sphere"));
  }
}

TEST(DomainOperators, SafeDisplacementNeverExceedsTheTrueDistance) {
  struct Case {
    double r, a, w;
  };
  // |aω| < 1: along each ray from the centre t − r + δ(tω) is increasing, so the
  // surface is the graph t*(direction), found by safeguarded Newton.
  const Case cases[] = {{1.0, 0.1, 5.0}, {0.8, 0.05, 8.0}, {1.0, -0.2, 3.0}};
  for (const Case& c : cases) {
    const auto on_surface = [&](int, double u, double v) {
      const double theta = kPi * u, phi = 2 * kPi * v;
      const V dir{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      double lo = c.r - std::abs(c.a) - 1e-9, hi = c.r + std::abs(c.a) + 1e-9, t = c.r;
      for (int it = 0; it < 100; ++it) {
        const V p = dir * t;
        const double g = displace_value(p, c.a, c.w, t - c.r);
        if (std::abs(g) <= 1e-15) break;  // a few ulps of t: as close as doubles get
        (g < 0 ? lo : hi) = t;
        const double sx = std::sin(c.w * p.x), sy = std::sin(c.w * p.y), sz = std::sin(c.w * p.z);
        const V grad = V{std::cos(c.w * p.x) * sy * sz, sx * std::cos(c.w * p.y) * sz, sx * sy * std::cos(c.w * p.z)} *
                       (c.a * c.w);
        double next = t - g / (1 + dot(grad, dir));
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - t) <= 1e-15) break;
        t = next;
      }
      return dir * t;
    };
    const SampledSurface surface(1, on_surface, 200);
    std::vector<V> points = test_points(surface, {-2, -2, -2}, {2, 2, 2}, 250, 250, 13);
    Tightness t;
    for (const V& p : points) {
      const double d = sdf_sphere(p, c.r);
      const double fast = displace_value(p, c.a, c.w, d);
      t.add(displace_bound(p, c.a, c.w, d), fast, surface.distance(p), fast);
    }
    EXPECT_EQ(t.violations, 0);
    EXPECT_EQ(t.wrong_signs, 0);
    t.report("displacement a=" + std::to_string(c.a) + " w=" + std::to_string(c.w));
  }
}

// ---------------------------------------------------------------------------
// Safe values against closed forms: round, elongate, symmetry, repetition.
// ---------------------------------------------------------------------------

std::vector<V> uniform_points(const V& lo, const V& hi, int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<V> out;
  for (int i = 0; i < count; ++i) {
    out.push_back({lo.x + (hi.x - lo.x) * unit(random), lo.y + (hi.y - lo.y) * unit(random),
                   lo.z + (hi.z - lo.z) * unit(random)});
  }
  return out;
}

TEST(DomainOperators, RoundIsTheOffsetOfExactChildren) {
  // The r-offset of a box [−b, b] has the exact distance sdf_box − r (inside the box
  // every path out crosses the box's boundary and then r more).
  for (const V& p : uniform_points({-3, -3, -3}, {3, 3, 3}, 500, 21)) {
    EXPECT_NEAR(round_value(sdf_sphere(p, 1.0), 0.3), norm(p) - 1.3, 1e-15);
    EXPECT_EQ(round_value(sdf_box(p, V{1, 0.5, 0.2}), 0.25), sdf_box(p, V{1, 0.5, 0.2}) - 0.25);
  }
}

TEST(DomainOperators, SafeElongationAgainstClosedForms) {
  // A sphere of radius r elongated by h is the round box [−h, h] ⊕ B(0, r): exact
  // distance sdf_box(p, h) − r. A box b elongated by h is the box b + h.
  const V h{1.0, 0.4, 0.7};
  double sphere_worst = 0, cube_worst = 0, box_min_ratio = 1, fast_min_ratio = 1;
  for (const V& p : uniform_points({-3, -3, -3}, {3, 3, 3}, 2000, 22)) {
    const V q = elongate_point(p, h);
    const double exact_sphere = sdf_box(p, h) - 0.5;
    const double safe_sphere = elongate_bound(p, h, sdf_sphere(q, 0.5));
    sphere_worst = std::max(sphere_worst, std::abs(safe_sphere - exact_sphere));
    // Fast is the same outside the core box, −r inside it (a bound, not exact).
    EXPECT_LE(std::abs(sdf_sphere(q, 0.5)), std::abs(exact_sphere) + 1e-12);

    const double exact_cube = sdf_box(p, h + V{0.3, 0.3, 0.3});
    cube_worst = std::max(cube_worst, std::abs(elongate_bound(p, h, sdf_box(q, V{0.3, 0.3, 0.3})) - exact_cube));

    const V b{0.2, 0.5, 0.3};
    const double exact_box = sdf_box(p, h + b);
    const double safe_box = elongate_bound(p, h, sdf_box(q, b));
    const double fast_box = sdf_box(q, b);
    EXPECT_LE(std::abs(safe_box), std::abs(exact_box) + 1e-12);
    EXPECT_EQ(safe_box < 0, exact_box < 0);
    if (std::abs(exact_box) > 1e-3) {
      box_min_ratio = std::min(box_min_ratio, safe_box / exact_box);
      fast_min_ratio = std::min(fast_min_ratio, fast_box / exact_box);
    }
  }
  EXPECT_LT(sphere_worst, 1e-12);
  EXPECT_LT(cube_worst, 1e-12);
  std::cout << "[measure] elongate: |safe - exact| <= " << sphere_worst << " (sphere child), " << cube_worst
            << " (cube child); box (0.2,0.5,0.3) child: safe/exact >= " << box_min_ratio
            << ", fast/exact >= " << fast_min_ratio << "\n";
}

TEST(DomainOperators, QuilezElongationNeedsTheOriginInsideTheChild) {
  // A sphere of radius 1 at (1.5, 0, 0) elongated by h = (10, 10, 10): the shape is
  // x ∈ [10.5, 12.5] (and its rounding), 10.5 away from the origin.
  const V h{10, 10, 10}, c{1.5, 0, 0}, p{0, 0, 0};
  const double child = sdf_sphere(elongate_point(p, h) - c, 1.0);
  const V q = abs(p) - h;
  const double quilez = child + std::min(max_component(q), 0.0);  // the unguarded correction
  EXPECT_EQ(child, 0.5);
  EXPECT_EQ(quilez, -9.5);                      // claims "inside": wrong
  EXPECT_EQ(elongate_bound(p, h, child), 0.5);  // safe keeps the sign
  EXPECT_LE(elongate_bound(p, h, child), 10.5);
}

TEST(DomainOperators, SymmetryAgainstClosedForms) {
  // A box crossing the mirror plane x = 0: the shape is the union of the box and its
  // mirror image, here the box of half extents (1.3, 1, 1) at (0, 0.2, 0). Inside,
  // near the plane, the value sees the box's face at x = −0.7 that the union lost.
  const V centre{0.3, 0.2, 0}, b{1, 1, 1};
  double min_ratio = 1;
  for (const V& p : uniform_points({-3, -3, -3}, {3, 3, 3}, 2000, 23)) {
    const double v = sdf_box(mirror_point(p, AxisSet{true, false, false}) - centre, b);
    const double exact = sdf_box(p - V{0, 0.2, 0}, V{1.3, 1, 1});
    EXPECT_LE(std::abs(v), std::abs(exact) + 1e-12);
    EXPECT_EQ(v < 0, exact < 0);
    if (std::abs(exact) > 1e-3) min_ratio = std::min(min_ratio, v / exact);
    // A sphere that crosses no plane, mirrored in all three: the eight copies, exact.
    const V s{1, 0.5, 0.3};
    double eight = 1e9;
    for (int m = 0; m < 8; ++m) {
      eight = std::min(eight, norm(p - V{m & 1 ? -s.x : s.x, m & 2 ? -s.y : s.y, m & 4 ? -s.z : s.z}) - 0.25);
    }
    EXPECT_NEAR(sdf_sphere(mirror_point(p, AxisSet{true, true, true}) - s, 0.25), eight, 1e-12);
  }
  EXPECT_LT(min_ratio, 0.99);  // a bound, not the distance
  std::cout << "[measure] symmetry: box crossing the plane, value/exact >= " << min_ratio << "\n";
}

// The union of the copies of `child` (|k_i| ≤ limit_i, 0 on axes not repeated):
// outside, the exact distance; inside, −(depth in the deepest copy), whose magnitude
// is at most the depth in the union.
double copies_min(const Child& child, const V& p, const V& s, const V& limit) {
  double best = 1e300;
  for (int i = -int(limit.x); i <= int(limit.x); ++i) {
    for (int j = -int(limit.y); j <= int(limit.y); ++j) {
      for (int k = -int(limit.z); k <= int(limit.z); ++k) {
        best = std::min(best, child.value(p - V{i * s.x, j * s.y, k * s.z}));
      }
    }
  }
  return best;
}

TEST(DomainOperators, SafeRepetitionAgainstAllCopies) {
  struct Case {
    const char* name;
    Child child;
    V period;
    bool finite;
    V limit;  // finite: copies −l..l; infinite: how many the brute force sums
  };
  const Case cases[] = {
      {"sphere r=1 along x, s=3", sphere({0, 0, 0}, 1), {3, 0, 0}, false, {30, 0, 0}},
      // The small sphere far from its cell's centre: fast is wrong near the other side.
      {"sphere r=0.05 at x=1.4, s=3", sphere({1.4, 0, 0}, 0.05), {3, 0, 0}, false, {30, 0, 0}},
      // Overlapping copies: the box [−2.5, 2.5] is wider than the period.
      {"sphere r=2.5, s=3 (overlapping)", sphere({0, 0, 0}, 2.5), {3, 0, 0}, false, {30, 0, 0}},
      {"box off-centre along x and z", box({0.4, 0.3, -0.5}, {0.8, 0.6, 0.7}), {2.5, 0, 2}, false, {12, 0, 12}},
      {"sphere in a 3-D lattice", sphere({0.2, -0.1, 0.3}, 0.6), {2, 1.5, 1.8}, false, {8, 8, 8}},
      {"finite box, l=(2,0,1)", box({0.1, 0, 0.2}, {0.9, 0.4, 0.5}), {2, 0, 1.5}, true, {2, 0, 1}},
      {"finite sphere, l=(0,3,0)", sphere({0, 0.5, 0}, 0.8), {0, 2, 0}, true, {0, 3, 0}},
  };
  for (const Case& c : cases) {
    const AxisSet axes = axes_of(c.period);
    Tightness t;
    double wrong_fast = 0;
    int inside = 0;
    // Uniform points, and as many near random copies (inside some of them).
    std::vector<V> points = uniform_points({-7, -7, -7}, {7, 7, 7}, 2000, 24);
    std::mt19937 random(25);
    std::uniform_int_distribution<int> index(-3, 3);
    const V extent = (c.child.hi() - c.child.lo()) * 0.6;
    for (const V& o : uniform_points(V{} - extent, extent, 1000, 26)) {
      const V copy{c.period.x * std::clamp(index(random), -int(c.limit.x), int(c.limit.x)),
                   c.period.y * std::clamp(index(random), -int(c.limit.y), int(c.limit.y)),
                   c.period.z * std::clamp(index(random), -int(c.limit.z), int(c.limit.z))};
      points.push_back(c.child.centre + copy + o);
    }
    for (const V& p : points) {
      const auto child = [&](const V& q) { return c.child.value(q); };
      const double safe = c.finite ? repeat_finite_bound(p, c.period, c.limit, axes, c.child.lo(), c.child.hi(), child)
                                   : repeat_bound(p, c.period, axes, c.child.lo(), c.child.hi(), child);
      const double fast =
          c.child.value(c.finite ? repeat_finite_point(p, c.period, c.limit, axes) : repeat_point(p, c.period, axes));
      const double exact = copies_min(c.child, p, c.period, c.limit);
      // Outside the union `exact` is the distance; inside its magnitude is at most
      // the depth, so |safe| ≤ |exact| is sufficient there too.
      t.add(safe, fast, std::abs(exact), exact);
      if (exact < 0) ++inside;
      if (exact > 0) wrong_fast = std::max(wrong_fast, fast - exact);
    }
    EXPECT_EQ(t.violations, 0) << c.name;
    EXPECT_EQ(t.wrong_signs, 0) << c.name;
    EXPECT_GT(inside, 0) << c.name;
    t.report(std::string("repetition ") + c.name);
    std::cout << "[measure]   fast exceeds the distance by up to " << wrong_fast << "\n";
  }
}

TEST(DomainOperators, NearerNeighbourCopy) {
  // Fast is 2.75 at (−1.4, 0, 0); the copy at −1.6 is 0.15 away; safe finds it.
  const Child c = sphere({1.4, 0, 0}, 0.05);
  const V p{-1.4, 0, 0}, s{3, 0, 0};
  const AxisSet x{true, false, false};
  EXPECT_NEAR(c.value(repeat_point(p, s, x)), 2.75, 1e-12);
  EXPECT_NEAR(repeat_bound(p, s, x, c.lo(), c.hi(), [&](const V& q) { return c.value(q); }), 0.15, 1e-12);
}

TEST(DomainOperators, RepeatedSphereHasZerosAtEveryCopy) {
  const Child c = sphere({0, 0, 0}, 1);
  const F s{3, 0, 0};
  const AxisSet x{true, false, false};
  for (int k = -40; k <= 40; ++k) {
    for (const F& p : {F{3.0f * k + 1, 0, 0}, F{3.0f * k - 1, 0, 0}, F{3.0f * k, 1, 0}, F{3.0f * k, 0, -1}}) {
      EXPECT_EQ(c.value(repeat_point(p, s, x)), 0.0f) << k;
      EXPECT_EQ(repeat_bound(p, s, x, to_float(c.lo()), to_float(c.hi()), [&](const F& q) { return c.value(q); }), 0.0f)
          << k;
    }
    EXPECT_EQ(c.value(repeat_point(F{3.0f * k, 0, 0}, s, x)), -1.0f);
  }
}

TEST(DomainOperators, RepetitionRefusesUnsafeChildren) {
  const AxisSet x{true, false, false};
  const double inf = std::numeric_limits<double>::infinity();
  try {
    check_repetition_box({-inf, -1, -1}, {inf, 1, 1}, {3, 0, 0}, x, "scene.child");
    FAIL() << "an unbounded child was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "unbounded_child");
    EXPECT_EQ(e.field(), "scene.child");
  }
  try {
    check_repetition_box({-3.2, -1, -1}, {1, 1, 1}, {3, 0, 0}, x, "scene.child");
    FAIL() << "a child reaching beyond the neighbour cell was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "repetition_overlap");
  }
  // Unbounded along an axis that is not repeated, and almost two periods wide: fine.
  EXPECT_NO_THROW(check_repetition_box({-2.9, -inf, -1}, {2.9, inf, 1}, {3, 0, 0}, x, "scene.child"));
}

// ---------------------------------------------------------------------------
// GLSL: both dialects, and llvmpipe against the C++ float twin.
// ---------------------------------------------------------------------------

// One operated shape: the GLSL `float t_sdf(vec3 p)` (helpers, child, body) and its
// C++ float twin, and how much of the GPU's sin/cos error can reach the value.
struct GlslCase {
  std::string name;
  std::string glsl;
  std::function<float(const F&)> cpu;
  std::function<double(const V&, double)> trig_tolerance;  // (p, E) → bound on the sin/cos part
};

std::string shader(const Child& child, const std::string& helpers, const std::string& body) {
  return child.glsl() + helpers + "float t_sdf(vec3 p) {\n" + body + "}\n";
}

std::vector<GlslCase> glsl_cases() {
  std::vector<GlslCase> out;
  const auto none = [](const V&, double) { return 0.0; };
  const Child bar = box({0, 0, 0}, {0.5, 1.5, 0.3});
  const Child ball = sphere({0.3, -0.2, 0.1}, 0.8);
  for (bool safe : {false, true}) {
    const std::string mode = safe ? " safe" : " fast";
    const float k = 1.2f;
    out.push_back({"twist" + mode,
                   shader(bar, twist_glsl("t") + (safe ? twist_bound_glsl("t") : ""),
                          "  float d = t_child(t_twist(p, " + lit(k) + "));\n" +
                              (safe ? "  return t_twist_bound(p, " + lit(k) + ", d);\n" : "  return d;\n")),
                   [=](const F& p) {
                     const float d = bar.value(twist_point(p, k));
                     return safe ? twist_bound(p, k, d) : d;
                   },
                   [](const V& p, double e) { return 2 * e * std::sqrt(p.x * p.x + p.z * p.z); }});
    const float kb = 0.5f;
    out.push_back({"bend" + mode,
                   shader(bar, bend_glsl("t") + (safe ? bend_bound_glsl("t") : ""),
                          "  float d = t_child(t_bend(p, " + lit(kb) + "));\n" +
                              (safe ? "  return t_bend_bound(p, " + lit(kb) + ", d);\n" : "  return d;\n")),
                   [=](const F& p) {
                     const float d = bar.value(bend_point(p, kb));
                     return safe ? bend_bound(p, kb, d) : d;
                   },
                   [](const V& p, double e) { return 2 * e * std::sqrt(p.x * p.x + p.y * p.y); }});
    const float a = 0.1f, w = 5.0f;
    out.push_back({"displacement" + mode,
                   shader(ball, safe ? displace_bound_glsl("t") : displace_glsl("t"),
                          "  return t_displace" + std::string(safe ? "_bound" : "") + "(p, " + lit(a) + ", " + lit(w) +
                              ", t_child(p));\n"),
                   [=](const F& p) {
                     const float d = ball.value(p);
                     return safe ? displace_bound(p, a, w, d) : displace_value(p, a, w, d);
                   },
                   [=](const V&, double e) { return 3 * std::abs(a) * e; }});
    const F h{1.0f, 0.4f, 0.7f};
    out.push_back(
        {"elongate" + mode,
         shader(ball, elongate_glsl("t") + (safe ? elongate_bound_glsl("t") : ""),
                "  float d = t_child(t_elongate(p, " + lit(to_double(h)) + "));\n" +
                    (safe ? "  return t_elongate_bound(p, " + lit(to_double(h)) + ", d);\n" : "  return d;\n")),
         [=](const F& p) {
           const float d = ball.value(elongate_point(p, h));
           return safe ? elongate_bound(p, h, d) : d;
         },
         none});
  }
  const float r = 0.25f;
  out.push_back({"round", shader(bar, round_glsl("t"), "  return t_round(t_child(p), " + lit(r) + ");\n"),
                 [=](const F& p) { return round_value(bar.value(p), r); }, none});
  const AxisSet xz{true, false, true};
  out.push_back({"symmetry xz", shader(ball, symmetry_glsl("t", xz), "  return t_child(t_symmetry_xz(p));\n"),
                 [=](const F& p) { return ball.value(mirror_point(p, xz)); }, none});

  // Repetition: a box off-centre along x and z, infinite and finite, both modes.
  const Child cell = box({0.4, 0.3, -0.5}, {0.8, 0.6, 0.7});
  const F s{2.5f, 0.0f, 2.0f}, l{2.0f, 0.0f, 1.0f};
  const F lo = to_float(cell.lo()), hi = to_float(cell.hi());
  out.push_back({"repeat xz fast",
                 shader(cell, repeat_glsl("t", xz), "  return t_child(t_repeat_xz(p, " + lit(to_double(s)) + "));\n"),
                 [=](const F& p) { return cell.value(repeat_point(p, s, xz)); }, none});
  out.push_back({"repeat xz safe",
                 shader(cell, repeat_safe_glsl("t", xz),
                        "  vec3 s = " + lit(to_double(s)) + ";\n  float v = t_repeat_xz_rest(p, s, " +
                            lit(to_double(lo)) + ", " + lit(to_double(hi)) +
                            ");\n  for (int cell = 0; cell < 4; ++cell) v = min(v, t_child(t_repeat_xz_cell(p, s, "
                            "cell)));\n  return v;\n"),
                 [=](const F& p) { return repeat_bound(p, s, xz, lo, hi, [&](const F& q) { return cell.value(q); }); },
                 none});
  out.push_back(
      {"repeat finite xz fast",
       shader(cell, repeat_finite_glsl("t", xz),
              "  return t_child(t_repeat_finite_xz(p, " + lit(to_double(s)) + ", " + lit(to_double(l)) + "));\n"),
       [=](const F& p) { return cell.value(repeat_finite_point(p, s, l, xz)); }, none});
  out.push_back(
      {"repeat finite xz safe",
       shader(cell, repeat_finite_safe_glsl("t", xz),
              "  vec3 s = " + lit(to_double(s)) + ";\n  vec3 l = " + lit(to_double(l)) +
                  ";\n  float v = t_repeat_finite_xz_rest(p, s, l, " + lit(to_double(lo)) + ", " + lit(to_double(hi)) +
                  ");\n  for (int cell = 0; cell < 4; ++cell) v = min(v, "
                  "t_child(t_repeat_finite_xz_cell(p, s, l, cell)));\n  return v;\n"),
       [=](const F& p) { return repeat_finite_bound(p, s, l, xz, lo, hi, [&](const F& q) { return cell.value(q); }); },
       none});
  // The three-axis cell and rest functions, and a y-only one (other code paths).
  const AxisSet xyz{true, true, true}, y{false, true, false};
  const F s3{2.0f, 1.5f, 1.8f};
  const Child dot3 = sphere({0.2, -0.1, 0.3}, 0.6);
  out.push_back({"repeat xyz safe",
                 shader(dot3, repeat_safe_glsl("t", xyz),
                        "  vec3 s = " + lit(to_double(s3)) + ";\n  float v = t_repeat_xyz_rest(p, s, " +
                            lit(dot3.lo()) + ", " + lit(dot3.hi()) +
                            ");\n  for (int cell = 0; cell < 8; ++cell) v = min(v, t_child(t_repeat_xyz_cell(p, s, "
                            "cell)));\n  return v;\n"),
                 [=](const F& p) {
                   return repeat_bound(p, s3, xyz, to_float(dot3.lo()), to_float(dot3.hi()),
                                       [&](const F& q) { return dot3.value(q); });
                 },
                 none});
  out.push_back({"symmetry y + repeat y fast",
                 shader(dot3, symmetry_glsl("t", y) + repeat_glsl("t", y),
                        "  return t_child(t_repeat_y(t_symmetry_y(p), " + lit(to_double(s3)) + "));\n"),
                 [=](const F& p) { return dot3.value(repeat_point(mirror_point(p, y), s3, y)); }, none});
  return out;
}

TEST(DomainOperatorsGlsl, CompilesInBothDialects) {
  for (const GlslCase& c : glsl_cases()) {
    for (const char* header : {"#version 300 es\nprecision highp float;", "#version 330"}) {
      EXPECT_EQ(testing::glslang_errors(header, c.glsl, "t_sdf"), "") << c.name << "\n" << c.glsl;
    }
  }
}

// The largest |GPU − exact| of sin and cos over [−24, 24] (the angles the cases
// reach), and the same for the C++ float functions: their sum bounds how much the
// two runs' sin/cos can differ.
struct TrigError {
  double gpu = 0, cpu = 0;
};

TrigError measure_trig(testing::GlesRunner& runner) {
  std::vector<float> xyz;
  for (int i = 0; i < 4001; ++i) {
    const float angle = -24.0f + 48.0f * float(i) / 4000.0f;
    xyz.insert(xyz.end(), {angle, 0.0f, 0.0f});
  }
  TrigError e;
  for (const char* f : {"sin", "cos"}) {
    std::string error;
    const std::vector<float> gpu =
        runner.evaluate(std::string("float t_trig(vec3 p) {\n  return ") + f + "(p.x);\n}\n", "t_trig", xyz, error);
    EXPECT_EQ(error, "");
    if (gpu.empty()) return e;
    for (std::size_t i = 0; i < gpu.size(); ++i) {
      const double angle = xyz[3 * i];
      const double exact = f[0] == 's' ? std::sin(angle) : std::cos(angle);
      const float cpu = f[0] == 's' ? std::sin(xyz[3 * i]) : std::cos(xyz[3 * i]);
      e.gpu = std::max(e.gpu, std::abs(gpu[i] - exact));
      e.cpu = std::max(e.cpu, std::abs(double(cpu) - exact));
    }
  }
  return e;
}

TEST(DomainOperatorsGlsl, RunsOnLlvmpipeLikeTheFloatTwin) {
  testing::GlesRunner& runner = testing::GlesRunner::instance();
  if (!runner.unavailable().empty()) GTEST_SKIP() << runner.unavailable();
  const TrigError trig = measure_trig(runner);
  std::cout << "[measure] " << runner.renderer() << ": max |sin, cos - exact| on [-24, 24]: GPU " << trig.gpu
            << ", C++ float " << trig.cpu << "\n";
  // A documented ceiling, so a much worse sin/cos fails here rather than silently
  // widening the tolerances below.
  EXPECT_LT(trig.gpu, 1e-5);

  std::mt19937 random(31);
  std::uniform_real_distribution<float> coordinate(-4, 4);
  std::vector<float> xyz;
  for (int i = 0; i < 2000; ++i) xyz.insert(xyz.end(), {coordinate(random), coordinate(random), coordinate(random)});
  for (const GlslCase& c : glsl_cases()) {
    std::string error;
    const std::vector<float> gpu = runner.evaluate(c.glsl, "t_sdf", xyz, error);
    ASSERT_EQ(error, "") << c.name;
    double worst = 0, worst_of_bound = 0;
    int identical = 0;
    for (std::size_t i = 0; i < gpu.size(); ++i) {
      const F p{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
      const float cpu = c.cpu(p);
      const double diff = std::abs(double(gpu[i]) - double(cpu));
      // The sin/cos part, plus 32 ulps of the magnitudes involved for the rest
      // (fused multiply-adds, sqrt, division: a few roundings each).
      const double bound = c.trig_tolerance(to_double(p), trig.gpu + trig.cpu) +
                           32 * kFloatEps * (1 + norm(to_double(p)) + std::abs(cpu));
      if (gpu[i] == cpu) ++identical;
      worst = std::max(worst, diff);
      worst_of_bound = std::max(worst_of_bound, diff / bound);
      EXPECT_LE(diff, bound) << c.name << " at (" << p.x << ", " << p.y << ", " << p.z << "): GPU " << gpu[i]
                             << ", C++ " << cpu;
      if (std::abs(cpu) > bound) {
        EXPECT_EQ(gpu[i] < 0, cpu < 0) << c.name;
      }
    }
    std::cout << "[measure] llvmpipe " << c.name << ": " << identical << "/" << gpu.size()
              << " bit-identical, max |GPU - C++| " << worst << " (" << worst_of_bound << " of the bound)\n";
  }
}

TEST(DomainOperatorsGlsl, RepeatedSphereHasZerosAtEveryCopyOnTheGpu) {
  testing::GlesRunner& runner = testing::GlesRunner::instance();
  if (!runner.unavailable().empty()) GTEST_SKIP() << runner.unavailable();
  const Child c = sphere({0, 0, 0}, 1);
  const AxisSet x{true, false, false};
  const std::string fast = shader(c, repeat_glsl("t", x), "  return t_child(t_repeat_x(p, vec3(3.0, 0.0, 0.0)));\n");
  const std::string safe =
      shader(c, repeat_safe_glsl("t", x),
             "  vec3 s = vec3(3.0, 0.0, 0.0);\n  float v = t_repeat_x_rest(p, s, " + lit(c.lo()) + ", " + lit(c.hi()) +
                 ");\n  for (int cell = 0; cell < 2; ++cell) v = min(v, t_child(t_repeat_x_cell(p, s, cell)));\n"
                 "  return v;\n");
  std::vector<float> xyz;
  for (int k = -40; k <= 40; ++k) {
    xyz.insert(xyz.end(), {3.0f * k + 1, 0, 0, 3.0f * k - 1, 0, 0, 3.0f * k, 1, 0, 3.0f * k, 0, -1});
  }
  for (const std::string& glsl : {fast, safe}) {
    std::string error;
    const std::vector<float> gpu = runner.evaluate(glsl, "t_sdf", xyz, error);
    ASSERT_EQ(error, "");
    int exact_zeros = 0;
    for (std::size_t i = 0; i < gpu.size(); ++i) {
      EXPECT_LE(std::abs(gpu[i]), 1e-6f) << "x = " << xyz[3 * i];
      if (gpu[i] == 0) ++exact_zeros;
    }
    std::cout << "[measure] llvmpipe repeated sphere: " << exact_zeros << "/" << gpu.size() << " values exactly 0\n";
  }
}

// ---------------------------------------------------------------------------
// In a scene: node kinds twist, bend, round, elongate, symmetry, repeat,
// repeat_finite, displace.
// ---------------------------------------------------------------------------

SceneNode unary(NodeKind kind, std::vector<std::pair<std::string, ParameterValue>> parameters, SceneNode child) {
  return make_node(kind, std::move(parameters), {std::move(child)});
}
SceneNode box_node(V size) { return make_node(NodeKind::box, {{"size", size}}); }

// (code, field) of compile_scene's InputError, ("", "") when it compiles.
std::pair<std::string, std::string> failure(const SceneNode& root, SdfMode mode) {
  try {
    testing::compile(root, mode);
  } catch (const InputError& e) {
    return {e.code(), e.field()};
  }
  return {"", ""};
}
using Failure = std::pair<std::string, std::string>;

struct SceneCase {
  std::string label;
  SceneNode root;
};

std::vector<SceneCase> scene_cases() {
  using testing::named;
  using testing::translate;
  const auto ball = [](double r) { return testing::sphere(r); };
  std::vector<SceneCase> out;
  const SceneNode bar = box_node({0.5, 1.5, 0.3});
  out.push_back({"twist", unary(NodeKind::twist, {{"k", 1.2}}, bar)});
  out.push_back({"twist uniform", named(unary(NodeKind::twist, {{"k", 1.2}}, bar), "tw", {"k"})});
  out.push_back({"bend", unary(NodeKind::bend, {{"k", 0.5}}, box_node({1.2, 0.2, 0.4}))});
  out.push_back({"bend uniform", named(unary(NodeKind::bend, {{"k", 0.5}}, box_node({1.2, 0.2, 0.4})), "bd", {"k"})});
  out.push_back({"round", unary(NodeKind::round, {{"radius", 0.2}}, box_node({1, 0.5, 0.25}))});
  out.push_back(
      {"round uniform", named(unary(NodeKind::round, {{"radius", 0.2}}, box_node({1, 0.5, 0.25})), "rd", {"radius"})});
  out.push_back({"elongate", unary(NodeKind::elongate, {{"size", V{1, 0.4, 0.7}}}, ball(0.5))});
  out.push_back(
      {"elongate uniform", named(unary(NodeKind::elongate, {{"size", V{1, 0.4, 0.7}}}, ball(0.5)), "el", {"size"})});
  out.push_back(
      {"symmetry xz", unary(NodeKind::symmetry, {{"axes", V{1, 0, 1}}}, translate({0.8, 0.2, 0.5}, ball(0.4)))});
  out.push_back({"repeat x", unary(NodeKind::repeat, {{"period", V{3, 0, 0}}}, ball(1))});
  out.push_back({"repeat xz uniform", named(unary(NodeKind::repeat, {{"period", V{2.5, 0, 2}}},
                                                  translate({0.4, 0.3, -0.5}, box_node({0.8, 0.6, 0.7}))),
                                            "rp", {"period"})});
  out.push_back(
      {"repeat xyz", unary(NodeKind::repeat, {{"period", V{2, 1.5, 1.8}}}, translate({0.2, -0.1, 0.3}, ball(0.6)))});
  out.push_back({"repeat_finite xz", unary(NodeKind::repeat_finite, {{"period", V{2, 0, 1.5}}, {"limit", V{2, 0, 1}}},
                                           box_node({0.9, 0.4, 0.5}))});
  out.push_back({"displace", unary(NodeKind::displace, {{"amplitude", 0.1}, {"frequency", 5.0}}, ball(1))});
  out.push_back({"displace uniform", named(unary(NodeKind::displace, {{"amplitude", 0.1}, {"frequency", 5.0}}, ball(1)),
                                           "dp", {"amplitude", "frequency"})});
  // Compositions: a repeated twisted bar, a rounded smooth union displaced, nested
  // repetitions, a mirrored elongation.
  out.push_back({"repeat of twist",
                 unary(NodeKind::repeat, {{"period", V{1.5, 0, 0}}}, unary(NodeKind::twist, {{"k", 1.0}}, bar))});
  out.push_back(
      {"displace of round of smooth union",
       unary(NodeKind::displace, {{"amplitude", 0.05}, {"frequency", 6.0}},
             unary(NodeKind::round, {{"radius", 0.1}},
                   make_node(NodeKind::smooth_union, {{"k", 0.3}}, {ball(0.6), translate({0.7, 0, 0}, ball(0.4))})))});
  out.push_back({"repeat of repeat_finite",
                 unary(NodeKind::repeat, {{"period", V{3, 0, 0}}},
                       unary(NodeKind::repeat_finite, {{"period", V{0, 0, 1.2}}, {"limit", V{0, 0, 2}}}, ball(0.5)))});
  out.push_back({"symmetry of elongate",
                 unary(NodeKind::symmetry, {{"axes", V{0, 1, 0}}},
                       unary(NodeKind::elongate, {{"size", V{0.3, 0.2, 0}}}, translate({0, 0.9, 0}, ball(0.3))))});
  return out;
}

TEST(DomainOperatorsInAScene, CompileInBothModesAndDialects) {
  for (const SceneCase& c : scene_cases()) {
    for (SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      const CompiledScene scene = testing::compile(c.root, mode);
      EXPECT_EQ(testing::glslang_both(scene), "") << c.label;
      if (mode == SdfMode::safe) {
        EXPECT_NE(scene.root_class(), NodeClass::estimate) << c.label;
      }
    }
  }
}

TEST(DomainOperatorsInAScene, RunOnLlvmpipeLikeTheFloatEvaluator) {
  if (!testing::GlesRunner::instance().unavailable().empty()) {
    GTEST_SKIP() << testing::GlesRunner::instance().unavailable();
  }
  const std::vector<Vec3<float>> points = testing::random_points(1000, -4, 4, 41);
  for (const SceneCase& c : scene_cases()) {
    for (SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      const CompiledScene scene = testing::compile(c.root, mode);
      // The uniforms at their defaults and moved by 10%: the GLSL reads them at run time.
      for (double factor : {1.0, 1.1}) {
        UniformValues values = scene.default_uniform_values();
        for (Vec3<double>& v : values) v = v * factor;
        const testing::GpuComparison r = testing::compare_on_gpu(scene, points, values);
        ASSERT_EQ(r.error, "") << c.label;
        double worst = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
          const double diff = std::abs(double(r.gpu[i]) - double(r.cpu[i]));
          // sin/cos (measured above: both within 1e-7 of exact) times the distance to
          // the axis (≤ 7), plus 64 ulps of the magnitudes.
          const double bound = 2e-7 * 7 + 64 * kFloatEps * (1 + norm(to_double(points[i])) + std::abs(r.cpu[i]));
          EXPECT_LE(diff, bound) << c.label << " at " << i;
          worst = std::max(worst, diff);
        }
        if (factor == 1.0) {
          std::cout << "[measure] scene " << c.label << (mode == SdfMode::safe ? " safe" : " fast") << ": "
                    << r.identical << "/" << r.points << " bit-identical, max |GPU - C++| " << worst << "\n";
        }
      }
    }
  }
}

TEST(DomainOperatorsInAScene, ClassesAndRefusals) {
  using testing::implicit;
  const SceneNode leaf = implicit("x^2+y^2+z^2-1");
  const SceneNode ball = testing::sphere(1);
  // Classes in safe mode.
  EXPECT_EQ(testing::compile(unary(NodeKind::twist, {{"k", 1.0}}, ball), SdfMode::safe).root_class(), NodeClass::bound);
  EXPECT_EQ(testing::compile(unary(NodeKind::round, {{"radius", 0.1}}, ball), SdfMode::safe).root_class(),
            NodeClass::lipschitz);
  EXPECT_EQ(testing::compile(unary(NodeKind::elongate, {{"size", V{1, 0, 0}}}, leaf), SdfMode::safe).root_class(),
            NodeClass::bound);
  EXPECT_EQ(testing::compile(unary(NodeKind::symmetry, {{"axes", V{1, 1, 0}}}, ball), SdfMode::safe).root_class(),
            NodeClass::lipschitz);
  EXPECT_EQ(testing::compile(unary(NodeKind::displace, {{"amplitude", 0.1}, {"frequency", 3.0}}, ball), SdfMode::safe)
                .root_class(),
            NodeClass::lipschitz);
  EXPECT_EQ(testing::compile(unary(NodeKind::repeat, {{"period", V{3, 0, 0}}}, ball), SdfMode::safe).root_class(),
            NodeClass::bound);
  // Fast mode: twist, bend, displace and repeat overshoot (estimates).
  EXPECT_EQ(testing::compile(unary(NodeKind::displace, {{"amplitude", 0.1}, {"frequency", 3.0}}, ball)).root_class(),
            NodeClass::estimate);
  // Over bound-only children (a polynomial leaf, a safe twist): round and displace refuse.
  EXPECT_EQ(failure(unary(NodeKind::round, {{"radius", 0.1}}, leaf), SdfMode::safe),
            Failure("unsafe_operator", "scene.child"));
  EXPECT_EQ(failure(unary(NodeKind::displace, {{"amplitude", 0.1}, {"frequency", 3.0}}, leaf), SdfMode::safe),
            Failure("unsafe_operator", "scene.child"));
  EXPECT_EQ(
      failure(unary(NodeKind::round, {{"radius", 0.1}}, unary(NodeKind::twist, {{"k", 1.0}}, ball)), SdfMode::safe),
      Failure("unsafe_operator", "scene.child"));
  EXPECT_EQ(failure(unary(NodeKind::round, {{"radius", 0.1}}, leaf), SdfMode::fast), Failure("", ""));
  // Repetition: the child's box must be bounded along the repeated axes and inside
  // (−period, period) there.
  const auto repeat_x = [](double period, SceneNode child) {
    return unary(NodeKind::repeat, {{"period", V{period, 0, 0}}}, std::move(child));
  };
  EXPECT_EQ(failure(repeat_x(3, make_node(NodeKind::plane, {{"normal", V{1, 0, 0}}})), SdfMode::safe),
            Failure("unbounded_child", "scene.child"));
  EXPECT_EQ(failure(repeat_x(3, make_node(NodeKind::cylinder, {{"radius", 1.0}})), SdfMode::safe),
            Failure("", ""));  // unbounded along z only
  EXPECT_EQ(failure(repeat_x(3, testing::sphere(3.5)), SdfMode::safe), Failure("repetition_overlap", "scene.child"));
  EXPECT_EQ(failure(repeat_x(3, testing::sphere(2.9)), SdfMode::safe), Failure("", ""));  // overlapping copies
  EXPECT_EQ(failure(repeat_x(3, testing::translate({2.5, 0, 0}, ball)), SdfMode::safe),
            Failure("repetition_overlap", "scene.child"));
  EXPECT_EQ(failure(repeat_x(3, testing::named(ball, "b", {"radius"})), SdfMode::safe),
            Failure("unbounded_child", "scene.child"));  // its box depends on a uniform
  EXPECT_EQ(failure(repeat_x(3, testing::sphere(3.5)), SdfMode::fast), Failure("", ""));
  // Boxes through the operators: round adds its radius, smooth union k/(2n), twist
  // the largest distance to its axis (0.583 for the box (0.5, 1.5, 0.3)), an
  // implicit leaf its far-field cube (±4 for the default box [−2, 2]³).
  EXPECT_EQ(failure(repeat_x(1.6, unary(NodeKind::round, {{"radius", 0.5}}, ball)), SdfMode::safe).first, "");
  EXPECT_EQ(failure(repeat_x(1.5, unary(NodeKind::round, {{"radius", 0.5}}, ball)), SdfMode::safe).first,
            "repetition_overlap");
  const SceneNode blend =
      make_node(NodeKind::smooth_union, {{"k", 0.5}}, {ball, testing::translate({1, 0, 0}, ball)});  // [−1.125, 2.125]
  EXPECT_EQ(failure(repeat_x(2.2, blend), SdfMode::safe).first, "");
  EXPECT_EQ(failure(repeat_x(2.1, blend), SdfMode::safe).first, "repetition_overlap");
  EXPECT_EQ(
      failure(repeat_x(0.6, unary(NodeKind::twist, {{"k", 1.0}}, box_node({0.5, 1.5, 0.3}))), SdfMode::safe).first, "");
  EXPECT_EQ(
      failure(repeat_x(0.58, unary(NodeKind::twist, {{"k", 1.0}}, box_node({0.5, 1.5, 0.3}))), SdfMode::safe).first,
      "repetition_overlap");
  EXPECT_EQ(failure(repeat_x(4.01, leaf), SdfMode::safe).first, "");
  EXPECT_EQ(failure(repeat_x(4, leaf), SdfMode::safe).first, "repetition_overlap");
  // Parameter validation the table's ranges cannot say.
  EXPECT_EQ(failure(unary(NodeKind::elongate, {{"size", V{1, -0.1, 0}}}, ball), SdfMode::fast),
            Failure("invalid_value", "scene.size"));
  EXPECT_EQ(failure(unary(NodeKind::symmetry, {{"axes", V{2, 0, 0}}}, ball), SdfMode::fast),
            Failure("invalid_value", "scene.axes"));
  EXPECT_EQ(failure(unary(NodeKind::repeat, {{"period", V{-1, 0, 0}}}, ball), SdfMode::fast),
            Failure("invalid_value", "scene.period"));
  EXPECT_EQ(
      failure(unary(NodeKind::repeat_finite, {{"period", V{3, 0, 0}}, {"limit", V{1.5, 0, 0}}}, ball), SdfMode::fast),
      Failure("invalid_value", "scene.limit"));
  EXPECT_EQ(
      failure(testing::named(unary(NodeKind::symmetry, {{"axes", V{1, 0, 0}}}, ball), "m", {"axes"}), SdfMode::fast),
      Failure("invalid_value", "scene.uniforms[0]"));
}

TEST(DomainOperatorsInAScene, OnlyTheHelpersOfTheModeArePresent) {
  const SceneNode root =
      unary(NodeKind::repeat, {{"period", V{3, 0, 0}}}, unary(NodeKind::twist, {{"k", 1.0}}, testing::sphere(0.5)));
  const std::string fast = testing::compile(root, SdfMode::fast).to_glsl();
  const std::string safe = testing::compile(root, SdfMode::safe).to_glsl();
  EXPECT_NE(fast.find("s_repeat_x("), std::string::npos);
  EXPECT_EQ(fast.find("s_repeat_x_cell"), std::string::npos);
  EXPECT_EQ(fast.find("s_twist_bound"), std::string::npos);
  EXPECT_NE(safe.find("s_repeat_x_cell("), std::string::npos);
  EXPECT_NE(safe.find("s_repeat_x_rest("), std::string::npos);
  EXPECT_NE(safe.find("s_twist_bound("), std::string::npos);
  EXPECT_EQ(safe.find("s_bend"), std::string::npos);
  // The child is written once, inside the loop over the 2^m cells.
  EXPECT_EQ(safe.find("s_twist(", safe.find("s_twist(", safe.find("float s_sdf")) + 1), std::string::npos);
}

TEST(DomainOperatorsInAScene, RepeatedSphereHasZerosAtEveryCopy) {
  const SceneNode root = unary(NodeKind::repeat, {{"period", V{3, 0, 0}}}, testing::sphere(1));
  std::vector<Vec3<float>> points;
  for (int k = -40; k <= 40; ++k)
    points.insert(points.end(), {F{3.0f * k + 1, 0, 0}, F{3.0f * k - 1, 0, 0}, F{3.0f * k, 1, 0}});
  for (SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
    const CompiledScene scene = testing::compile(root, mode);
    for (const F& p : points) EXPECT_EQ(scene.evaluate(p), 0.0f) << p.x;
    if (testing::GlesRunner::instance().unavailable().empty()) {
      const testing::GpuComparison r = testing::compare_on_gpu(scene, points, scene.default_uniform_values());
      ASSERT_EQ(r.error, "");
      for (float v : r.gpu) EXPECT_EQ(v, 0.0f);
    }
  }
}

TEST(DomainOperatorsInAScene, SafeValuesFollowTheUniforms) {
  // The safety constants are computed from the uniform's value at run time: with
  // the twist rate moved from its default 0.5 to 2, the scene's safe value is still
  // below the true distance of the bar twisted at rate 2 (and llvmpipe agrees).
  const Child bar = box({0, 0, 0}, {0.5, 1.5, 0.3});
  const SceneNode twist = testing::named(unary(NodeKind::twist, {{"k", 0.5}}, box_node(bar.size)), "tw", {"k"});
  const CompiledScene scene = testing::compile(twist, SdfMode::safe);
  const UniformValues values{{2.0, 0, 0}};
  const SampledSurface surface(
      6, [&](int patch, double u, double v) { return twist_preimage(bar.surface(patch, u, v), 2.0); }, 100);
  int violations = 0;
  const std::vector<V> points = test_points(surface, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5}, 150, 150, 42);
  for (const V& p : points) {
    if (std::abs(scene.evaluate(p, values)) > surface.distance(p) * (1 + 1e-9) + 1e-9) ++violations;
  }
  EXPECT_EQ(violations, 0);
  // The repetition's period as a uniform: moved from 3 to 4, the value is that of
  // copies 4 apart (checked against all copies), and the GPU agrees.
  const SceneNode rows = testing::named(
      unary(NodeKind::repeat, {{"period", V{3, 0, 0}}}, testing::translate({0.5, 0, 0}, testing::sphere(1))), "rp",
      {"period"});
  const CompiledScene repeated = testing::compile(rows, SdfMode::safe);
  const UniformValues period{{4, 0, 0}};
  const Child one = sphere({0.5, 0, 0}, 1);
  for (const V& p : uniform_points({-9, -3, -3}, {9, 3, 3}, 1000, 43)) {
    const double exact = copies_min(one, p, {4, 0, 0}, {30, 0, 0});
    const double v = repeated.evaluate(p, period);
    EXPECT_LE(std::abs(v), std::abs(exact) + 1e-12);
    EXPECT_EQ(v < 0, exact < 0);
  }
  if (testing::GlesRunner::instance().unavailable().empty()) {
    const testing::GpuComparison r = testing::compare_on_gpu(repeated, testing::random_points(500, -9, 9, 44), period);
    ASSERT_EQ(r.error, "");
    EXPECT_LE(r.worst_ulps, 64);
  }
}

TEST(DomainOperatorsInAScene, SafeRepetitionOfAUnionIsABound) {
  // Two spheres side by side (their union's exact distance outside), repeated along
  // x and z: |v| never exceeds the distance to the union of all copies.
  const SceneNode pair = make_node(NodeKind::csg_union, {},
                                   {testing::translate({-0.4, 0, 0}, testing::sphere(0.5)),
                                    testing::translate({0.5, 0.2, 0.3}, testing::sphere(0.4))});
  const CompiledScene child = testing::compile(pair, SdfMode::safe);
  const CompiledScene scene =
      testing::compile(unary(NodeKind::repeat, {{"period", V{1.6, 0, 1.5}}}, pair), SdfMode::safe);
  int inside = 0;
  for (const V& p : uniform_points({-6, -3, -6}, {6, 3, 6}, 3000, 45)) {
    double exact = 1e300;
    for (int i = -8; i <= 8; ++i) {
      for (int k = -8; k <= 8; ++k) exact = std::min(exact, child.evaluate(p - V{1.6 * i, 0, 1.5 * k}));
    }
    const double v = scene.evaluate(p);
    EXPECT_LE(std::abs(v), std::abs(exact) + 1e-12);
    EXPECT_EQ(v < 0, exact < 0);
    inside += exact < 0;
  }
  EXPECT_GT(inside, 0);
}

}  // namespace
}  // namespace implicitizer
