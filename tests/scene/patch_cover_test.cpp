// Tests of lib/src/scene/patch_cover.cpp: the cover's distance is 0 on the patch,
// above 0.01·h at points of the algebraic surface farther than 0.1·h from the patch,
// never above the distance to the patch (nor the exact value of its leaves), the same
// in GLSL on llvmpipe as in C++ float; and the leaf counts and build times of the
// bench surfaces (printed for docs/sdf.md, "Patches").

#include "implicitizer/scene/patch_cover.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "implicitization/surfaces.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/patch_domain.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "scene/scene_support.hpp"

namespace implicitizer {
namespace {

using V = Vec3<double>;

ParameterDomain domain_of(double s0, double s1, double t0, double t1) {
  return ParameterDomain{{{Rational(s0), Rational(s1)}, {Rational(t0), Rational(t1)}}};
}

// A patch with its implicit equation, its frame box (the exact bound padded by 1e-4
// of its largest side, as PolynomialLeaf fits it) and its cover.
struct Covered {
  Parametrization parametrization;
  ParameterDomain domain;
  Polynomial equation{space_ring()};
  SceneBox frame;
  double h = 0;
  std::optional<PatchCover> cover;
  double seconds = 0;  // the cover's build time
};

Covered cover_patch(const std::string& x, const std::string& y, const std::string& z, const ParameterDomain& domain,
                    const PatchCoverParams& params = PatchCoverParams()) {
  Covered c;
  c.parametrization = parse_parametrization(x, y, z);
  c.domain = domain;
  c.equation = implicitize(c.parametrization).implicit;
  const PatchBounds b = bound_patch(c.parametrization, domain);
  Rational largest(0);
  for (std::size_t i = 0; i < 3; ++i) largest = std::max(largest, b.hi[i] - b.lo[i]);
  for (std::size_t i = 0; i < 3; ++i) {
    c.frame.lo[i] = b.lo[i] - largest / Rational(10000);
    c.frame.hi[i] = b.hi[i] + largest / Rational(10000);
  }
  c.h = to_mpq(largest).get_d() * (1 + 2e-4) / 2;
  const auto start = std::chrono::steady_clock::now();
  c.cover = PatchCover::build(c.parametrization, domain, c.equation, c.frame, Budget(), params);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

V map_point(const Parametrization& p, double s, double t) {
  const std::vector<Rational> point{Rational(s), Rational(t)};
  double out[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const RationalFunction& f = p.coordinates[i];
    out[i] = to_mpq(f.numerator().evaluate(point) / f.denominator().evaluate(point)).get_d();
  }
  return {out[0], out[1], out[2]};
}

// A dense sample of X(D) and the largest distance between grid neighbours (every
// point of the patch is within about that of the sample).
struct Sample {
  std::vector<V> points;
  double gap = 0;

  double distance(const V& q) const {
    double best = INFINITY;
    for (const V& p : points) best = std::min(best, length(p - q));
    return best;
  }
};

Sample sample_patch(const Covered& c, int n) {
  Sample s;
  const double s0 = to_mpq(c.domain.intervals[0].first).get_d(), s1 = to_mpq(c.domain.intervals[0].second).get_d();
  const double t0 = to_mpq(c.domain.intervals[1].first).get_d(), t1 = to_mpq(c.domain.intervals[1].second).get_d();
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      s.points.push_back(map_point(c.parametrization, s0 + (s1 - s0) * i / n, t0 + (t1 - t0) * j / n));
      if (j > 0) s.gap = std::max(s.gap, length(s.points.back() - s.points[s.points.size() - 2]));
      if (i > 0) s.gap = std::max(s.gap, length(s.points.back() - s.points[s.points.size() - 1 - (n + 1)]));
    }
  }
  return s;
}

bool in_frame(const Covered& c, const V& p) {
  const double q[3] = {p.x, p.y, p.z};
  for (std::size_t i = 0; i < 3; ++i) {
    if (q[i] < to_mpq(c.frame.lo[i]).get_d() || q[i] > to_mpq(c.frame.hi[i]).get_d()) return false;
  }
  return true;
}

Vec3<float> to_float(const V& p) { return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)}; }

