// Tests of lib/src/approximation/trim_polytope.cpp: the polytope holds the sub-patch
// X(S) (a dense grid of X(S), evaluated by the test in long double from the
// parametrization's texts, lies inside it), is as thin as the piece is flat (a plane
// patch gives a slab of width zero up to rounding), and its side planes stand across
// the patch (X just past an edge of S lies outside).

#include "implicitizer/approximation/trim_polytope.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "approximation/polytope_support.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/implicitization/parametrization.hpp"

namespace implicitizer {
namespace {

using Map = std::function<std::array<long double, 3>(long double, long double)>;

ParameterDomain domain_of(double s0, double s1, double t0, double t1) {
  return ParameterDomain{{{Rational(s0), Rational(s1)}, {Rational(t0), Rational(t1)}}};
}

// The largest excess over a 101×101 grid of S (<= 0 up to long double's rounding).
long double worst_excess(const TrimPolytope& polytope, const Map& x, const ParameterDomain& d) {
  const long double s0 = to_mpq(d.intervals[0].first).get_d(), s1 = to_mpq(d.intervals[0].second).get_d();
  const long double t0 = to_mpq(d.intervals[1].first).get_d(), t1 = to_mpq(d.intervals[1].second).get_d();
  long double worst = -std::numeric_limits<long double>::infinity();
  for (int i = 0; i <= 100; ++i) {
    for (int j = 0; j <= 100; ++j)
      worst =
          std::max(worst, testing::polytope_excess(polytope, x(s0 + (s1 - s0) * i / 100, t0 + (t1 - t0) * j / 100)));
  }
  return worst;
}

// tp_33 of ../shared/bench/surfaces_hard.json, a bicubic patch.
const char* const kTp33[3] = {
    "3+2*t^2+t^3-3*s-5*s*t+s^2-2*s^2*t-3*s^2*t^2-3*s^2*t^3+4*s^3-3*s^3*t+3*s^3*t^2-s^3*t^3",
    "3+t-2*t^2-4*t^3-3*s+s*t+5*s*t^2+2*s*t^3+4*s^2-s^2*t-5*s^2*t^2+s^2*t^3-5*s^3-3*s^3*t-5*s^3*t^2+3*s^3*t^3",
    "-2-2*t-4*t^2-5*t^3+3*s-3*s*t-4*s*t^2-4*s*t^3-s^2+3*s^2*t-3*s^2*t^2-2*s^2*t^3+3*s^3+5*s^3*t-2*s^3*t^2+2*s^3*t^3"};

TEST(TrimPolytope, HoldsTheSubPatchOfABicubic) {
  const Parametrization p = parse_parametrization(kTp33[0], kTp33[1], kTp33[2], std::vector<std::string>{"s", "t"});
  for (const ParameterDomain& d :
       {domain_of(0, 1, 0, 1), domain_of(0, 0.5, 0, 0.5), domain_of(0.25, 0.5, 0.5, 1), domain_of(0.75, 1, 0.875, 1)}) {
    const std::optional<TrimPolytope> polytope = bound_piece_polytope(p, d, Budget());
    ASSERT_TRUE(polytope);
    ASSERT_EQ(polytope->normals.size(), 10u);
    for (const auto& n : polytope->normals) EXPECT_NEAR(std::hypot(n[0], n[1], n[2]), 1.0, 1e-15);
    EXPECT_LE(worst_excess(*polytope, testing::tp33_point<long double>, d), 1e-12L);
  }
}

TEST(TrimPolytope, IsAFlatSlabAroundAPlanePatchAndCutsPastItsEdges) {
  // The plane x + 2y − 2z = 1 (unit normal (1, 2, −2)/3), over [0, 1]²: both normal
  // offsets agree to rounding, and the points just past each edge of S are outside.
  const Parametrization p = parse_parametrization("s", "t", "(s+2*t-1)/2");
  const Map x = [](long double s, long double t) { return std::array<long double, 3>{s, t, (s + 2 * t - 1) / 2}; };
  const ParameterDomain d = domain_of(0, 1, 0, 1);
  const std::optional<TrimPolytope> polytope = bound_piece_polytope(p, d, Budget());
  ASSERT_TRUE(polytope);
  EXPECT_NEAR(polytope->offsets[0] + polytope->offsets[1], 0.0, 1e-12);
  EXPECT_LE(worst_excess(*polytope, x, d), 1e-12L);
  for (const auto& [s, t] : {std::pair{-0.05, 0.5}, {1.05, 0.5}, {0.5, -0.05}, {0.5, 1.05}}) {
    EXPECT_GT(testing::polytope_excess(*polytope, x(s, t)), 0.01L) << s << ", " << t;
  }
}

TEST(TrimPolytope, NoneAtASingularCentre) {
  // X = (s·t, s, s) has X_t = 0 where s = 0: a domain centred there has no normal at
  // its centre to build the planes on.
  const Parametrization p = parse_parametrization("s*t", "s", "s");
  EXPECT_FALSE(bound_piece_polytope(p, domain_of(-1, 1, 0, 1), Budget()));
}

}  // namespace
}  // namespace implicitizer
