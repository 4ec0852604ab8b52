// Tests of lib/src/implicitization/patch_bounds.cpp: the box contains every exactly
// mapped point of the bench patches, is tight, is exact where the extremes are at
// corners, and refuses bad domains and denominators with a zero.

#include "implicitizer/implicitization/patch_bounds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>

#include "implicitization/surfaces.hpp"

namespace implicitizer {
namespace {

Rational q(long n, long d = 1) { return Rational(n, d); }

ParameterDomain box(std::vector<std::pair<Rational, Rational>> intervals) {
  return ParameterDomain{std::move(intervals)};
}

std::vector<testing::Surface> bench_surfaces() {
  const std::string dir = std::string(IMPLICITIZER_SHARED_DIR) + "/bench/";
  auto all = testing::read_surfaces(dir + "surfaces_public.json");
  for (const auto& s : testing::read_surfaces(dir + "surfaces_hard.json")) all.push_back(s);
  return all;
}

// The domains every bench surface is bounded on: the unit square, one across s = 0
// with a short side, one with odd rational ends.
std::vector<std::pair<std::string, ParameterDomain>> bench_domains() {
  return {{"[0,1]^2", box({{q(0), q(1)}, {q(0), q(1)}})},
          {"[-1,2]x[1/2,1]", box({{q(-1), q(2)}, {q(1, 2), q(1)}})},
          {"[-3/7,1/3]x[-2,-1]", box({{q(-3, 7), q(1, 3)}, {q(-2), q(-1)}})}};
}

// A random rational in [lo, hi] with a denominator up to 1000; the ends themselves
// one time in eight each, since extremes often sit on the boundary.
Rational random_in(const Rational& lo, const Rational& hi, std::mt19937& rng) {
  const int pick = std::uniform_int_distribution<int>(0, 7)(rng);
  if (pick == 0) return lo;
  if (pick == 1) return hi;
  const long den = std::uniform_int_distribution<long>(1, 1000)(rng);
  const long num = std::uniform_int_distribution<long>(0, den)(rng);
  return lo + (hi - lo) * Rational(num, den);
}

// The exact image of `point`.
std::vector<Rational> map_exactly(const Parametrization& p, const std::vector<Rational>& point) {
  std::vector<Rational> out;
  for (const auto& c : p.coordinates) out.push_back(c.numerator().evaluate(point) / c.denominator().evaluate(point));
  return out;
}

// Asserts that `count` random points of `domain` map into `bounds`; returns how
// many points were checked.
int expect_contains(const Parametrization& p, const ParameterDomain& domain, const PatchBounds& bounds, int count,
                    std::mt19937& rng) {
  for (int k = 0; k < count; ++k) {
    std::vector<Rational> point;
    for (const auto& [lo, hi] : domain.intervals) point.push_back(random_in(lo, hi, rng));
    const std::vector<Rational> value = map_exactly(p, point);
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (value[i] < bounds.lo[i] || value[i] > bounds.hi[i]) {
        ADD_FAILURE() << "coordinate " << i << " = " << to_string(value[i]) << " outside [" << to_string(bounds.lo[i])
                      << ", " << to_string(bounds.hi[i]) << "]";
        return k;
      }
    }
  }
  return count;
}

TEST(PatchBounds, ContainsEveryExactlyMappedPointOfTheBenchPatches) {
  std::mt19937 rng(20240611);
  int checked = 0;
  const auto surfaces = bench_surfaces();
  ASSERT_GE(surfaces.size(), 22U);
  for (const auto& s : surfaces) {
    const Parametrization p = parse_parametrization(s.x, s.y, s.z);
    for (const auto& [name, domain] : bench_domains()) {
      SCOPED_TRACE(s.name + " on " + name);
      // The plain Bernstein bound of the whole domain and the tightened default.
      for (std::size_t depth : {std::size_t{0}, PatchBoundsParams().tightening_depth}) {
        PatchBoundsParams params;
        params.tightening_depth = depth;
        checked += expect_contains(p, domain, bound_patch(p, domain, Budget(), params), 200, rng);
      }
    }
  }
  EXPECT_EQ(checked, static_cast<int>(surfaces.size()) * 3 * 2 * 200);
}

TEST(PatchBounds, ExactOnBilinearPatch) {
  // Every extreme of s, t and s·t is at a corner of [0,1]², where the Bernstein
  // coefficient is the value: the box is exact without any subdivision.
  const Parametrization p = parse_parametrization("s", "t", "s*t");
  for (std::size_t depth : {0, 8}) {
    PatchBoundsParams params;
    params.tightening_depth = depth;
    const PatchBounds b = bound_patch(p, box({{q(0), q(1)}, {q(0), q(1)}}), Budget(), params);
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(b.lo[i], q(0));
      EXPECT_EQ(b.hi[i], q(1));
    }
  }
}