// The smallest leaf value of the cover's float data in long double (each leaf: the
// larger of its box distance and its largest slab excess, patch_cover.hpp), without
// the float run's slack and shrink: what the float and double values must not exceed.
long double exact_leaf_distance(const PatchCover& cover, const Vec3<float>& p) {
  long double best = INFINITY;
  for (std::size_t j = 0; j < cover.leaf_lo().size(); ++j) {
    const Vec3<float>& lo = cover.leaf_lo()[j];
    const Vec3<float>& hi = cover.leaf_hi()[j];
    const long double dx = std::max({(long double)lo.x - p.x, (long double)p.x - hi.x, 0.0L});
    const long double dy = std::max({(long double)lo.y - p.y, (long double)p.y - hi.y, 0.0L});
    const long double dz = std::max({(long double)lo.z - p.z, (long double)p.z - hi.z, 0.0L});
    long double value = std::sqrt(dx * dx + dy * dy + dz * dz);
    const long double d[3] = {(long double)p.x - lo.x, (long double)p.y - lo.y, (long double)p.z - lo.z};
    const float slo[3] = {cover.leaf_slab_lo()[j].x, cover.leaf_slab_lo()[j].y, cover.leaf_slab_lo()[j].z};
    const float shi[3] = {cover.leaf_slab_hi()[j].x, cover.leaf_slab_hi()[j].y, cover.leaf_slab_hi()[j].z};
    for (std::size_t i = 0; i < 3; ++i) {
      const Vec3<float>& w = cover.leaf_slab_normals(i)[j];
      const long double q = w.x * d[0] + w.y * d[1] + w.z * d[2];
      value = std::max({value, slo[i] - q, q - shi[i]});
    }
    best = std::min(best, value);
  }
  return best;
}

struct Case {
  const char* name;
  const char* x;
  const char* y;
  const char* z;
};

// The patches of the issue: open surfaces whose algebraic surface continues far
// beyond [0, 1]², and a random bicubic patch.
const Case kCases[] = {
    {"hyperbolic_paraboloid", "t", "s", "t^2-s^2"},
    {"enneper", "s-s^3/3+s*t^2", "t-t^3/3+t*s^2", "s^2-t^2"},
    {"biquadratic_patch", "s^2+2*s*t-t+1", "s*t^2-s+3*t", "s^2*t^2+s-2*t^2"},
    {"bicubic", "s+s^2*t-2*t^3", "t-s*t+s^3*t^2", "s^2+t^3-s*t"},
};

TEST(PatchCover, PatchPointsAreInsideAndFarSurfacePointsAreAway) {
  for (const Case& k : kCases) {
    const Covered c = cover_patch(k.x, k.y, k.z, domain_of(0, 1, 0, 1));
    const PatchCover& cover = *c.cover;
    EXPECT_EQ(cover.stats().unresolved, 0U) << k.name;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0, 1), wide(-1, 2);
    // On the patch: within 1e-3·h of a box (0 up to float rounding).
    for (int i = 0; i < 500; ++i) {
      const V p = map_point(c.parametrization, unit(rng), unit(rng));
      EXPECT_LE(cover.distance_lower_bound(to_float(p), 0.0f), 1e-3 * c.h) << k.name;
      EXPECT_EQ(cover.distance_lower_bound(p, 0.0), 0.0) << k.name;
    }
    // Points of Z from parameters in [-1, 2]² outside D, inside the frame box and
    // farther than 0.1·h from the patch (measured on a sample, plus its spacing).
    const Sample sample = sample_patch(c, 300);
    ASSERT_LT(sample.gap, 0.05 * c.h) << k.name;
    std::size_t far = 0;
    for (int i = 0; i < 4000; ++i) {
      const double s = wide(rng), t = wide(rng);
      if (s >= 0 && s <= 1 && t >= 0 && t <= 1) continue;
      const V p = map_point(c.parametrization, s, t);
      if (!in_frame(c, p) || sample.distance(p) <= 0.1 * c.h + sample.gap) continue;
      ++far;
      EXPECT_GT(cover.distance_lower_bound(to_float(p), 0.0f), 0.01 * c.h) << k.name << " at s=" << s << " t=" << t;
    }
    std::printf("%s: %zu leaves, %zu far points of Z checked, %.3f s\n", k.name, cover.stats().leaves, far, c.seconds);
  }
}

