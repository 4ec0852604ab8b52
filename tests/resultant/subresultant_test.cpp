// Tests of lib/src/resultant/subresultant.cpp: resultants and discriminants known
// by hand, the subresultant PRS against Bareiss' determinant of the Sylvester matrix
// and against FLINT on seeded random pairs (defective chains included), the edge
// cases of the conventions, and the budget.

#include "implicitizer/resultant/subresultant.hpp"

#include <flint/fmpz_mpoly.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/resultant/sylvester.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

// Σ_{i ≤ degree} c_i·x_var^i with random coefficients c_i in the other variables:
// up to `terms` terms each, exponents ≤ 2, c_degree ≠ 0. Coefficients are small
// integers, or random rationals (some huge) when `rational` is set.
Polynomial random_in(testing::RandomSource& random, const RingPtr& ring, std::size_t var, int degree, int terms,
                     bool rational) {
  Polynomial f(ring);
  std::vector<std::int32_t> e(ring->num_variables());
  for (int i = 0; i <= degree; ++i) {
    Polynomial c(ring);
    const long count = random.uniform(i == degree ? 1 : 0, terms);
    for (long k = 0; k < count; ++k) {
      for (std::size_t v = 0; v < e.size(); ++v) e[v] = v == var ? 0 : static_cast<std::int32_t>(random.uniform(0, 2));
      Rational coefficient;
      if (rational) {
        coefficient = random.rational();
      } else {
        const long magnitude = random.uniform(1, 9);
        coefficient = Rational(static_cast<int>(random.uniform(0, 1) ? magnitude : -magnitude));
      }
      c += Polynomial::term(ring, coefficient, e);
    }
    if (i == degree && c.is_zero()) c = Polynomial::constant(ring, Rational(1));
    std::fill(e.begin(), e.end(), 0);
    e[var] = i;
    f += c * Polynomial::term(ring, Rational(1), e);
  }
  return f;
}

// FLINT's fmpz_mpoly_resultant or _discriminant of integer polynomials. The
// polynomials cross over as text (our printer, FLINT's parser and back), which
// keeps this check independent of gcd.cpp's converters.
class FlintOracle {
 public:
  explicit FlintOracle(const RingPtr& ring) : ring_(ring) {
    for (const std::string& name : ring->variables()) names_.push_back(name.c_str());
    fmpz_mpoly_ctx_init(ctx_, static_cast<slong>(names_.size()), ORD_LEX);
  }
  ~FlintOracle() { fmpz_mpoly_ctx_clear(ctx_); }
  FlintOracle(const FlintOracle&) = delete;
  FlintOracle& operator=(const FlintOracle&) = delete;

  Polynomial resultant(const Polynomial& f, const Polynomial& g, std::size_t var) { return run(f, g, var, true); }
  Polynomial discriminant(const Polynomial& f, std::size_t var) { return run(f, f, var, false); }

 private:
  Polynomial run(const Polynomial& f, const Polynomial& g, std::size_t var, bool resultant) {
    fmpz_mpoly_t a, b, r;
    fmpz_mpoly_init(a, ctx_);
    fmpz_mpoly_init(b, ctx_);
    fmpz_mpoly_init(r, ctx_);
    EXPECT_EQ(fmpz_mpoly_set_str_pretty(a, to_string(f).c_str(), names_.data(), ctx_), 0) << to_string(f);
    EXPECT_EQ(fmpz_mpoly_set_str_pretty(b, to_string(g).c_str(), names_.data(), ctx_), 0) << to_string(g);
    const int ok = resultant ? fmpz_mpoly_resultant(r, a, b, static_cast<slong>(var), ctx_)
                             : fmpz_mpoly_discriminant(r, a, static_cast<slong>(var), ctx_);
    EXPECT_TRUE(ok) << "FLINT failed";
    char* text = fmpz_mpoly_get_str_pretty(r, names_.data(), ctx_);
    Polynomial out = parse_polynomial(text, ring_);
    flint_free(text);
    fmpz_mpoly_clear(a, ctx_);
    fmpz_mpoly_clear(b, ctx_);
    fmpz_mpoly_clear(r, ctx_);
    return out;
  }

