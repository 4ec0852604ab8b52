// Oracle: reduced Gröbner bases from compute_groebner_basis() against Singular's
// `option(redSB); option(redTail); std(I)` on random ideals (fixed seed) in x, y, z,
// under lex, grlex and grevlex. One Singular run per order computes every ideal; a
// reduced basis is unique, so after making Singular's elements monic (Singular clears
// denominators instead) the two bases must be the same set of polynomials.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/polynomial/monomial_order.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "oracle/oracle_support.hpp"

namespace implicitizer {
namespace {

constexpr int kNumIdeals = 60;
constexpr unsigned kSeed = 20240611;

// Random generators as text with integer coefficients, so that Singular reads exactly
// what our parser reads (and Singular's `2/3` rational-literal lexing never applies):
// 2 to 4 generators, each 2 to 4 distinct terms of total degree <= 3 with non-zero
// coefficients in [-9, 9]. The same ideals are used for every order.
std::vector<std::vector<std::string>> random_ideals() {
  std::vector<std::array<int, 3>> monomials;
  for (int a = 0; a <= 3; ++a)
    for (int b = 0; a + b <= 3; ++b)
      for (int c = 0; a + b + c <= 3; ++c) monomials.push_back({a, b, c});
  std::mt19937 rng(kSeed);
  std::uniform_int_distribution<int> count(2, 4);
  std::uniform_int_distribution<int> magnitude(1, 9);
  std::bernoulli_distribution negative(0.5);
  const char* names[3] = {"x", "y", "z"};
  std::vector<std::vector<std::string>> ideals;
  for (int i = 0; i < kNumIdeals; ++i) {
    std::vector<std::string> generators;
    const int num_generators = count(rng);
    for (int g = 0; g < num_generators; ++g) {
      std::shuffle(monomials.begin(), monomials.end(), rng);
      const int num_terms = count(rng);
      std::string text;
      for (int t = 0; t < num_terms; ++t) {
        const int c = magnitude(rng);
        text += negative(rng) ? "-" : (t > 0 ? "+" : "");
        std::string monomial;
        for (int v = 0; v < 3; ++v) {
          const int e = monomials[t][v];
          if (e == 0) continue;
          monomial += (monomial.empty() ? "" : "*") + std::string(names[v]) + (e > 1 ? "^" + std::to_string(e) : "");
        }
        if (monomial.empty()) {
          text += std::to_string(c);
        } else {
          text += (c == 1 ? "" : std::to_string(c) + "*") + monomial;
        }
      }
      generators.push_back(text);
    }
    ideals.push_back(generators);
  }
  return ideals;
}

// One script for all ideals: section k holds the reduced basis of ideal k, one
// element per line; the section "end" proves that Singular got to the end.
std::string singular_batch_script(const MonomialOrder& order, const std::vector<std::vector<std::string>>& ideals) {
  std::string script = "ring r = 0, (x,y,z), " + order.singular_name(3) +
                       ";\n"
                       "short = 0;\n"
                       "option(redSB); option(redTail);\n"
                       "ideal I; ideal G; int i;\n";
  for (std::size_t k = 0; k < ideals.size(); ++k) {
    script += "I = " + testing::join(ideals[k], ", ") + ";\nG = std(I);\n\"" +
              testing::section_marker(std::to_string(k)) + "\";\nfor (i = 1; i <= size(G); i++) { print(G[i]); }\n";
  }
  return script + "\"" + testing::section_marker("end") + "\";\nquit;\n";
}

class BuchbergerOracle : public ::testing::TestWithParam<const char*> {};

TEST_P(BuchbergerOracle, ReducedBasesMatchSingular) {
  if (!testing::is_runnable(testing::kSingular)) {
    GTEST_SKIP() << "Singular not found (SINGULAR_EXECUTABLE=\"" << testing::kSingular << "\")";
  }
  const MonomialOrder order = MonomialOrder::from_name(GetParam());
  const RingPtr ring = Ring::make({"x", "y", "z"}, order);
  const auto ideals = random_ideals();

  const testing::ScriptRun run = testing::run_singular(singular_batch_script(order, ideals));
  ASSERT_EQ(run.exit_code, 0) << run.describe();
  auto sections = testing::split_sections(run.out);
  ASSERT_TRUE(sections.count("end")) << "Singular stopped early:\n" << run.describe();
  ASSERT_TRUE(sections[""].empty()) << "stray output:\n" << run.describe();

  for (std::size_t k = 0; k < ideals.size(); ++k) {
    SCOPED_TRACE("ideal " + std::to_string(k) + " in " + order.name() + ": " + testing::join(ideals[k], ", "));

    std::vector<Polynomial> input;
    for (const auto& g : ideals[k]) input.push_back(parse_polynomial(g, ring));
    // Singular needs a few milliseconds per ideal; about 2 s of work is generous
    // (counted as work, so a loaded machine gives the same verdict). When the default
    // parameters run out of it that is reported, and the basis is still checked with
    // the normal strategy, so that a slow ideal does not hide a wrong one.
    BuchbergerParams params;
    params.budget.set_max_work(buchberger_work_of_milliseconds(2000));
    std::vector<Polynomial> ours;
    try {
      ours = compute_groebner_basis(input, params).basis;
    } catch (const LimitExceeded& e) {
      ADD_FAILURE() << "compute_groebner_basis with default parameters: " << e.what()
                    << " (Singular: milliseconds); checking with the normal strategy instead";
      params.variant.strategy = SelectionStrategy::normal;
      params.budget.set_timeout(10);
      ours = compute_groebner_basis(input, params).basis;
    }

    std::vector<Polynomial> theirs;
    for (const auto& line : sections[std::to_string(k)]) theirs.push_back(parse_polynomial(line, ring).monic());

    std::string printed_ours;
    std::string printed_theirs;
    for (const auto& p : ours) printed_ours += "\n  " + to_string(p);
    for (const auto& p : theirs) printed_theirs += "\n  " + to_string(p);
    const std::string both = "ours:" + printed_ours + "\nSingular (made monic):" + printed_theirs;
    ASSERT_FALSE(theirs.empty()) << both;
    // Leading monomials of a reduced basis are distinct, so equal sizes and inclusion
    // one way is set equality.
    EXPECT_EQ(ours.size(), theirs.size()) << both;
    for (const auto& p : ours) {
      EXPECT_NE(std::find(theirs.begin(), theirs.end(), p), theirs.end())
          << to_string(p) << " is not in Singular's basis\n"
          << both;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Orders, BuchbergerOracle, ::testing::Values("lex", "grlex", "grevlex"),
                         [](const auto& test) { return std::string(test.param); });

}  // namespace
}  // namespace implicitizer