TEST(PatchCover, NeverAboveTheDistanceToThePatchOrItsBoxes) {
  for (const Case& k : kCases) {
    const Covered c = cover_patch(k.x, k.y, k.z, domain_of(0, 1, 0, 1));
    const Sample sample = sample_patch(c, 200);
    const Vec3<float> lo = c.cover->lo(), hi = c.cover->hi();
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> x(lo.x - 0.2f, hi.x + 0.2f), y(lo.y - 0.2f, hi.y + 0.2f),
        z(lo.z - 0.2f, hi.z + 0.2f);
    for (int i = 0; i < 1500; ++i) {
      const Vec3<float> p{x(rng), y(rng), z(rng)};
      const float value = c.cover->distance_lower_bound(p, 0.0f);
      const long double leaves = exact_leaf_distance(*c.cover, p);
      EXPECT_LE(value, leaves) << k.name;
      // And no lower than the leaves' rounding and slack: the walk skips no leaf that
      // would set the minimum, and its start (the nearest cluster point) is no lower.
      const float reach = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
      EXPECT_GE(value, leaves * (1 - 0x1p-12L) - 0x1p-16L * reach) << k.name;
      // The leaves' boxes and slabs contain the patch, so the sample is never closer
      // than they are.
      EXPECT_LE(value, sample.distance({p.x, p.y, p.z})) << k.name;
      // With |d| larger than the box distance the answer is |d|.
      EXPECT_EQ(c.cover->distance_lower_bound(p, -value - 1.0f), value + 1.0f) << k.name;
      EXPECT_LE(c.cover->distance_lower_bound(V{p.x, p.y, p.z}, 0.0), static_cast<double>(leaves)) << k.name;
    }
  }
}

TEST(PatchCover, PlanePatchNeedsOneLeaf) {
  // x = y + z is the whole algebraic surface, and inside the fitted box it is the
  // patch itself: no far cells, so the root is a leaf.
  const Covered c = cover_patch("s+t", "s", "t", domain_of(0, 1, 0, 1));
  EXPECT_EQ(c.cover->stats().far_cells, 0U);
  EXPECT_EQ(c.cover->stats().leaves, 1U);
}

TEST(PatchCover, LeafCapLeavesAnUnresolvedTolerance) {
  PatchCoverParams params;
  params.max_leaves = 16;
  const Covered c = cover_patch("s-s^3/3+s*t^2", "t-t^3/3+t*s^2", "s^2-t^2", domain_of(0, 1, 0, 1), params);
  EXPECT_LE(c.cover->stats().leaves, 16U);
  EXPECT_GT(c.cover->stats().unresolved, 0U);
  EXPECT_GT(c.cover->stats().tolerance_reached, params.tolerance);
}

TEST(PatchCover, SearchCapIsALimit) {
  PatchCoverParams params;
  params.max_search_cells = 100;
  EXPECT_THROW(cover_patch("s-s^3/3+s*t^2", "t-t^3/3+t*s^2", "s^2-t^2", domain_of(0, 1, 0, 1), params), LimitExceeded);
}

TEST(PatchCover, PatchBeyondFloatsRangeInASmallBox) {
  // z reaches 1e54 on [0, 1]²: the boxes' corners beyond float's range are clamped
  // to ±FLT_MAX, and the GLSL states only finite numbers.
  const Parametrization p =
      parse_parametrization("s", "t", "1000000000000000000000000000000000000000000000000000000*s*t");
  const Polynomial f = implicitize(p).implicit;
  SceneBox frame;
  for (std::size_t i = 0; i < 3; ++i) {
    frame.lo[i] = Rational(-2);
    frame.hi[i] = Rational(2);
  }
  const PatchCover cover = PatchCover::build(p, domain_of(0, 1, 0, 1), f, frame, Budget());
  for (const Vec3<float>& hi : cover.leaf_hi()) EXPECT_TRUE(std::isfinite(hi.z));
  // X(1/2, 2e-24) = (1/2, 2e-24, 1e30) lies in a box.
  EXPECT_EQ(cover.distance_lower_bound(Vec3<float>{0.5f, 2e-24f, 1e30f}, 0.0f), 0.0f);
  EXPECT_EQ(testing::glslang_errors("#version 300 es\nprecision highp float;",
                                    cover.to_glsl("cover") + "float run(vec3 p) { return cover(p, 0.0); }\n", "run"),
            "");
}