  RingPtr ring_;
  std::vector<const char*> names_;
  fmpz_mpoly_ctx_t ctx_;
};

class SubresultantTest : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"x", "y", "t"});
  static constexpr std::size_t kT = 2;
  Polynomial parse(const std::string& text) const { return parse_polynomial(text, ring_); }
  Polynomial res(const std::string& f, const std::string& g) const { return resultant(parse(f), parse(g), kT); }
  Polynomial disc(const std::string& f) const { return discriminant(parse(f), kT); }
};

TEST_F(SubresultantTest, KnownResultants) {
  // Values Singular 4.3 gives for `resultant(f, g, t)` in ring (x,y,t).
  EXPECT_EQ(res("t^2+x", "y*t+1"), parse("x*y^2+1"));
  EXPECT_EQ(res("y*t+1", "t^2+x"), parse("x*y^2+1"));
  EXPECT_EQ(res("t", "t+1"), parse("1"));
  EXPECT_EQ(res("t+1", "t"), parse("-1"));
  EXPECT_EQ(res("2*t^3+x*t+1", "t^2-y"), parse("-x^2*y-4*x*y^2-4*y^3+1"));
  EXPECT_EQ(res("t^2-y", "2*t^3+x*t+1"), parse("-x^2*y-4*x*y^2-4*y^3+1"));
  EXPECT_EQ(res("x*t^2+1", "x*t+y"), parse("x*y^2+x^2"));
  EXPECT_EQ(res("t^3+x", "t^2+y"), parse("y^3+x^2"));
  EXPECT_EQ(res("3/2*t+1/3", "t^2-1/5"), parse("-61/180"));
  // By hand: Res(a t^2 + b t + c, d t + e) = a e^2 − b d e + c d^2.
  EXPECT_EQ(res("x*t^2+y*t+1", "2*t-x*y"), parse("x*(x*y)^2+y*2*x*y+4"));
  // Res(t − a, g) = g(a).
  EXPECT_EQ(res("t-x", "t^3+y*t+7"), parse("x^3+y*x+7"));
  EXPECT_EQ(res("t^3+y*t+7", "t-x"), parse("-(x^3+y*x+7)"));
}

TEST_F(SubresultantTest, CommonFactorGivesZero) {
  EXPECT_TRUE(res("(t-x)*(t+1)", "(t-x)*(t^2+y)").is_zero());
  EXPECT_TRUE(res("(x*t+y)^2", "(x*t+y)*(t^3-2)").is_zero());
  EXPECT_TRUE(res("t^4-y^2", "t^2-y").is_zero());
}

TEST_F(SubresultantTest, EdgeCases) {
  // Factors free of t: c^deg, whichever side.
  EXPECT_EQ(res("3", "t^2+x"), parse("9"));
  EXPECT_EQ(res("t^2+x", "3"), parse("9"));
  EXPECT_EQ(res("2", "x*t^3+y"), parse("8"));
  EXPECT_EQ(res("x*t^3+y", "2"), parse("8"));
  EXPECT_EQ(res("x", "t^2"), parse("x^2"));
  EXPECT_EQ(res("x+y", "t^3-t"), parse("(x+y)^3"));
  EXPECT_EQ(res("x+y", "x-y"), parse("1"));
  EXPECT_EQ(res("5", "7"), parse("1"));
  // Zero: always 0, against a constant too (as Singular and FLINT).
  EXPECT_TRUE(res("0", "t^2+x").is_zero());
  EXPECT_TRUE(res("x*t^3+y", "0").is_zero());
  EXPECT_TRUE(res("0", "5").is_zero());
  EXPECT_TRUE(res("5", "0").is_zero());
  EXPECT_TRUE(res("0", "0").is_zero());
  // Equal degrees, and a polynomial with itself.
  EXPECT_EQ(res("t^2+x", "t^2+y"), parse("(y-x)^2"));
  EXPECT_TRUE(res("x*t^2+y", "x*t^2+y").is_zero());
}

