// Tests of lib/src/approximation/patch_approximation.cpp: a quadric comes back as its
// exact equation (Singular's, ../shared/bench/expected), the two-sided bound holds on a
// dense sample the test draws itself (not the library's), and bad input is refused.

#include "implicitizer/approximation/patch_approximation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>

#include "implicitization/surfaces.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer {
namespace {

using Point = std::array<double, 3>;

ParameterDomain unit_square() { return ParameterDomain{{{Rational(0), Rational(1)}, {Rational(0), Rational(1)}}}; }

testing::Surface bench_surface(const std::string& name) {
  const std::string dir = std::string(IMPLICITIZER_SHARED_DIR) + "/bench/";
  for (const char* file : {"surfaces_public.json", "surfaces_hard.json"}) {
    for (const testing::Surface& s : testing::read_surfaces(dir + file)) {
      if (s.name == name) return s;
    }
  }
  ADD_FAILURE() << "no bench surface " << name;
  return {};
}

Parametrization parametrization_of(const std::string& name) {
  const testing::Surface s = bench_surface(name);
  return parse_parametrization(s.x, s.y, s.z, std::vector<std::string>{"s", "t"});
}

// A polynomial in double, evaluated term by term (independent of the library's).
struct Evaluator {
  std::vector<double> c;
  std::vector<std::vector<std::int32_t>> e;

  explicit Evaluator(const Polynomial& p) {
    for (std::size_t k = 0; k < p.num_terms(); ++k) {
      c.push_back(to_mpq(p.coefficient(k)).get_d());
      e.push_back(p.exponents(k));
    }
  }
  double operator()(const double* x) const {
    double sum = 0;
    for (std::size_t k = 0; k < c.size(); ++k) {
      double term = c[k];
      for (std::size_t v = 0; v < e[k].size(); ++v) term *= std::pow(x[v], e[k][v]);
      sum += term;
    }
    return sum;
  }
};

// q of a piece evaluated in the piece's own frame, q(c + H·u) expanded exactly and then
// rounded (the power basis in x, y, z far from the origin would cancel), with its
// gradient by central differences (the test's own way, not the library's).
struct Surface {
  std::array<double, 3> c{};
  double half = 1;
  std::optional<Evaluator> q;