TEST(PatchCover, CommonDenominatorBeyondDoublesRange) {
  // x = t²/(10^400 + t), y = t: a segment of the y-axis, to 10^-400, but over the
  // common denominator ω = 10^400 + t the double evaluation is x = t²/∞ and y = ∞/∞,
  // a NaN that the sample leaves out (the request fuzzer found it as undefined
  // behaviour: a NaN bucket count).
  const std::string big = "1" + std::string(400, '0');
  const Parametrization curve = parse_parametrization({"t^2/(" + big + "+t)", "t"});
  const Polynomial f = parse_polynomial("x*(" + big + "+y)-y^2", space_ring());
  SceneBox frame;
  for (std::size_t i = 0; i < 3; ++i) {
    frame.lo[i] = Rational(-1, 1000);
    frame.hi[i] = Rational(i == 1 ? 1001 : 1, 1000);
  }
  const PatchCover cover = PatchCover::build(curve, ParameterDomain{{{Rational(0), Rational(1)}}}, f, frame, Budget());
  EXPECT_EQ(cover.stats().sample_points, 0U);
  for (int i = 0; i <= 10; ++i) EXPECT_EQ(cover.distance_lower_bound(V{0, 0.1 * i, 0}, 0.0), 0.0);
}

TEST(PatchCover, CancelledBudgetStopsTheBuild) {
  const Parametrization p = parse_parametrization("s-s^3/3+s*t^2", "t-t^3/3+t*s^2", "s^2-t^2");
  const Polynomial f = implicitize(p).implicit;
  SceneBox frame;
  for (std::size_t i = 0; i < 3; ++i) {
    frame.lo[i] = Rational(-2);
    frame.hi[i] = Rational(2);
  }
  Budget budget;
  budget.cancel();
  try {
    PatchCover::build(p, domain_of(0, 1, 0, 1), f, frame, budget);
    ADD_FAILURE() << "no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
}

TEST(PatchCover, GlslMatchesFloatOnLlvmpipe) {
  const Covered c = cover_patch("s^2+2*s*t-t+1", "s*t^2-s+3*t", "s^2*t^2+s-2*t^2", domain_of(0, 1, 0, 1));
  for (const char* header : {"#version 300 es\nprecision highp float;", "#version 330"}) {
    EXPECT_EQ(testing::glslang_errors(
                  header, c.cover->to_glsl("cover") + "float run(vec3 p) { return cover(p, p.x * 0.25); }\n", "run"),
              "")
        << header;
  }
  const std::string reason = testing::GlesRunner::instance().unavailable();
  if (!reason.empty()) GTEST_SKIP() << "no headless llvmpipe: " << reason;
  const Vec3<float> lo = c.cover->lo(), hi = c.cover->hi();
  std::vector<float> xyz;
  std::vector<Vec3<float>> points;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> x(lo.x - 0.5f, hi.x + 0.5f), y(lo.y - 0.5f, hi.y + 0.5f),
      z(lo.z - 0.5f, hi.z + 0.5f);
  for (int i = 0; i < 2000; ++i) {
    points.push_back({x(rng), y(rng), z(rng)});
    xyz.insert(xyz.end(), {points.back().x, points.back().y, points.back().z});
  }
  std::string error;
  const std::vector<float> gpu = testing::GlesRunner::instance().evaluate(
      c.cover->to_glsl("cover") + "float run(vec3 p) { return cover(p, p.x * 0.25); }\n", "run", xyz, error);
  ASSERT_EQ(error, "");
  std::size_t identical = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float cpu = c.cover->distance_lower_bound(points[i], points[i].x * 0.25f);
    // The only freedom the GPU has is fusing the sum of squares into multiply-adds.
    EXPECT_LE(testing::ulps_apart(cpu, gpu[i]), 4) << i;
    identical += cpu == gpu[i];
  }
  std::printf("%zu of %zu points bit-identical\n", identical, points.size());
}