TEST_F(SubresultantTest, ResultLivesInTheInputRingWithoutTheVariable) {
  const Polynomial r = res("x*t^3+y*t+1", "t^2-x*y");
  EXPECT_EQ(*r.ring(), *ring_);
  EXPECT_FALSE(r.involves(kT));
  EXPECT_TRUE(r.is_canonical());
  // Eliminating another variable.
  EXPECT_EQ(resultant(parse("x^2+t"), parse("x-y"), 0), parse("y^2+t"));
}

TEST_F(SubresultantTest, RefusesForeignRingsAndVariables) {
  const RingPtr other = Ring::make({"t", "x"});
  EXPECT_THROW(resultant(parse("t"), parse_polynomial("t", other), kT), std::invalid_argument);
  EXPECT_THROW(resultant(parse("t"), parse("t+1"), 3), std::invalid_argument);
  EXPECT_THROW(discriminant(parse("t^2"), 3), std::invalid_argument);
}

TEST_F(SubresultantTest, DefectiveChainsNeedLazardsStep) {
  // Remainders whose degree falls by more than one: S_e = (lc/s)^(δ-1)·S_(d-1).
  const std::vector<std::pair<std::string, std::string>> pairs = {
      {"t^6+y*t^2+1", "t^4+x"},          // 4 → 2
      {"t^7+y", "t^6+x"},                // 6 → 1
      {"t^9+x*t^2+y", "t^8+x*y*t+1"},    // gaps inside the chain
      {"x*t^5+t^3*y+1", "x*t^5+2*t+y"},  // equal degrees
      {"(t^3+x)*(t^4+y)+1", "t^3+x"},    // the remainder is a constant
      {"t^10+x", "t^2+y*t"}};
  for (const auto& [f, g] : pairs) {
    EXPECT_EQ(res(f, g), determinant_bareiss(sylvester_matrix(parse(f), parse(g), kT))) << f << ", " << g;
    EXPECT_EQ(res(g, f), determinant_bareiss(sylvester_matrix(parse(g), parse(f), kT))) << g << ", " << f;
  }
}

