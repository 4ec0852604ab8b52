// Tests of substitute_trigonometric and map_parameter_domain
// (lib/src/implicitization/trigonometric_substitution.cpp) through parse_parametrization:
// the rational forms agree with cos, sin, tan, cosh, sinh, tanh at sample points, the
// identities hold exactly, issue 20's surfaces and curves give the expected equations,
// and every refusal has its code, field and position.

#include "implicitizer/implicitization/trigonometric_substitution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {
namespace {

double value_at(const RationalFunction& f, const std::vector<double>& point) {
  std::vector<Rational> exact;
  for (double p : point) exact.emplace_back(p);
  return CGAL::to_double(f.numerator().evaluate(exact)) / CGAL::to_double(f.denominator().evaluate(exact));
}

// The implicit equation of a parametrization compared with `expected` up to a constant
// factor (both made primitive with a positive leading coefficient).
void expect_equation(const std::vector<std::string>& coordinates, const std::string& expected) {
  const ImplicitizeResult r = implicitize(parse_parametrization(coordinates));
  EXPECT_TRUE(r.verified);
  const Polynomial want = parse_polynomial(expected, implicit_ring(coordinates.size())).primitive_part();
  EXPECT_EQ(to_string(r.implicit), to_string(want));
}

// Issue 20's expected answers, each up to a constant factor.
TEST(TrigonometricSubstitution, IssueExamplesGiveTheExpectedEquations) {
  expect_equation({"cos(u)*cos(v)", "cos(u)*sin(v)", "sin(u)"}, "x^2+y^2+z^2-1");
  expect_equation({"(2+cos(v))*cos(u)", "(2+cos(v))*sin(u)", "sin(v)"}, "(x^2+y^2+z^2+3)^2-16*(x^2+y^2)");
  expect_equation({"cosh(u)*cos(v)", "cosh(u)*sin(v)", "sinh(u)"}, "x^2+y^2-z^2-1");
  expect_equation({"cos(2*t)", "sin(t)"}, "x+2*y^2-1");
  expect_equation({"cos(t)^3", "sin(t)^3"}, "(x^2+y^2-1)^3+27*x^2*y^2");
}

// The rational form against the functions themselves at random angles: the θ_j go to
// t_j = tan(θ_j/2) (half angle) or e_j = exp(θ_j) and the values must agree.
TEST(TrigonometricSubstitution, RationalFormsAgreeWithTheFunctionsAtRandomPoints) {
  struct Case {
    std::string text;
    double (*f)(double, double);
  };
  const std::vector<Case> trigonometric = {
      {"cos(3*u-2*v)", [](double u, double v) { return std::cos(3 * u - 2 * v); }},
      {"sin(u+v)^2", [](double u, double v) { return std::pow(std::sin(u + v), 2); }},
      {"tan(2*v)", [](double, double v) { return std::tan(2 * v); }},
      {"cos(-u)*sin(-5*v)", [](double u, double v) { return std::cos(-u) * std::sin(-5 * v); }},
  };
  const std::vector<Case> hyperbolic = {
      {"cosh(2*u-v)", [](double u, double v) { return std::cosh(2 * u - v); }},
      {"sinh(u+3*v)", [](double u, double v) { return std::sinh(u + 3 * v); }},
      {"tanh(-u)", [](double u, double) { return std::tanh(-u); }},
  };
  std::mt19937 random(20);
  std::uniform_real_distribution<double> angle(-1.4, 1.4);
  for (const auto* cases : {&trigonometric, &hyperbolic}) {
    const bool half_angle = cases == &trigonometric;
    for (const Case& c : *cases) {
      SCOPED_TRACE(c.text);
      const Parametrization p = parse_parametrization({c.text, "1"}, std::vector<std::string>{"u", "v"});
      ASSERT_FALSE(p.substitutions.empty());
      const std::size_t samples = 20;
      for (std::size_t i = 0; i < samples; ++i) {
        const double u = angle(random), v = angle(random);
        const auto to = [&](double theta) { return half_angle ? std::tan(theta / 2) : std::exp(theta); };
        const double want = c.f(u, v);
        EXPECT_NEAR(value_at(p.coordinates[0], {to(u), to(v)}), want, 1e-9 * (1 + std::abs(want)));
      }
    }
  }
}

TEST(TrigonometricSubstitution, IdentitiesHoldExactly) {
  const auto same = [](const std::string& a, const std::string& b) {
    const Parametrization p = parse_parametrization({a, b}, std::vector<std::string>{"u", "v"});
    EXPECT_EQ(p.coordinates[0].numerator(), p.coordinates[1].numerator()) << a << " vs " << b;
    EXPECT_EQ(p.coordinates[0].denominator(), p.coordinates[1].denominator()) << a << " vs " << b;
  };
  same("cos(3*u)+0*cos(v)", "4*cos(u)^3-3*cos(u)");
  same("sin(u+v)", "sin(u)*cos(v)+cos(u)*sin(v)");
  same("tan(2*u)+0*cos(v)", "2*tan(u)/(1-tan(u)^2)");
  same("cos(u)^2+sin(u)^2+cos(v)", "1+cos(v)");
  same("cos(u-u)+sin(v)", "1+sin(v)");
  same("cosh(u+v)", "cosh(u)*cosh(v)+sinh(u)*sinh(v)");
  same("tanh(u)+0*cosh(v)", "sinh(u)/cosh(u)");
  same("cosh(u)^2-sinh(u)^2+cosh(v)", "1+cosh(v)");
}

TEST(TrigonometricSubstitution, SaysWhichSubstitutionWasMade) {
  const Parametrization p = parse_parametrization({"cosh(u)*cos(v)", "tu", "sinh(u)"});
  ASSERT_EQ(p.substitutions.size(), 2u);
  EXPECT_EQ(to_string(p.substitutions[0]), "eu = exp(u)");
  EXPECT_EQ(p.substitutions[0].kind, ParameterSubstitution::Kind::exponential);
  // v's natural name tv is free; u's exponential eu too; a taken name gets a number.
  EXPECT_EQ(to_string(p.substitutions[1]), "tv = tan(v/2)");
  EXPECT_EQ(p.parameter_ring->variables(), (std::vector<std::string>{"eu", "tv", "tu"}));
  const Parametrization q = parse_parametrization({"cos(u)", "tu", "v"});
  EXPECT_EQ(q.parameter_ring->variables(), (std::vector<std::string>{"tu1", "tu", "v"}));
  // A rational input is not touched.
  EXPECT_TRUE(parse_parametrization({"s", "t", "s*t"}).substitutions.empty());
}

::testing::AssertionResult refuses(const std::vector<std::string>& coordinates, const std::string& code,
                                   const std::string& field, std::size_t position, const std::string& named) {
  try {
    parse_parametrization(coordinates);
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (e.code() == code && e.field() == field && e.position() == position &&
        message.find("'" + named + "'") != std::string::npos) {
      return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << "got " << e.code() << " in " << e.field() << " at "
                                         << e.position().value_or(999) << ": " << message;
  }
  return ::testing::AssertionFailure() << "accepted";
}

TEST(TrigonometricSubstitution, RefusesWhatHasNoRationalForm) {
  EXPECT_TRUE(refuses({"u*cos(u)", "sin(u)"}, "parameter_inside_and_outside", "x", 2, "cos"));
  EXPECT_TRUE(refuses({"cos(u)", "v", "u"}, "parameter_inside_and_outside", "x", 0, "cos"));
  EXPECT_TRUE(refuses({"cos(s*t)", "sin(t)", "s"}, "nonlinear_argument", "x", 0, "cos"));
  EXPECT_TRUE(refuses({"s", "sin(t^2)", "s"}, "nonlinear_argument", "y", 0, "sin"));
  EXPECT_TRUE(refuses({"s", "t", "1+tan(cos(t))"}, "nonlinear_argument", "z", 2, "tan"));
  EXPECT_TRUE(refuses({"cos(u/2)", "sin(u)"}, "non_integer_argument", "x", 0, "cos"));
  EXPECT_TRUE(refuses({"cos(u+1)", "sin(u)"}, "non_integer_argument", "x", 0, "cos"));
  EXPECT_TRUE(refuses({"cos(u)*cosh(u)", "sin(u)"}, "mixed_function_kinds", "x", 7, "cosh"));
  EXPECT_TRUE(refuses({"cos(1001*u)", "sin(u)"}, "multiple_too_large", "x", 0, "cos"));
  EXPECT_TRUE(refuses({"sqrt(s)", "t", "s"}, "function_not_rational", "x", 0, "sqrt"));
  EXPECT_TRUE(refuses({"s", "exp(t)", "s"}, "function_not_rational", "y", 0, "exp"));
  EXPECT_TRUE(refuses({"s", "t", "2*log(s)"}, "function_not_rational", "z", 2, "log"));
  EXPECT_TRUE(refuses({"s", "t", "arcsin(s)"}, "unknown_function", "z", 0, "arcsin"));
}

TEST(TrigonometricSubstitution, DomainsInAnglesMapThroughTheSubstitution) {
  const Parametrization p = parse_parametrization({"cosh(u)*cos(v)", "cosh(u)*sin(v)", "w"});
  ParameterDomain angles{{{Rational(-1), Rational(2)}, {Rational(0), Rational(3)}, {Rational(5), Rational(6)}}};
  const ParameterDomain mapped = map_parameter_domain(p.substitutions, *p.parameter_ring, angles);
  EXPECT_EQ(CGAL::to_double(mapped.intervals[0].first), std::exp(-1.0));
  EXPECT_EQ(CGAL::to_double(mapped.intervals[0].second), std::exp(2.0));
  EXPECT_EQ(CGAL::to_double(mapped.intervals[1].first), 0.0);
  EXPECT_EQ(CGAL::to_double(mapped.intervals[1].second), std::tan(1.5));
  EXPECT_EQ(mapped.intervals[2], angles.intervals[2]);
  // θ = π is t = ∞: an angle interval reaching past π has no finite image.
  ParameterDomain past_pi{{{Rational(0), Rational(1)}, {Rational(0), Rational(16, 5)}, {Rational(0), Rational(1)}}};
  try {
    map_parameter_domain(p.substitutions, *p.parameter_ring, past_pi);
    FAIL() << "accepted an angle beyond pi";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "domain_out_of_range");
    EXPECT_EQ(e.field(), "domain");
  }
}

// ---- issue 41: every phase of the conversion within its limits --------------------
//
// The reproducers ran 25–48 s past 1–2 s limits and held 2–5 GB: products and common
// denominators were built whole before any limit was read. These tests assert what
// does not depend on the machine's speed: which limit stopped the computation, the
// phase it names, the size it predicted, and the memory the budget's account held.

constexpr const char* kPowers[] = {"sin(u)^1000", "cos(v)^1000", "sin(u+v)"};
constexpr const char* kMultiples[] = {"cos(999*u)*cos(1000*v)", "sin(999*u)", "sin(1000*v)"};
constexpr std::size_t kMiB = std::size_t{1} << 20;

std::vector<std::string> texts(const char* const (&coordinates)[3]) {
  return {coordinates[0], coordinates[1], coordinates[2]};
}

// Runs `compute` charging `budget`'s account (as a server worker and the command line
// do) and returns the LimitExceeded it must throw.
template <typename Compute>
LimitExceeded limit_of(const Budget& budget, Compute compute) {
  try {
    compute_charging(budget, compute);
  } catch (const LimitExceeded& e) {
    return e;
  }
  ADD_FAILURE() << "the computation completed";
  return LimitExceeded(Limit::cancelled, "");
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The server's term limit (200 000): the lcm of (1 + t²)^1000 and (1 + s²)^1000 has
// exactly 1001·1001 terms, known before it is multiplied.
TEST(TrigonometricLimits, PowersAreRefusedInTheCommonDenominatorBeforeItIsBuilt) {
  Budget budget;
  budget.set_max_terms(200'000).set_max_memory(std::size_t{4} << 30);  // the account measures
  ImplicitizeParams params;
  params.budget = budget;
  const LimitExceeded e =
      limit_of(budget, [&] { implicitize(parse_parametrization(texts(kPowers), {}, budget), params); });
  EXPECT_EQ(e.limit(), Limit::size);
  EXPECT_TRUE(contains(e.what(), "in the common denominator of the parametrization")) << e.what();
  EXPECT_TRUE(contains(e.what(), "would have 1002001 terms (limit 200000)")) << e.what();
  // The product's coefficients alone (about 1200 bits each) would hold more than 150 MiB.
  if (memory_accounting_enabled()) {
    EXPECT_LT(budget.memory_account()->peak_bytes(), 32 * kMiB);
  }
}

// The numerators of cos(999u) and cos(1000v) have 1000 and 1001 terms: their product
// is refused in the substitution itself, before the product or any gcd of it.
TEST(TrigonometricLimits, MultiplesAreRefusedInTheSubstitutionBeforeTheProduct) {
  Budget budget;
  budget.set_max_terms(200'000).set_max_memory(std::size_t{4} << 30);
  const LimitExceeded e = limit_of(budget, [&] { parse_parametrization(texts(kMultiples), {}, budget); });
  EXPECT_EQ(e.limit(), Limit::size);
  EXPECT_TRUE(contains(e.what(), "in the trigonometric substitution")) << e.what();
  EXPECT_TRUE(contains(e.what(), "the product of 1000 and 1001 terms in disjoint variables would have 1001000 terms"))
      << e.what();
  if (memory_accounting_enabled()) {
    EXPECT_LT(budget.memory_account()->peak_bytes(), 32 * kMiB);
  }
}

// No term limit, a memory limit: the products are stopped while they grow, within a
// tenth of the limit (the 512 MiB server "held 634 MiB" before).
TEST(TrigonometricLimits, MemoryLimitHoldsWhileTheProductsGrow) {
  if (!memory_accounting_enabled()) GTEST_SKIP() << "a sanitizer build counts no allocations";
  const std::size_t limit = 64 * kMiB;
  {
    Budget budget;
    budget.set_max_memory(limit);
    ImplicitizeParams params;
    params.budget = budget;
    const LimitExceeded e =
        limit_of(budget, [&] { implicitize(parse_parametrization(texts(kPowers), {}, budget), params); });
    EXPECT_EQ(e.limit(), Limit::memory) << e.what();
    EXPECT_TRUE(contains(e.what(), "in the common denominator of the parametrization")) << e.what();
    EXPECT_LE(budget.memory_account()->peak_bytes(), limit + limit / 10);
  }
  {
    Budget budget;
    budget.set_max_memory(limit);
    const LimitExceeded e = limit_of(budget, [&] { parse_parametrization(texts(kMultiples), {}, budget); });
    EXPECT_EQ(e.limit(), Limit::memory) << e.what();
    EXPECT_TRUE(contains(e.what(), "in the trigonometric substitution")) << e.what();
    EXPECT_LE(budget.memory_account()->peak_bytes(), limit + limit / 10);
  }
}

// A time limit alone stops the computation by the limit, not by completing (no
// machine computes these in a second), and every phase reads the clock: with the
// deadline already past, the common denominator stops at its first check.
TEST(TrigonometricLimits, TimeLimitStopsEveryPhase) {
  Budget budget = Budget::with_timeout(1);
  ImplicitizeParams params;
  params.budget = budget;
  const LimitExceeded e =
      limit_of(budget, [&] { implicitize(parse_parametrization(texts(kPowers), {}, budget), params); });
  EXPECT_EQ(e.limit(), Limit::time) << e.what();

  const Parametrization p = parse_parametrization(texts(kPowers));
  const Budget past = Budget::with_timeout(1e-9);
  const LimitExceeded late = limit_of(past, [&] { common_denominator_form(p, past); });
  EXPECT_EQ(late.limit(), Limit::time);
  EXPECT_TRUE(contains(late.what(), "in the common denominator of the parametrization")) << late.what();
}

}  // namespace
}  // namespace implicitizer
