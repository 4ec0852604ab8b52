// Tests of lib/src/implicitization/patch_domain.cpp: the charts are the
// parametrization at reciprocal parameters (exactly), the closed bench surfaces are
// bounded on the whole plane and get it as their default domain, every polynomial
// map gets [0, 1]^m, and the bound of the plane contains the image of far points.

#include "implicitizer/implicitization/patch_domain.hpp"

#include <gtest/gtest.h>

#include <random>

#include "implicitization/surfaces.hpp"

namespace implicitizer {
namespace {

std::vector<testing::Surface> bench_surfaces() {
  const std::string dir = std::string(IMPLICITIZER_SHARED_DIR) + "/bench/";
  auto all = testing::read_surfaces(dir + "surfaces_public.json");
  for (const auto& s : testing::read_surfaces(dir + "surfaces_hard.json")) all.push_back(s);
  return all;
}

std::vector<Rational> map_exactly(const Parametrization& p, const std::vector<Rational>& point) {
  std::vector<Rational> out;
  for (const auto& c : p.coordinates) out.push_back(c.numerator().evaluate(point) / c.denominator().evaluate(point));
  return out;
}

// Nonzero rational parameter pairs (fixed seed).
std::vector<std::pair<Rational, Rational>> nonzero_pairs(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<long> pick(-40, 40);
  std::vector<std::pair<Rational, Rational>> out;
  while (out.size() < 40) {
    Rational a(pick(rng), 7L), b(pick(rng), 9L);
    if (a != Rational(0) && b != Rational(0)) out.emplace_back(a, b);
  }
  return out;
}

TEST(PatchDomain, ChartsAreTheParametrizationAtReciprocalParameters) {
  const Parametrization p = parse_parametrization("(2+(1-t^2)/(1+t^2))*(1-s^2)/(1+s^2)",
                                                  "(2+(1-t^2)/(1+t^2))*2*s/(1+s^2)", "2*t/(1+t^2)+s^3");
  const std::vector<Parametrization> charts = parameter_charts(p);
  ASSERT_EQ(charts.size(), 4U);
  for (const auto& [a, b] : nonzero_pairs(3)) {
    for (std::size_t mask = 0; mask < 4; ++mask) {
      const Rational s = (mask & 1U) ? Rational(1) / a : a;
      const Rational t = (mask & 2U) ? Rational(1) / b : b;
      EXPECT_EQ(map_exactly(charts[mask], {a, b}), map_exactly(p, {s, t})) << "chart " << mask;
    }
  }
}

TEST(PatchDomain, ProjectiveChartsAreTheParametrizationAtHomogeneousParameters) {
  const Parametrization p =
      parse_parametrization("2*t*(1-s^2-t^2)/(1+s^2+t^2)^2", "2*s*(1-s^2-t^2)/(1+s^2+t^2)^2", "4*s*t/(1+s^2+t^2)^2+s");
  const std::vector<Parametrization> charts = projective_charts(p);
  ASSERT_EQ(charts.size(), 3U);
  for (const auto& [a, b] : nonzero_pairs(5)) {
    EXPECT_EQ(map_exactly(charts[0], {a, b}), map_exactly(p, {a, b}));
    EXPECT_EQ(map_exactly(charts[1], {a, b}), map_exactly(p, {Rational(1) / a, b / a}));
    EXPECT_EQ(map_exactly(charts[2], {a, b}), map_exactly(p, {a / b, Rational(1) / b}));
  }
}

TEST(PatchDomain, ClosedBenchSurfacesDefaultToTheWholePlane) {
  for (const testing::Surface& s : bench_surfaces()) {
    const Parametrization p = parse_parametrization(s.x, s.y, s.z);
    const DefaultPatchDomain d = default_patch_domain(p);
    const bool closed = s.name == "unit_sphere" || s.name == "torus_R2_r1" || s.name == "steiner_roman";
    EXPECT_EQ(d.whole_plane, closed) << s.name;
    if (!d.whole_plane) {
      EXPECT_EQ(d.domain.intervals, unit_domain(p).intervals) << s.name;
      continue;
    }
    // Far and near parameters map into the bound.
    for (const auto& point : std::vector<std::vector<Rational>>{
             {Rational(0), Rational(0)}, {Rational(1000), Rational(-3)}, {Rational(-7, 3), Rational(100000)}}) {
      const std::vector<Rational> x = map_exactly(p, point);
      for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_LE(d.bounds.lo[i], x[i]) << s.name;
        EXPECT_GE(d.bounds.hi[i], x[i]) << s.name;
      }
    }
  }
}

TEST(PatchDomain, UnitSphereBoundOfThePlaneIsTheCube) {
  const Parametrization p = parse_parametrization("2*s/(s^2+t^2+1)", "2*t/(s^2+t^2+1)", "(s^2+t^2-1)/(s^2+t^2+1)");
  const PatchBounds b = bound_patch_on_plane(p);
  for (std::size_t i = 0; i < 3; ++i) {
    // Within the default tightening of [-1, 1] (patch_bounds.hpp: 0.25% at depth 8).
    EXPECT_LE(b.lo[i], Rational(-1));
    EXPECT_GE(b.lo[i], Rational(-1006, 1000));
    EXPECT_GE(b.hi[i], Rational(1));
    EXPECT_LE(b.hi[i], Rational(1006, 1000));
  }
}

TEST(PatchDomain, CurvesHaveTwoCharts) {
  const Parametrization circle = parse_parametrization({"(1-t^2)/(1+t^2)", "2*t/(1+t^2)"});
  EXPECT_EQ(parameter_charts(circle).size(), 2U);
  EXPECT_TRUE(default_patch_domain(circle).whole_plane);
  const Parametrization parabola = parse_parametrization({"t", "t^2"});
  EXPECT_FALSE(default_patch_domain(parabola).whole_plane);
  // A rational curve with a real pole at t = 0 is bounded neither on the line nor on
  // [0, 1]: the default domain says so.
  const Parametrization hyperbola = parse_parametrization({"t", "1/t"});
  EXPECT_THROW(bound_patch_on_plane(hyperbola), InputError);
  EXPECT_THROW(default_patch_domain(hyperbola), InputError);
  // With the pole at t = −2 the default is [0, 1].
  EXPECT_FALSE(default_patch_domain(parse_parametrization({"t", "1/(t+2)"})).whole_plane);
}

}  // namespace
}  // namespace implicitizer