TEST(PatchCover, PlaneCurveIsCoveredByABinaryTree) {
  // The nodal cubic y² = x²(x + 1), x = t² − 1, y = t³ − t, over t ∈ [0, 3/2]: the
  // lower half of the loop and the upper branch. The upper half of the loop
  // (t ∈ (−1, 0)) lies inside the box of X(D) and must stay away; the curve is a
  // cylinder in space, cut at z = 0, and every box lies in that plane.
  const Parametrization curve = parse_parametrization({"t^2-1", "t^3-t"});
  const Polynomial f = parse_polynomial("y^2-x^3-x^2", space_ring());
  SceneBox frame;
  for (std::size_t i = 0; i < 3; ++i) {
    frame.lo[i] = Rational(-3, 2);
    frame.hi[i] = Rational(22, 10);
  }
  const double h = 1.85;
  const PatchCover cover =
      PatchCover::build(curve, ParameterDomain{{{Rational(0), Rational(3, 2)}}}, f, frame, Budget());
  EXPECT_EQ(cover.stats().unresolved, 0U);
  EXPECT_GT(cover.stats().leaves, 1U);
  const auto at = [](double t) { return V{t * t - 1, t * t * t - t, 0}; };
  std::vector<V> sample;
  for (int i = 0; i <= 3000; ++i) sample.push_back(at(1.5 * i / 3000));
  std::size_t far = 0;
  for (int i = 0; i <= 200; ++i) {
    EXPECT_EQ(cover.distance_lower_bound(at(1.5 * i / 200), 0.0), 0.0);
    const V p = at(-1 + 0.01 * i);  // t ∈ [−1, 1]: the whole loop
    double distance = INFINITY;
    for (const V& q : sample) distance = std::min(distance, length(p - q));
    if (distance <= 0.1 * h + 1e-3) continue;
    ++far;
    EXPECT_GT(cover.distance_lower_bound(to_float(p), 0.0f), 0.01 * h) << "t = " << -1 + 0.01 * i;
  }
  EXPECT_GT(far, 50U);
  for (std::size_t j = 0; j < cover.leaf_lo().size(); ++j) {
    EXPECT_EQ(cover.leaf_lo()[j].z, 0.0f);
    EXPECT_EQ(cover.leaf_hi()[j].z, 0.0f);
  }
  std::printf("nodal cubic: %zu leaves, %zu far points checked\n", cover.stats().leaves, far);
}

// Leaf counts and build times of every parametric bench surface on [0, 1]² (the
// numbers of docs/sdf.md, "Patches"; not asserted: they depend on the machine).
TEST(PatchCover, BenchSurfaces) {
  const std::string dir = std::string(IMPLICITIZER_SHARED_DIR) + "/bench/";
  for (const char* file : {"surfaces_public.json", "surfaces_hard.json"}) {
    for (const testing::Surface& s : testing::read_surfaces(dir + file)) {
      const Covered c = cover_patch(s.x, s.y, s.z, domain_of(0, 1, 0, 1));
      const PatchCoverStats& st = c.cover->stats();
      EXPECT_EQ(st.unresolved, 0U) << s.name;
      EXPECT_EQ(st.edge_unresolved, 0U) << s.name;
      std::printf("%-22s deg %2d: %4zu leaves %3zu clusters %5zu nodes %7zu cells %6zu far %s %zu box-only %.3f s\n",
                  s.name.c_str(), s.degree, st.leaves, st.clusters, st.nodes, st.search_cells, st.far_cells,
                  st.proven_empty_cells ? "safe" : "none", st.box_leaves, c.seconds);
    }
  }
}

}  // namespace
}  // namespace implicitizer