  explicit Surface(const ApproximationPiece& piece) {
    for (std::size_t i = 0; i < 3; ++i) {
      c[i] = to_mpq(piece.box.lo[i] + piece.box.hi[i]).get_d() / 2;
      half = std::max(half, to_mpq(piece.box.hi[i] - piece.box.lo[i]).get_d() / 2);
    }
    const RingPtr& ring = piece.equation.ring();
    std::vector<Polynomial> x;
    for (std::size_t i = 0; i < 3; ++i) {
      x.push_back(Polynomial::constant(ring, to_rational(mpq_class(c[i]))) +
                  Polynomial::variable(ring, i).scaled(to_rational(mpq_class(half))));
    }
    q.emplace(piece.equation.compose(ring, x));
  }
  double value(const Point& p) const {
    const Point u{(p[0] - c[0]) / half, (p[1] - c[1]) / half, (p[2] - c[2]) / half};
    return (*q)(u.data());
  }
  Point gradient(const Point& p) const {
    Point g;
    for (std::size_t i = 0; i < 3; ++i) {
      Point a = p, b = p;
      const double h = 1e-6 * half;
      a[i] += h;
      b[i] -= h;
      g[i] = (value(a) - value(b)) / (2 * h);
    }
    return g;
  }
};

struct Patch {
  std::array<Evaluator, 3> numerators, denominators;
  explicit Patch(const Parametrization& p)
      : numerators{Evaluator(p.coordinates[0].numerator()), Evaluator(p.coordinates[1].numerator()),
                   Evaluator(p.coordinates[2].numerator())},
        denominators{Evaluator(p.coordinates[0].denominator()), Evaluator(p.coordinates[1].denominator()),
                     Evaluator(p.coordinates[2].denominator())} {}
  Point operator()(double s, double t) const {
    const double st[2] = {s, t};
    return {numerators[0](st) / denominators[0](st), numerators[1](st) / denominators[1](st),
            numerators[2](st) / denominators[2](st)};
  }
};

double norm(const Point& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Point along(const Point& p, const Point& n, double lambda) {
  return {p[0] + lambda * n[0], p[1] + lambda * n[1], p[2] + lambda * n[2]};
}

std::array<double, 4> rect(const ParameterDomain& d) {
  return {to_mpq(d.intervals[0].first).get_d(), to_mpq(d.intervals[0].second).get_d(),
          to_mpq(d.intervals[1].first).get_d(), to_mpq(d.intervals[1].second).get_d()};
}

// The piece whose parameter rectangle holds (s, t).
const ApproximationPiece& piece_at(const PatchApproximation& a, double s, double t) {
  for (const ApproximationPiece& p : a.pieces) {
    const auto r = rect(p.domain);
    if (s >= r[0] && s <= r[1] && t >= r[2] && t <= r[3]) return p;
  }
  ADD_FAILURE() << "no piece holds (" << s << ", " << t << ")";
  return a.pieces.front();
}

// Patch → surface on a 200×200 grid of D: along ∇q from X(s, t), q changes sign within
// the piece's certified bound (a 1-D root search on 65 points of [−B, B]).
double check_patch_to_surface(const Parametrization& parametrization, const PatchApproximation& a) {
  const Patch patch(parametrization);
  const std::size_t side = 200;
  std::size_t failures = 0;
  double worst = 0;
  for (std::size_t i = 0; i < side; ++i) {
    for (std::size_t j = 0; j < side; ++j) {
      const double s = (double(i) + 0.5) / side, t = (double(j) + 0.5) / side;
      const ApproximationPiece& piece = piece_at(a, s, t);
      const Surface q(piece);
      const Point p = patch(s, t), g = q.gradient(p);
      const Point n{g[0] / norm(g), g[1] / norm(g), g[2] / norm(g)};
      const double bound = piece.patch_to_surface * (1 + 1e-6) + 1e-12 * a.diagonal;
      std::optional<double> root;
      const double q0 = q.value(p);
      for (int k = 1; k <= 32 && !root && q0 != 0; ++k) {
        for (const double lambda : {bound * k / 32, -bound * k / 32}) {
          if ((q.value(along(p, n, lambda)) > 0) != (q0 > 0)) root = std::abs(lambda);
        }
      }
      if (q0 == 0) root = 0;
      if (!root) ++failures;
      worst = std::max(worst, root.value_or(0));
    }
  }
  EXPECT_EQ(failures, 0u) << "patch points farther than the certified bound from {q = 0}";
  return worst / a.diagonal;
}

// The distance from y to X(rect) by a 30×30 grid and a compass search (no derivatives).
double distance_to_patch(const Patch& patch, const std::array<double, 4>& r, const Point& y) {
  double best = std::numeric_limits<double>::infinity(), bs = r[0], bt = r[2];
  for (int i = 0; i <= 30; ++i) {
    for (int j = 0; j <= 30; ++j) {
      const double s = r[0] + (r[1] - r[0]) * i / 30, t = r[2] + (r[3] - r[2]) * j / 30;
      const Point x = patch(s, t);
      const double d = norm({x[0] - y[0], x[1] - y[1], x[2] - y[2]});
      if (d < best) best = d, bs = s, bt = t;
    }
  }
  for (double step = (r[1] - r[0] + r[3] - r[2]) / 60; step > 1e-9; step /= 2) {
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [ds, dt] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const double s = std::clamp(bs + ds * step, r[0], r[1]), t = std::clamp(bt + dt * step, r[2], r[3]);
        const Point x = patch(s, t);
        const double d = norm({x[0] - y[0], x[1] - y[1], x[2] - y[2]});
        if (d < best) best = d, bs = s, bt = t, moved = true;
      }
    }
  }
  return best;
}