TEST(PatchBounds, ExactOnUnitSphereOctant) {
  // x = 2s/(1+s²+t²) on [0,1]² runs from 0 (s = 0) to 1 (s = 1, t = 0), y likewise,
  // z = (r²−1)/(r²+1) with r² = s²+t² ∈ [0, 2] from −1 to 1/3. By hand, the degree-(2,2)
  // Bernstein coefficients are w_ij = 1 + a_i + a_j, ξ_x,ij = b_i with a = (0, 0, 1),
  // b = (0, 1, 2): every ratio lies in [0, 1], and (a_i + a_j − 1)/(a_i + a_j + 1)
  // takes −1, 0, 1/3. So even the undivided bound is exact.
  const Parametrization p = parse_parametrization("2*s/(s^2+t^2+1)", "2*t/(s^2+t^2+1)", "(s^2+t^2-1)/(s^2+t^2+1)");
  for (std::size_t depth : {0, 8}) {
    PatchBoundsParams params;
    params.tightening_depth = depth;
    const PatchBounds b = bound_patch(p, box({{q(0), q(1)}, {q(0), q(1)}}), Budget(), params);
    EXPECT_EQ(b.lo, (std::vector<Rational>{q(0), q(0), q(-1)}));
    EXPECT_EQ(b.hi, (std::vector<Rational>{q(1), q(1), q(1, 3)}));
  }
}

TEST(PatchBounds, SubdivisionReachesAnInteriorMaximum) {
  // x = s(1−s) on [0,1] has Bernstein coefficients (0, 1/2, 0): the undivided bound
  // is [0, 1/2], twice the range. One bisection puts the maximum 1/4 at a corner and
  // the halves' coefficients (0, 1/4, 1/4) and (1/4, 1/4, 0) prove it.
  const Parametrization p = parse_parametrization(std::vector<std::string>{"s*(1-s)", "s"});
  PatchBoundsParams params;
  params.tightening_depth = 0;
  const ParameterDomain unit = box({{q(0), q(1)}});
  EXPECT_EQ(bound_patch(p, unit, Budget(), params).hi[0], q(1, 2));
  params.tightening_depth = 1;
  const PatchBounds b = bound_patch(p, unit, Budget(), params);
  EXPECT_EQ(b.lo, (std::vector<Rational>{q(0), q(0)}));
  EXPECT_EQ(b.hi, (std::vector<Rational>{q(1, 4), q(1)}));
}

TEST(PatchBounds, NegativeDenominator) {
  // ω = s − 2 < 0 on [0,1]: all weights negative is as good as all positive.
  const Parametrization p = parse_parametrization(std::vector<std::string>{"1/(s-2)", "s"});
  const PatchBounds b = bound_patch(p, box({{q(0), q(1)}}));
  EXPECT_EQ(b.lo, (std::vector<Rational>{q(-1), q(0)}));
  EXPECT_EQ(b.hi, (std::vector<Rational>{q(-1, 2), q(1)}));
}

TEST(PatchBounds, DenominatorProvenZeroFreeBySubdivision) {
  // ω = 4s² − 4s + 101/100 has the minimum 1/100 at s = 1/2 but Bernstein coefficients
  // (1.01, −0.99, 1.01) on [0,1]: only the halves prove it positive. x peaks at 100.
  const Parametrization p = parse_parametrization(std::vector<std::string>{"1/(4*s^2-4*s+101/100)", "s"});
  const ParameterDomain unit = box({{q(0), q(1)}});
  const PatchBounds b = bound_patch(p, unit);
  EXPECT_GE(b.hi[0], q(100));
  EXPECT_LE(b.hi[0], q(101));
  EXPECT_EQ(b.lo[0], q(100, 101));
  std::mt19937 rng(7);
  EXPECT_EQ(expect_contains(p, unit, b, 500, rng), 500);
  // Without subdivision the same denominator cannot be proven zero-free.
  PatchBoundsParams params;
  params.max_denominator_depth = 0;
  try {
    bound_patch(p, unit, Budget(), params);
    FAIL() << "expected unbounded_patch";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "unbounded_patch");
    EXPECT_NE(std::string(e.what()).find("could not prove"), std::string::npos) << e.what();
  }
}