TEST_F(SubresultantTest, MatchesBareissOnRandomPairsInEveryOrder) {
  testing::RandomSource random(20240612);
  int checked = 0;
  for (const MonomialOrder& order : testing::all_orders(3)) {
    for (std::size_t var = 0; var < 3; ++var) {
      const RingPtr ring = Ring::make({"x", "y", "t"}, order);
      for (int k = 0; k < 4; ++k) {
        const int m = static_cast<int>(random.uniform(0, 5));
        const int n = static_cast<int>(random.uniform(0, 5));
        const bool rational = random.uniform(0, 3) == 0;
        const Polynomial f = random_in(random, ring, var, m, 3, rational);
        const Polynomial g = random_in(random, ring, var, n, 3, rational);
        const Polynomial expected = determinant_bareiss(sylvester_matrix(f, g, var));
        EXPECT_EQ(resultant(f, g, var), expected)
            << order.name() << ", variable " << var << ":\n  " << to_string(f) << "\n  " << to_string(g);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 8 * 3 * 4);
}

TEST_F(SubresultantTest, AntisymmetryAndMultiplicativity) {
  testing::RandomSource random(99);
  for (int k = 0; k < 15; ++k) {
    const int m = static_cast<int>(random.uniform(1, 4));
    const int n = static_cast<int>(random.uniform(1, 4));
    const Polynomial f = random_in(random, ring_, kT, m, 2, false);
    const Polynomial g = random_in(random, ring_, kT, n, 2, false);
    const Polynomial h = random_in(random, ring_, kT, static_cast<int>(random.uniform(0, 3)), 2, false);
    const Polynomial fg = resultant(f, g, kT);
    EXPECT_EQ(resultant(g, f, kT), (m * n) % 2 == 0 ? fg : -fg);
    // Res(f·h, g) = Res(f, g)·Res(h, g).
    EXPECT_EQ(resultant(f * h, g, kT), fg * resultant(h, g, kT)) << to_string(f) << " | " << to_string(h);
  }
}

TEST_F(SubresultantTest, MatchesFlint) {
  const RingPtr ring = Ring::make({"a", "t", "b", "c"});
  constexpr std::size_t kVar = 1;
  FlintOracle flint(ring);
  testing::RandomSource random(4242);
  for (int k = 0; k < 40; ++k) {
    const Polynomial f = random_in(random, ring, kVar, static_cast<int>(random.uniform(0, 7)), 3, false);
    const Polynomial g = random_in(random, ring, kVar, static_cast<int>(random.uniform(1, 7)), 3, false);
    EXPECT_EQ(resultant(f, g, kVar), flint.resultant(f, g, kVar)) << to_string(f) << "\n  " << to_string(g);
    if (f.degree_in(kVar) >= 1) {
      EXPECT_EQ(discriminant(f, kVar), flint.discriminant(f, kVar)) << to_string(f);
    }
  }
}

TEST_F(SubresultantTest, Discriminants) {
  const RingPtr abcd = Ring::make({"a", "b", "c", "d", "t"});
  auto d = [&](const std::string& f) { return discriminant(parse_polynomial(f, abcd), 4); };
  auto p = [&](const std::string& f) { return parse_polynomial(f, abcd); };
  EXPECT_EQ(d("a*t^2+b*t+c"), p("b^2-4*a*c"));
  EXPECT_EQ(d("a*t^3+b*t^2+c*t+d"), p("b^2*c^2-4*a*c^3-4*b^3*d-27*a^2*d^2+18*a*b*c*d"));
  EXPECT_EQ(d("t^3+a*t+b"), p("-4*a^3-27*b^2"));
  EXPECT_EQ(d("t^4+a*t+b"), p("-27*a^4+256*b^3"));
  EXPECT_EQ(d("2*t^4+a*t+1"), p("-108*a^4+2048"));  // FLINT's answer
  // A product of linear factors: ∏_{i<j} (r_i − r_j)^2.
  EXPECT_EQ(d("(t-a)*(t-b)*(t-1)"), p("(a-b)^2*(a-1)^2*(b-1)^2"));
  EXPECT_TRUE(d("(t-a)^2*(t+b)").is_zero());
  EXPECT_EQ(d("a*t+b"), p("1"));
  EXPECT_EQ(disc("t^2-x"), parse("4*x"));
  EXPECT_EQ(disc("x*t^2+y*t+1/2"), parse("y^2-2*x"));
  EXPECT_TRUE(disc("0").is_zero());
  EXPECT_THROW(disc("x+y"), std::invalid_argument);
}

TEST_F(SubresultantTest, StopsWhenTheBudgetIsSpent) {
  const Polynomial f = parse("(x+y+1)^3*t^9+(x-y)^2*t^5+x*y*t+1");
  const Polynomial g = parse("(x-2*y)^2*t^8+y^3*t^3+x*t^2+7");
  Budget cancelled;
  cancelled.cancel();
  try {
    resultant(f, g, kT, cancelled);
    ADD_FAILURE() << "no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
  Budget small;
  small.set_max_terms(20);
  try {
    resultant(f, g, kT, small);
    ADD_FAILURE() << "no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
  }
  const Budget expired = Budget::with_timeout(1e-9);
  try {
    discriminant(f, kT, expired);
    ADD_FAILURE() << "no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
  // The same inputs finish without limits (and the answer is not trivial).
  EXPECT_GT(resultant(f, g, kT).num_terms(), 20u);
}

}  // namespace
}  // namespace implicitizer
