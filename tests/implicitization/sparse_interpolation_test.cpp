// Tests of lib/src/implicitization/sparse_interpolation.cpp: sparse_s7t7 against the
// bench's answer, other sparse maps against Singular's elimination run live, the
// minimality check on the classes, the fall-back of a map of degree > 1, rejected
// candidates, and the budget's limits.

#include "implicitizer/implicitization/sparse_interpolation.hpp"

#include <gtest/gtest.h>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "oracle/oracle_support.hpp"

namespace implicitizer {
namespace {

const std::string kBench = std::string(IMPLICITIZER_SHARED_DIR) + "/bench";

Parametrization s7t7() { return parse_parametrization("s^7+t", "t^7+s", "s*t^3"); }

Polynomial expected_s7t7() {
  return parse_polynomial(testing::read_text(kBench + "/expected/sparse_s7t7.txt"), space_ring());
}

std::optional<InterpolationResult> sparse(const Parametrization& p, const InterpolationParams& options = {}) {
  const auto support = predict_implicit_support(p);
  if (!support) throw std::logic_error("no prediction");
  return implicitize_by_sparse_interpolation(p, *support, options);
}

TEST(SparseInterpolation, S7t7IsTheBenchAnswer) {
  const auto r = sparse(s7t7());
  ASSERT_TRUE(r);
  EXPECT_TRUE(testing::equal_up_to_scalar(r->implicit, expected_s7t7()));
  EXPECT_EQ(r->stats.degree, 49);
  EXPECT_EQ(r->stats.degree_bound, 49);
  EXPECT_LE(r->stats.columns, 200u);       // one class, not the 22,100 dense columns
  EXPECT_GE(r->stats.degree_probes, 48u);  // every class had a kernel
  EXPECT_EQ(r->stats.rejected_candidates, 0u);
}

TEST(SparseInterpolation, AutoTakesItForS7t7) {
  const ImplicitizeResult r = implicitize(s7t7());
  EXPECT_EQ(r.method, "interpolation");
  EXPECT_NE(r.route.find("predicted support"), std::string::npos) << r.route;
  EXPECT_TRUE(r.verified);
  EXPECT_EQ(r.degree, 49);
  EXPECT_TRUE(testing::equal_up_to_scalar(r.implicit, expected_s7t7()));
}

TEST(SparseInterpolation, MethodInterpolationTakesItWhereTheDenseMatrixIsTooLarge) {
  // The dense bound 49 needs 22,100 columns, past the limit of 3,000: the route used to refuse.
  ImplicitizeParams options;
  options.method = ImplicitizationMethod::interpolation;
  const ImplicitizeResult r = implicitize(s7t7(), options);
  EXPECT_EQ(r.method, "interpolation");
  EXPECT_TRUE(r.verified);
  ASSERT_TRUE(r.interpolation_stats);
  EXPECT_LE(r.interpolation_stats->columns, 200u);
  EXPECT_TRUE(testing::equal_up_to_scalar(r.implicit, expected_s7t7()));
}

// A map as numerators and one denominator, for the route and for Singular.
struct SparseMap {
  std::string x, y, z, denominator;
  int degree;
};

// Singular's elimination of <d·x − p_x, d·y − p_y, d·z − p_z, 1 − d·w>, printed
// between markers.
std::string singular_script(const SparseMap& m) {
  return "ring r = 0, (w,s,t,x,y,z), dp;\nshort = 0;\npoly d = " + m.denominator + ";\nideal I = d*x-(" + m.x +
         "), d*y-(" + m.y + "), d*z-(" + m.z + "), 1-d*w;\nideal J = eliminate(I, w*s*t);\n\"" +
         testing::section_marker("begin") + "\";\nint i;\nfor (i = 1; i <= size(J); i++) { print(J[i]); }\n\"" +
         testing::section_marker("end") + "\";\nquit;\n";
}

TEST(SparseInterpolation, SparseMapsAgreeWithSingular) {
  const SparseMap maps[] = {
      {"s^5+t", "t^4+s", "s*t^2", "1", 20},   {"s^6+t", "t^5+s^2", "s*t^2", "1", 30},
      {"s^3+t", "t^3+s", "s*t", "1", 9},      {"s^5+t^2", "t^3+s", "s^2*t", "1", 15},
      {"s^4+t", "t^4-s", "s*t^2+1", "1", 16}, {"s^5+t", "s*t^4+s^2*t", "s^2*t^3", "s*t", 15},
  };
  for (const SparseMap& m : maps) {
    SCOPED_TRACE(m.x + ", " + m.y + ", " + m.z + " over " + m.denominator);
    const std::string over = "/(" + m.denominator + ")";
    const Parametrization p =
        parse_parametrization("(" + m.x + ")" + over, "(" + m.y + ")" + over, "(" + m.z + ")" + over);
    const auto ours = sparse(p);
    ASSERT_TRUE(ours);
    EXPECT_EQ(ours->stats.degree, m.degree);
    const ImplicitEquationCheck check = check_implicit_equation(ours->implicit, p);
    EXPECT_TRUE(check.vanishes);
    EXPECT_TRUE(check.minimal);
    if (!testing::is_runnable(testing::kSingular)) continue;
    const testing::ScriptRun run = testing::run_singular(singular_script(m));
    ASSERT_EQ(run.exit_code, 0) << run.describe();
    auto sections = testing::split_sections(run.out);
    ASSERT_EQ(sections["begin"].size(), 1u) << "not one generator:\n" << run.describe();
    EXPECT_TRUE(testing::equal_up_to_scalar(ours->implicit, parse_polynomial(sections["begin"][0], space_ring())));
  }
}

TEST(SparseInterpolation, MinimalityOfDegree49IsCheckedOnTheClasses) {
  // The dense check would need 22,100 columns; it refused beyond 3,000.
  const Parametrization p = s7t7();
  const Polynomial f = expected_s7t7();
  const ImplicitEquationCheck good = check_implicit_equation(f, p);
  EXPECT_TRUE(good.vanishes);
  EXPECT_TRUE(good.minimal);
  const ImplicitEquationCheck multiple = check_implicit_equation(f * Polynomial::variable(f.ring(), 2), p);
  EXPECT_TRUE(multiple.vanishes);
  EXPECT_FALSE(multiple.minimal);
  const Polynomial changed = f + Polynomial::constant(f.ring(), Rational(1)) * Polynomial::variable(f.ring(), 2);
  const ImplicitEquationCheck bad = check_implicit_equation(changed, p);
  EXPECT_FALSE(bad.vanishes);
  EXPECT_FALSE(bad.minimal);
}

TEST(SparseInterpolation, AMapOfDegreeFourFallsBack) {
  // (s, t) → (s², t²) followed by x = u^3 + v, y = v^3 + u, z = u·v: every box bound is
  // four times the degree 9, so multiples of the equation fit and no class is left
  // with a one-dimensional kernel. auto then answers by another route, with the
  // equation of the map without squares.
  const Parametrization squared = parse_parametrization("s^6+t^2", "t^6+s^2", "s^2*t^2");
  EXPECT_FALSE(sparse(squared));
  const ImplicitizeResult r = implicitize(squared);
  EXPECT_EQ(r.route.find("predicted support"), std::string::npos) << r.route;
  const auto plain = sparse(parse_parametrization("s^3+t", "t^3+s", "s*t"));
  ASSERT_TRUE(plain);
  EXPECT_TRUE(testing::equal_up_to_scalar(r.implicit, plain->implicit));
}

TEST(SparseInterpolation, ACorruptedCandidateIsNeverReturned) {
  InterpolationParams options;
  options.max_primes = 6;
  options.tamper_candidate = [](Polynomial& f) { f = f + Polynomial::constant(f.ring(), Rational(1)); };
  EXPECT_FALSE(sparse(parse_parametrization("s^5+t", "t^4+s", "s*t^2"), options));
}

TEST(SparseInterpolation, NotASurface) {
  EXPECT_THROW(sparse(parse_parametrization("s+t^2", "(s+t^2)^2", "(s+t^2)^3")), NoSingleEquation);
}

TEST(SparseInterpolation, LimitsStopItAndSayWhich) {
  const Parametrization p = s7t7();
  InterpolationParams cancelled;
  cancelled.budget.cancel();
  try {
    sparse(p, cancelled);
    FAIL() << "a cancelled budget ran";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
  InterpolationParams quick;
  quick.budget.set_timeout(1e-4);
  try {
    sparse(p, quick);
    FAIL() << "sparse_s7t7 finished in 0.1 ms";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
  InterpolationParams narrow;
  narrow.max_columns = 100;  // the largest class has 187 monomials
  try {
    sparse(p, narrow);
    FAIL() << "no size limit";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
    EXPECT_NE(std::string(e.what()).find("class"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace implicitizer