TEST(PatchBounds, CurvesAndThreeParameters) {
  std::mt19937 rng(11);
  // A plane curve: the folium-like x = 3s/(1+s³), y = 3s²/(1+s³) on [0, 2].
  const Parametrization curve = parse_parametrization(std::vector<std::string>{"3*s/(1+s^3)", "3*s^2/(1+s^3)"});
  const ParameterDomain interval = box({{q(0), q(2)}});
  const PatchBounds c = bound_patch(curve, interval);
  ASSERT_EQ(c.lo.size(), 2U);
  EXPECT_EQ(expect_contains(curve, interval, c, 1000, rng), 1000);
  // A map of a solid: three parameters.
  const Parametrization solid = parse_parametrization("s+t*u", "s^2-u", "(t-u)/(1+s^2)");
  const ParameterDomain cube = box({{q(-1), q(1)}, {q(0), q(2)}, {q(1, 3), q(1, 2)}});
  const PatchBounds b = bound_patch(solid, cube);
  EXPECT_EQ(expect_contains(solid, cube, b, 1000, rng), 1000);
  // A degenerate interval (one value of s) is a curve on the patch.
  const Parametrization patch = parse_parametrization("s*t", "s-t^2", "t^3");
  const ParameterDomain line = box({{q(1, 2), q(1, 2)}, {q(-1), q(1)}});
  const PatchBounds l = bound_patch(patch, line);
  EXPECT_EQ(l.lo, (std::vector<Rational>{q(-1, 2), q(-1, 2), q(-1)}));
  EXPECT_EQ(l.hi, (std::vector<Rational>{q(1, 2), q(1, 2), q(1)}));
}

void expect_input_error(const Parametrization& p, const ParameterDomain& d, const std::string& code,
                        const std::string& words) {
  try {
    bound_patch(p, d);
    ADD_FAILURE() << "expected " << code;
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), code);
    EXPECT_EQ(e.field(), "domain");
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(PatchBounds, RejectsBadDomains) {
  const Parametrization p = parse_parametrization("s", "t", "s*t");
  expect_input_error(p, box({{q(0), q(1)}}), "invalid_domain", "1 intervals");
  expect_input_error(p, box({{q(0), q(1)}, {q(0), q(1)}, {q(0), q(1)}}), "invalid_domain", "3 intervals");
  expect_input_error(p, box({{q(0), q(1)}, {q(1), q(1, 2)}}), "invalid_domain", "interval of t");
}

TEST(PatchBounds, RejectsDenominatorsWithAZero) {
  // 1/s on [−1, 1]: ω = s is −1 and 1 at two corners.
  const Parametrization reciprocal = parse_parametrization("1/s", "t", "s");
  expect_input_error(reciprocal, box({{q(-1), q(1)}, {q(0), q(1)}}), "unbounded_patch", "changes sign");
  // The zero on the boundary: a corner value 0.
  expect_input_error(reciprocal, box({{q(0), q(1)}, {q(0), q(1)}}), "unbounded_patch", "vanishes at (s, t) = (0, 0)");
  // An isolated interior zero of s² + t², found at a corner after one bisection.
  const Parametrization pole = parse_parametrization("s/(s^2+t^2)", "t", "s");
  expect_input_error(pole, box({{q(-1), q(1)}, {q(-1), q(1)}}), "unbounded_patch", "vanishes at (s, t) = (0, 0)");
  // A double zero at s = 1/3, which no bisection of [0, 1] reaches: the honest answer
  // is that the denominator could not be proven zero-free.
  const Parametrization tangent = parse_parametrization(std::vector<std::string>{"1/(3*s-1)^2", "s"});
  expect_input_error(tangent, box({{q(0), q(1)}}), "unbounded_patch", "could not prove");
}

