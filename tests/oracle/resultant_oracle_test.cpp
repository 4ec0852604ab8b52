// Oracle: resultant() and discriminant() against Singular's `resultant(f, g, v)` on
// random pairs (fixed seed) in the ring (t, x, y, z), eliminating t or x, with degrees
// 0 to 5 in the eliminated variable (so constants, equal degrees and large gaps all
// occur). One Singular run answers every pair; answers are compared exactly, as
// polynomials, after parsing Singular's output with our parser.
//
// Singular has no general discriminant (grobcov.lib's `discrim` is for degree 2
// only), so discriminants are checked through the definition:
// Res(f, ∂f/∂v) = (−1)^(n(n−1)/2)·lc_v(f)·Disc_v(f), with Singular's resultant.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/resultant/subresultant.hpp"
#include "implicitizer/resultant/sylvester.hpp"
#include "oracle/oracle_support.hpp"

namespace implicitizer {
namespace {

constexpr int kNumPairs = 32;
constexpr unsigned kSeed = 20240613;

struct Pair {
  std::string f;
  std::string g;
  std::size_t var;  // 0 (t) or 1 (x)
};

// Σ_{i ≤ degree} c_i·v^i with c_i of 0 to 3 terms (1 to 3 for the leading one) in the
// other variables, exponents ≤ 2, integer coefficients in [−9, 9] \ {0}: integers so
// that Singular reads exactly what our parser reads.
Polynomial random_in(std::mt19937& rng, const RingPtr& ring, std::size_t var, int degree) {
  std::uniform_int_distribution<int> exponent(0, 2);
  std::uniform_int_distribution<int> magnitude(1, 9);
  std::bernoulli_distribution negative(0.5);
  Polynomial f(ring);
  std::vector<std::int32_t> e(ring->num_variables());
  for (int i = 0; i <= degree; ++i) {
    const int terms = std::uniform_int_distribution<int>(i == degree ? 1 : 0, 3)(rng);
    for (int k = 0; k < terms; ++k) {
      for (std::size_t v = 0; v < e.size(); ++v) e[v] = v == var ? i : exponent(rng);
      const int c = magnitude(rng);
      f += Polynomial::term(ring, Rational(negative(rng) ? -c : c), e);
    }
  }
  if (f.degree_in(var) < degree) {  // the leading terms cancelled: force one
    std::fill(e.begin(), e.end(), 0);
    e[var] = degree;
    f += Polynomial::term(ring, Rational(1), e);
  }
  return f;
}

std::vector<Pair> random_pairs(const RingPtr& ring) {
  std::mt19937 rng(kSeed);
  std::uniform_int_distribution<int> degree(0, 5);
  std::vector<Pair> pairs;
  for (int k = 0; k < kNumPairs; ++k) {
    const std::size_t var = k % 4 == 3 ? 1 : 0;
    const Polynomial f = random_in(rng, ring, var, degree(rng));
    const Polynomial g = random_in(rng, ring, var, degree(rng));
    pairs.push_back({to_string(f), to_string(g), var});
  }
  return pairs;
}

class ResultantOracle : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::is_runnable(testing::kSingular)) {
      GTEST_SKIP() << "Singular not found (SINGULAR_EXECUTABLE=\"" << testing::kSingular << "\")";
    }
  }
  RingPtr ring_ = Ring::make({"t", "x", "y", "z"});
};