// Surface → patch: points of {q = 0} found from 30×30 patch points per piece moved at
// random by up to 0.1·h (h the piece box's largest half side), projected by Newton along
// ∇q; each within EPS·diagonal of X(S') (S' = S widened by a quarter of its sides).
double check_surface_to_patch(const Parametrization& parametrization, const PatchApproximation& a) {
  const Patch patch(parametrization);
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> uniform(-1, 1);
  double worst = 0;
  for (const ApproximationPiece& piece : a.pieces) {
    const auto r = rect(piece.domain);
    double h = 0;
    for (std::size_t i = 0; i < 3; ++i) h = std::max(h, to_mpq(piece.box.hi[i] - piece.box.lo[i]).get_d() / 2);
    const double ws = (r[1] - r[0]) / 4, wt = (r[3] - r[2]) / 4;
    const std::array<double, 4> widened{r[0] - ws, r[1] + ws, r[2] - wt, r[3] + wt};
    const Surface q(piece);
    for (int i = 0; i < 30; ++i) {
      for (int j = 0; j < 30; ++j) {
        Point p = patch(r[0] + (r[1] - r[0]) * (i + 0.31) / 30, r[2] + (r[3] - r[2]) * (j + 0.77) / 30);
        Point d{uniform(random), uniform(random), uniform(random)};
        const double length = 0.1 * h * std::abs(uniform(random)) / norm(d);
        p = along(p, d, length);
        Point y = p;
        bool converged = false;
        for (int k = 0; k < 50 && !converged; ++k) {
          const Point g = q.gradient(y);
          const double step = q.value(y) / (norm(g) * norm(g));
          y = along(y, g, -step);
          converged = std::abs(step) * norm(g) < 1e-10 * q.half;
        }
        const Point moved{y[0] - p[0], y[1] - p[1], y[2] - p[2]};
        if (!converged || norm(moved) > 0.1 * h) continue;
        worst = std::max(worst, distance_to_patch(patch, widened, y));
      }
    }
  }
  EXPECT_LE(worst, a.tolerance * a.diagonal) << "a point of {q = 0} near the patch is beyond the tolerance";
  return worst / a.diagonal;
}

std::size_t total_terms(const PatchApproximation& a) {
  std::size_t terms = 0;
  for (const ApproximationPiece& p : a.pieces) terms += p.equation.num_terms();
  return terms;
}

class TwoSided : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(TwoSided, BoundHoldsOnAnIndependentDenseSample) {
  const auto [name, eps] = GetParam();
  const Parametrization parametrization = parametrization_of(name);
  ApproximationParams params;
  params.tolerance = eps;
  const auto start = std::chrono::steady_clock::now();
  const PatchApproximation a = approximate_patch(parametrization, unit_square(), params);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_FALSE(a.pieces.empty());
  for (const ApproximationPiece& p : a.pieces) {
    const auto r = rect(p.domain);
    std::printf("  [%g,%g]x[%g,%g] degree %d p2s %.3g s2p %.3g\n", r[0], r[1], r[2], r[3], p.degree,
                p.patch_to_surface / a.diagonal, p.surface_to_patch / a.diagonal);
  }
  EXPECT_LE(a.patch_to_surface, eps);
  EXPECT_LE(a.surface_to_patch, eps);
  EXPECT_EQ(a.patch_to_surface_method, BoundMethod::certified);
  EXPECT_EQ(to_string(a.surface_to_patch_method), "measured");
  EXPECT_GT(a.surface_to_patch_samples, 0u);
  const double p2s = check_patch_to_surface(parametrization, a);
  const double s2p = check_surface_to_patch(parametrization, a);
  std::printf(
      "%s EPS %g: %zu pieces, max degree %d, %zu terms, certified %.3g, measured %.3g (%zu points); "
      "test sample: patch->surface %.3g, surface->patch %.3g; %.2f s\n",
      name, eps, a.pieces.size(), a.max_degree, total_terms(a), a.patch_to_surface, a.surface_to_patch,
      a.surface_to_patch_samples, p2s, s2p, seconds);
}

INSTANTIATE_TEST_SUITE_P(BenchPatches, TwoSided,
                         ::testing::Combine(::testing::Values("tp_22", "tp_33", "biquadratic_patch", "enneper",
                                                              "tri_quartic"),
                                            ::testing::Values(1e-2, 1e-3)),
                         [](const auto& param_info) {
                           return std::string(std::get<0>(param_info.param)) +
                                  (std::get<1>(param_info.param) > 5e-3 ? "_1em2" : "_1em3");
                         });

}  // namespace
}  // namespace implicitizer
