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

#include "approximation/polytope_support.hpp"
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
    // Powers of each variable once, then one product per term.
    std::array<std::array<double, 32>, 3> power{};
    const std::size_t variables = e.empty() ? 0 : e[0].size();
    for (std::size_t v = 0; v < variables; ++v) {
      power[v][0] = 1;
      for (std::size_t k = 1; k < 32; ++k) power[v][k] = power[v][k - 1] * x[v];
    }
    double sum = 0;
    for (std::size_t k = 0; k < c.size(); ++k) {
      double term = c[k];
      for (std::size_t v = 0; v < variables; ++v) term *= power[v][std::size_t(e[k][v])];
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
std::size_t piece_at(const PatchApproximation& a, double s, double t) {
  for (std::size_t k = 0; k < a.pieces.size(); ++k) {
    const auto r = rect(a.pieces[k].domain);
    if (s >= r[0] && s <= r[1] && t >= r[2] && t <= r[3]) return k;
  }
  ADD_FAILURE() << "no piece holds (" << s << ", " << t << ")";
  return 0;
}

using testing::polytope_excess;

bool in_box(const ApproximationPiece& piece, const Point& y) {
  for (std::size_t i = 0; i < 3; ++i) {
    if (y[i] < to_mpq(piece.box.lo[i]).get_d() || y[i] > to_mpq(piece.box.hi[i]).get_d()) return false;
  }
  return true;
}

// Patch → surface on a 200×200 grid of D: along ∇q from X(s, t), q changes sign within
// the piece's certified bound (a 1-D root search on 65 points of [−B, B]); and each
// point lies in its piece's polytope (where it has one: the trimming must keep it).
double check_patch_to_surface(const Parametrization& parametrization, const PatchApproximation& a) {
  const Patch patch(parametrization);
  std::vector<Surface> surfaces;
  for (const ApproximationPiece& piece : a.pieces) surfaces.emplace_back(piece);
  const std::size_t side = 200;
  std::size_t failures = 0;
  double worst = 0;
  for (std::size_t i = 0; i < side; ++i) {
    for (std::size_t j = 0; j < side; ++j) {
      const double s = (double(i) + 0.5) / side, t = (double(j) + 0.5) / side;
      const std::size_t k = piece_at(a, s, t);
      const ApproximationPiece& piece = a.pieces[k];
      const Surface& q = surfaces[k];
      const Point p = patch(s, t), g = q.gradient(p);
      if (piece.polytope) {
        EXPECT_LE(polytope_excess(*piece.polytope, p), 1e-9L * a.diagonal) << "X(" << s << ", " << t << ")";
      }
      const Point n{g[0] / norm(g), g[1] / norm(g), g[2] / norm(g)};
      const double bound = piece.patch_to_surface * (1 + 1e-6) + 1e-12 * a.diagonal;
      std::optional<double> root;
      const double q0 = q.value(p);
      // The sign at ±B first (a change there proves a root; bisection then finds how
      // far), else 32 steps each way.
      for (const double end : {bound, -bound}) {
        if (root || q0 == 0 || (q.value(along(p, n, end)) > 0) == (q0 > 0)) continue;
        double inside = 0, outside = end;
        for (int halving = 0; halving < 40; ++halving) {
          const double middle = (inside + outside) / 2;
          ((q.value(along(p, n, middle)) > 0) == (q0 > 0) ? inside : outside) = middle;
        }
        root = std::abs(outside);
      }
      for (int step = 1; step <= 32 && !root && q0 != 0; ++step) {
        for (const double lambda : {bound * step / 32, -bound * step / 32}) {
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

// The distance from y to X(whole): from the nearest point of a 20×20 grid of `near`,
// and from that of a 20×20 grid of `whole` (near ⊂ whole), a compass search in
// `whole` (no derivatives); the smaller. Two starts, because a folded patch brings
// another part of X(whole) close, where a single search can stop in a local minimum.
double distance_to_patch(const Patch& patch, const std::array<double, 4>& near, const std::array<double, 4>& whole,
                         const Point& y) {
  const auto gap = [&](double s, double t) {
    const Point x = patch(s, t);
    return norm({x[0] - y[0], x[1] - y[1], x[2] - y[2]});
  };
  double overall = std::numeric_limits<double>::infinity();
  for (const auto& r : {near, whole}) {
    double best = std::numeric_limits<double>::infinity(), bs = r[0], bt = r[2];
    for (int i = 0; i <= 20; ++i) {
      for (int j = 0; j <= 20; ++j) {
        const double s = r[0] + (r[1] - r[0]) * i / 20, t = r[2] + (r[3] - r[2]) * j / 20, d = gap(s, t);
        if (d < best) best = d, bs = s, bt = t;
      }
    }
    for (double step = (r[1] - r[0] + r[3] - r[2]) / 40; step > 1e-9; step /= 2) {
      for (bool moved = true; moved;) {
        moved = false;
        for (const auto& [ds, dt] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const double s = std::clamp(bs + ds * step, whole[0], whole[1]);
          const double t = std::clamp(bt + dt * step, whole[2], whole[3]), d = gap(s, t);
          if (d < best) best = d, bs = s, bt = t, moved = true;
        }
      }
    }
    overall = std::min(overall, best);
  }
  return overall;
}

// Surface → patch: points of {q = 0} found from 24×24 patch points per piece moved at
// random by up to 0.1·h (h the piece box's largest half side), projected by Newton along
// ∇q; each that the trimming keeps (in the piece's polytope and box where it has one,
// else within 0.1·h of X(S)) within EPS·diagonal of X(D') (D' = D widened by a quarter
// of its sides; the nearest patch point searched near S' = S widened likewise, and
// over D').
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
    const std::array<double, 4> widened{r[0] - ws, r[1] + ws, r[2] - wt, r[3] + wt}, whole{-0.25, 1.25, -0.25, 1.25};
    const Surface q(piece);
    for (int i = 0; i < 24; ++i) {
      for (int j = 0; j < 24; ++j) {
        Point p = patch(r[0] + (r[1] - r[0]) * (i + 0.31) / 24, r[2] + (r[3] - r[2]) * (j + 0.77) / 24);
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
        // The part the trimming keeps.
        if (piece.polytope ? polytope_excess(*piece.polytope, y) > 0 || !in_box(piece, y)
                           : distance_to_patch(patch, r, r, y) > 0.1 * h) {
          continue;
        }
        const double dist = distance_to_patch(patch, widened, whole, y);
        EXPECT_LE(dist, a.tolerance * a.diagonal)
            << "piece [" << r[0] << ", " << r[1] << "]x[" << r[2] << ", " << r[3] << "] degree " << piece.degree
            << (piece.polytope ? ", trimmed to its polytope" : ", trimmed to a cover") << ", point (" << y[0] << ", "
            << y[1] << ", " << y[2] << ")";
        worst = std::max(worst, dist);
      }
    }
  }
  return worst / a.diagonal;
}

std::size_t total_terms(const PatchApproximation& a) {
  std::size_t terms = 0;
  for (const ApproximationPiece& p : a.pieces) terms += p.equation.num_terms();
  return terms;
}

// One row of the trade table: approximate, then check the two-sided bound on the
// test's own sample. `may_refuse`: rows where the library answers tolerance_not_met
// within the default 64 pieces (then the best bound it reports must exceed EPS: never
// a silent worse answer).
void check_row(const char* name, double eps, bool may_refuse) {
  const Parametrization parametrization = parametrization_of(name);
  ApproximationParams params;
  params.tolerance = eps;
  const auto start = std::chrono::steady_clock::now();
  std::optional<PatchApproximation> approximation;
  try {
    approximation = approximate_patch(parametrization, unit_square(), params);
  } catch (const ToleranceNotMet& e) {
    ASSERT_TRUE(may_refuse) << e.what();
    EXPECT_GT(e.best(), eps);
    std::printf("%s EPS %g: tolerance_not_met, best %.3g; %.2f s\n", name, eps, e.best(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const PatchApproximation& a = *approximation;
  ASSERT_FALSE(a.pieces.empty());
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

std::string row_name(const char* name, double eps) {
  return std::string(name) + (eps > 5e-3 ? "_1em2" : eps > 5e-4 ? "_1em3" : "_1em4");
}

class TwoSided : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(TwoSided, BoundHoldsOnAnIndependentDenseSample) {
  const auto [name, eps] = GetParam();
  check_row(name, eps, false);
}

// Every surface at 1e-2 and 1e-3 but tri_quartic at 1e-3 (a slow row, below).
INSTANTIATE_TEST_SUITE_P(BenchPatches, TwoSided,
                         ::testing::Values(std::tuple{"tp_22", 1e-2}, std::tuple{"tp_22", 1e-3},
                                           std::tuple{"tp_33", 1e-2}, std::tuple{"tp_33", 1e-3},
                                           std::tuple{"biquadratic_patch", 1e-2}, std::tuple{"biquadratic_patch", 1e-3},
                                           std::tuple{"enneper", 1e-2}, std::tuple{"enneper", 1e-3},
                                           std::tuple{"tri_quartic", 1e-2}),
                         [](const auto& param_info) {
                           return row_name(std::get<0>(param_info.param), std::get<1>(param_info.param));
                         });

// The slow rows, for the trade table (run with --gtest_also_run_disabled_tests): EPS =
// 1e-4 on every surface, and tri_quartic at 1e-3, whose near-singular point at
// (s, t) ≈ (0.63, 0.63) (|X_s × X_t| 0.7 against ~30 elsewhere) takes more than the
// default 64 pieces (docs/sdf.md). These may answer tolerance_not_met.
class TradeRow : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(TradeRow, DISABLED_SlowRow) { check_row(std::get<0>(GetParam()), std::get<1>(GetParam()), true); }

INSTANTIATE_TEST_SUITE_P(BenchPatches, TradeRow,
                         ::testing::Values(std::tuple{"tp_22", 1e-4}, std::tuple{"tp_33", 1e-4},
                                           std::tuple{"biquadratic_patch", 1e-4}, std::tuple{"enneper", 1e-4},
                                           std::tuple{"tri_quartic", 1e-4}, std::tuple{"tri_quartic", 1e-3}),
                         [](const auto& param_info) {
                           return row_name(std::get<0>(param_info.param), std::get<1>(param_info.param));
                         });

// q·k = Singular's equation for one k ≠ 0, up to the rounding of the SVD's vector.
void expect_multiple_of_expected(const Polynomial& q, const std::string& name) {
  const std::string text =
      testing::read_text(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/expected/" + name + ".txt");
  const Polynomial expected = parse_polynomial(text, q.ring());
  ASSERT_EQ(q.total_degree(), expected.total_degree());
  // k from the expected equation's leading term; then every coefficient of both.
  std::vector<Rational> point;
  const auto coefficient_of = [](const Polynomial& p, const std::vector<std::int32_t>& e) {
    for (std::size_t t = 0; t < p.num_terms(); ++t) {
      if (p.exponents(t) == e) return to_mpq(p.coefficient(t)).get_d();
    }
    return 0.0;
  };
  const double k = coefficient_of(q, expected.exponents(0)) / to_mpq(expected.coefficient(0)).get_d();
  ASSERT_NE(k, 0.0);
  for (std::size_t t = 0; t < expected.num_terms(); ++t) {
    EXPECT_NEAR(coefficient_of(q, expected.exponents(t)), k * to_mpq(expected.coefficient(t)).get_d(), 1e-9);
  }
  for (std::size_t t = 0; t < q.num_terms(); ++t) {
    EXPECT_NEAR(to_mpq(q.coefficient(t)).get_d(), k * coefficient_of(expected, q.exponents(t)), 1e-9);
  }
}

TEST(ApproximatePatch, QuadricComesBackAsItsExactEquation) {
  // A polynomial and a rational quadric: a plane cannot meet 1e-4 on them, degree 2
  // is exact, so one piece of degree 2 carries Singular's equation.
  for (const char* name : {"elliptic_paraboloid", "unit_sphere"}) {
    SCOPED_TRACE(name);
    ApproximationParams params;
    params.tolerance = 1e-4;
    params.max_degree = 2;
    const PatchApproximation a = approximate_patch(parametrization_of(name), unit_square(), params);
    ASSERT_EQ(a.pieces.size(), 1u);
    EXPECT_EQ(a.pieces[0].degree, 2);
    expect_multiple_of_expected(a.pieces[0].equation, name);
    EXPECT_LT(a.patch_to_surface, 1e-9);
    EXPECT_EQ(a.patch_to_surface_method, BoundMethod::certified);
  }
}

TEST(ApproximatePatch, RefusesInvalidTolerances) {
  const Parametrization p = parametrization_of("tp_33");
  for (const double eps : {0.0, -1.0, 0.6, std::nan(""), std::numeric_limits<double>::infinity()}) {
    ApproximationParams params;
    params.tolerance = eps;
    try {
      approximate_patch(p, unit_square(), params);
      ADD_FAILURE() << "accepted tolerance " << eps;
    } catch (const InputError& e) {
      EXPECT_EQ(e.code(), "invalid_tolerance") << eps;
      EXPECT_EQ(e.field(), "tolerance");
    }
  }
}

TEST(ApproximatePatch, RefusesCurvesAndEmptyDomains) {
  const Parametrization curve = parse_parametrization(std::vector<std::string>{"t", "t^2"});
  EXPECT_THROW(approximate_patch(curve, ParameterDomain{{{Rational(0), Rational(1)}}}, {}), InputError);
  const Parametrization p = parametrization_of("tp_22");
  try {
    approximate_patch(p, ParameterDomain{{{Rational(0), Rational(0)}, {Rational(0), Rational(1)}}}, {});
    ADD_FAILURE() << "accepted a domain with lo = hi";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "invalid_domain");
  }
}

TEST(ApproximatePatch, SaysWhenTheToleranceCannotBeMet) {
  ApproximationParams params;
  params.tolerance = 1e-4;
  params.max_pieces = 1;
  params.max_degree = 1;
  try {
    approximate_patch(parametrization_of("tp_33"), unit_square(), params);
    ADD_FAILURE() << "a plane met 1e-4 on tp_33";
  } catch (const ToleranceNotMet& e) {
    EXPECT_GT(e.best(), 1e-4);
    EXPECT_TRUE(std::isfinite(e.best()));
    EXPECT_NE(std::string(e.what()).find("0.0001"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace implicitizer