TEST_F(ResultantOracle, RandomPairsMatchSingularExactly) {
  const std::vector<Pair> pairs = random_pairs(ring_);
  // Section "res k": Res(f, g); section "dres k": Res(f, ∂f/∂v) when f involves v.
  std::string script = "ring r = 0, (t,x,y,z), dp;\nshort = 0;\npoly f; poly g;\n";
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const std::string& v = ring_->variables()[pairs[k].var];
    script += "f = " + pairs[k].f + ";\ng = " + pairs[k].g + ";\n";
    script += "\"" + testing::section_marker("res " + std::to_string(k)) + "\";\nprint(resultant(f, g, " + v + "));\n";
    script += "\"" + testing::section_marker("dres " + std::to_string(k)) + "\";\nprint(resultant(f, diff(f, " + v +
              "), " + v + "));\n";
  }
  script += "\"" + testing::section_marker("end") + "\";\nquit;\n";

  const testing::ScriptRun run = testing::run_singular(script);
  ASSERT_EQ(run.exit_code, 0) << run.describe();
  auto sections = testing::split_sections(run.out);
  ASSERT_TRUE(sections.count("end")) << "Singular stopped early:\n" << run.describe();
  ASSERT_TRUE(sections[""].empty()) << "stray output:\n" << run.describe();

  int nonconstant = 0;
  int discriminants = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const Pair& p = pairs[k];
    SCOPED_TRACE("pair " + std::to_string(k) + " in " + ring_->variables()[p.var] + ": f = " + p.f + ", g = " + p.g);
    const Polynomial f = parse_polynomial(p.f, ring_);
    const Polynomial g = parse_polynomial(p.g, ring_);

    const auto& res_lines = sections["res " + std::to_string(k)];
    ASSERT_EQ(res_lines.size(), 1u) << run.describe();
    const Polynomial theirs = parse_polynomial(res_lines.front(), ring_);
    const Polynomial ours = resultant(f, g, p.var);
    EXPECT_EQ(ours, theirs) << "ours: " << to_string(ours) << "\nSingular: " << res_lines.front();
    nonconstant += ours.is_constant() ? 0 : 1;

    const int n = f.degree_in(p.var);
    if (n < 1) continue;
    const auto& dres_lines = sections["dres " + std::to_string(k)];
    ASSERT_EQ(dres_lines.size(), 1u) << run.describe();
    Polynomial expected = discriminant(f, p.var) * coefficients_in(f, p.var).back();
    if ((n * (n - 1) / 2) % 2 != 0) expected = -expected;
    EXPECT_EQ(expected, parse_polynomial(dres_lines.front(), ring_))
        << "our discriminant: " << to_string(discriminant(f, p.var));
    ++discriminants;
  }
  // The seed must exercise real eliminations, not only constant corner cases.
  EXPECT_GE(nonconstant, kNumPairs / 2);
  EXPECT_GE(discriminants, kNumPairs / 2);
}

TEST_F(ResultantOracle, ConventionsOfConstantsAndZeroMatchSingular) {
  // Polynomials free of t give c^deg (1 for two of them); the zero polynomial gives 0
  // whatever the other one is, a constant included.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"3", "t^2+x"}, {"t^2+x", "3"}, {"x+y", "x-y"}, {"x", "t^3+y"}, {"x*t^3+y", "2*z"}, {"5", "7"},  {"0", "t^2+x"},
      {"t^2+x", "0"}, {"0", "5"},     {"5", "0"},     {"0", "0"},     {"t", "t+1"},       {"t+1", "t"}};
  std::string script = "ring r = 0, (t,x,y,z), dp;\nshort = 0;\n";
  for (std::size_t k = 0; k < cases.size(); ++k) {
    script += "\"" + testing::section_marker(std::to_string(k)) + "\";\nprint(resultant(" + cases[k].first + ", " +
              cases[k].second + ", t));\n";
  }
  script += "\"" + testing::section_marker("end") + "\";\nquit;\n";
  const testing::ScriptRun run = testing::run_singular(script);
  ASSERT_EQ(run.exit_code, 0) << run.describe();
  auto sections = testing::split_sections(run.out);
  ASSERT_TRUE(sections.count("end")) << run.describe();
  for (std::size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE(cases[k].first + ", " + cases[k].second);
    ASSERT_EQ(sections[std::to_string(k)].size(), 1u) << run.describe();
    EXPECT_EQ(resultant(parse_polynomial(cases[k].first, ring_), parse_polynomial(cases[k].second, ring_), 0),
              parse_polynomial(sections[std::to_string(k)].front(), ring_));
  }
}

}  // namespace
}  // namespace implicitizer