TEST(PatchBounds, BudgetStopsIt) {
  const Parametrization p = parse_parametrization("s^3*t-t", "s*t^2", "1/(1+s^2+t^2)");
  const ParameterDomain unit = box({{q(0), q(1)}, {q(0), q(1)}});
  Budget cancelled;
  cancelled.cancel();
  try {
    bound_patch(p, unit, cancelled);
    FAIL() << "expected LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
  const Budget timed = Budget::with_timeout(0.001);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  try {
    bound_patch(p, unit, timed);
    FAIL() << "expected LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
  // ξ_x = (s³t − t)(1 + s² + t²) has degree 5 in s, ξ_y = s·t²·(1 + s² + t²) degree 4
  // in t: four Bernstein forms of 6 × 5 coefficients, 120 held at once.
  Budget small;
  small.set_max_terms(119);
  try {
    bound_patch(p, unit, small);
    FAIL() << "expected LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
  }
  small.set_max_terms(120);
  EXPECT_NO_THROW(bound_patch(p, unit, small, PatchBoundsParams{0, 12}));
}

// A coordinate in doubles, for sampling the range on a fine grid.
struct DoubleForm {
  std::vector<double> coefficients;
  std::vector<std::vector<std::int32_t>> exponents;

  explicit DoubleForm(const Polynomial& p) {
    for (std::size_t t = 0; t < p.num_terms(); ++t) {
      coefficients.push_back(CGAL::to_double(p.coefficient(t)));
      exponents.push_back(p.exponents(t));
    }
  }
  double operator()(const std::vector<double>& point) const {
    double sum = 0;
    for (std::size_t t = 0; t < coefficients.size(); ++t) {
      double term = coefficients[t];
      for (std::size_t j = 0; j < point.size(); ++j) term *= std::pow(point[j], exponents[t][j]);
      sum += term;
    }
    return sum;
  }
};

// The range of every coordinate over a 201×201 grid of the domain.
std::vector<std::pair<double, double>> sampled_range(const Parametrization& p, const ParameterDomain& domain) {
  constexpr int kSteps = 200;
  std::vector<std::pair<DoubleForm, DoubleForm>> forms;
  for (const auto& c : p.coordinates) forms.emplace_back(DoubleForm(c.numerator()), DoubleForm(c.denominator()));
  std::vector<std::pair<double, double>> range(forms.size(), {INFINITY, -INFINITY});
  const double s0 = CGAL::to_double(domain.intervals[0].first), s1 = CGAL::to_double(domain.intervals[0].second);
  const double t0 = CGAL::to_double(domain.intervals[1].first), t1 = CGAL::to_double(domain.intervals[1].second);
  for (int i = 0; i <= kSteps; ++i) {
    for (int j = 0; j <= kSteps; ++j) {
      const std::vector<double> point = {s0 + (s1 - s0) * i / kSteps, t0 + (t1 - t0) * j / kSteps};
      for (std::size_t v = 0; v < forms.size(); ++v) {
        const double value = forms[v].first(point) / forms[v].second(point);
        range[v].first = std::min(range[v].first, value);
        range[v].second = std::max(range[v].second, value);
      }
    }
  }
  return range;
}

TEST(PatchBounds, TightnessPerDepth) {
  // Prints, per tightening depth, the worst and the mean ratio of bound width to
  // sampled width over x, y, z of every bench surface on the three bench domains
  // (docs/algorithms.md quotes this table), and asserts that deeper boxes never grow
  // and that the default depth is within the measured tightness.
  struct Case {
    std::string name;
    Parametrization p;
    ParameterDomain domain;
    std::vector<std::pair<double, double>> sampled;
    std::vector<double> width;  // of the box at the previous depth
  };
  std::vector<Case> cases;
  const auto domains = bench_domains();
  for (const auto& s : bench_surfaces()) {
    for (std::size_t d = 0; d < domains.size(); ++d) {
      Case c{s.name + " on " + domains[d].first, parse_parametrization(s.x, s.y, s.z), domains[d].second, {}, {}};
      c.sampled = sampled_range(c.p, c.domain);
      c.width.assign(3, 0.0);
      cases.push_back(std::move(c));
    }
  }
  std::printf("depth | worst ratio | mean ratio | time for %zu patches | worst patch\n", cases.size());
  const std::size_t default_depth = PatchBoundsParams().tightening_depth;
  for (std::size_t depth = 0; depth <= 12; ++depth) {
    PatchBoundsParams params;
    params.tightening_depth = depth;
    double worst = 0, sum = 0;
    std::string worst_name;
    int count = 0;
    const auto start = std::chrono::steady_clock::now();
    for (Case& c : cases) {
      SCOPED_TRACE(c.name);
      const PatchBounds b = bound_patch(c.p, c.domain, Budget(), params);
      for (std::size_t i = 0; i < 3; ++i) {
        const double width = CGAL::to_double(b.hi[i] - b.lo[i]);
        if (depth > 0) {
          EXPECT_LE(width, c.width[i]);  // nested pieces, nested hulls
        }
        c.width[i] = width;
        const double sampled = c.sampled[i].second - c.sampled[i].first;
        const double ratio = width / sampled;
        EXPECT_GE(ratio, 1 - 1e-9);  // the box contains the sampled points
        if (ratio > worst) {
          worst = ratio;
          worst_name = c.name + " (" + "xyz"[i] + ")";
        }
        sum += ratio;
        ++count;
      }
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("%5zu | %11.4f | %10.4f | %8.1f ms | %s\n", depth, worst, sum / count, ms, worst_name.c_str());
    if (depth == 0) {
      EXPECT_LE(worst, 2.5);
    }
    if (depth == default_depth) {
      EXPECT_LE(worst, 1.01);
    }
  }
}

}  // namespace
}  // namespace implicitizer
