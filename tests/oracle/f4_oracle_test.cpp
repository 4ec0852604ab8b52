// Oracle: the classic ideals of ../shared/bench/gb/ideals.json (cyclic-5, katsura-5,
// cyclic-6) over ℚ by the multi-modular route with F4 for each prime, proven and in
// the labelled unproven mode, against Singular's `option(redSB); option(redTail);
// std(I)` in grevlex. A reduced basis is unique, so after making Singular's elements
// monic the two must be the same set.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "implicitizer/groebner/modular_groebner.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "oracle/oracle_support.hpp"

namespace implicitizer {
namespace {

// The names and generators of the classic ideals; the file is JSON, read here with a
// few string searches (its shape is fixed: "name", "vars" and "polys" lists of
// strings) since the tests do not link a JSON library.
struct ClassicIdeal {
  std::vector<std::string> variables;
  std::vector<std::string> polynomials;
};

std::vector<std::string> string_list_after(const std::string& text, std::size_t from, const std::string& key) {
  const std::size_t open = text.find('[', text.find("\"" + key + "\"", from));
  const std::size_t close = text.find(']', open);
  std::vector<std::string> out;
  for (std::size_t q = text.find('"', open); q < close; q = text.find('"', q + 1)) {
    const std::size_t end = text.find('"', q + 1);
    out.push_back(text.substr(q + 1, end - q - 1));
    q = end;
  }
  return out;
}

ClassicIdeal read_classic_ideal(const std::string& name) {
  std::ifstream in(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/gb/ideals.json");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::size_t at = text.find("\"" + name + "\"");
  if (at == std::string::npos) return {};
  return {string_list_after(text, at, "vars"), string_list_after(text, at, "polys")};
}

class F4Oracle : public ::testing::TestWithParam<const char*> {
 protected:
  // Singular's reduced basis of the ideal, made monic, in `ring`.
  static std::vector<Polynomial> singular_basis(const ClassicIdeal& ideal, const RingPtr& ring) {
    const std::string script = "ring r = 0, (" + testing::join(ideal.variables, ",") +
                               "), dp;\nshort = 0;\noption(redSB); option(redTail);\nideal G = std(ideal(" +
                               testing::join(ideal.polynomials, ", ") + "));\n\"" + testing::section_marker("basis") +
                               "\";\nint i;\nfor (i = 1; i <= size(G); i++) { print(G[i]); }\n\"" +
                               testing::section_marker("end") + "\";\nquit;\n";
    const testing::ScriptRun run = testing::run_singular(script);
    EXPECT_EQ(run.exit_code, 0) << run.describe();
    auto sections = testing::split_sections(run.out);
    EXPECT_TRUE(sections.count("end")) << "Singular stopped early:\n" << run.describe();
    std::vector<Polynomial> theirs;
    for (const auto& line : sections["basis"]) theirs.push_back(parse_polynomial(line, ring).monic());
    return theirs;
  }

  // Ours by F4 modulo primes, proven or (`prove` false) checked on random primes,
  // against Singular's.
  static void expect_singular_basis(bool prove) {
    if (!testing::is_runnable(testing::kSingular)) {
      GTEST_SKIP() << "Singular not found (SINGULAR_EXECUTABLE=\"" << testing::kSingular << "\")";
    }
    const ClassicIdeal ideal = read_classic_ideal(GetParam());
    ASSERT_FALSE(ideal.polynomials.empty()) << "no " << GetParam() << " in " << IMPLICITIZER_SHARED_DIR;
    const RingPtr ring = Ring::make(ideal.variables, MonomialOrder::grevlex());
    const std::vector<Polynomial> theirs = singular_basis(ideal, ring);
    ASSERT_FALSE(theirs.empty());

    std::vector<Polynomial> generators;
    for (const auto& p : ideal.polynomials) generators.push_back(parse_polynomial(p, ring));
    ModularGroebnerParams params;
    params.algorithm = ModularAlgorithm::f4;
    params.prove = prove;
    params.random_checks = prove ? 0 : 2;
    params.buchberger.budget.set_timeout(120);
    ModularGroebnerStats stats;
    const std::vector<Polynomial> ours = compute_groebner_basis_modular(generators, params, &stats).basis;
    EXPECT_EQ(stats.proven, prove);
    EXPECT_EQ(stats.random_primes.size(), prove ? 0u : 2u);
    EXPECT_EQ(ours.size(), theirs.size());
    for (const auto& p : ours) {
      EXPECT_NE(std::find(theirs.begin(), theirs.end(), p), theirs.end())
          << to_string(p) << " is not in Singular's basis";
    }
  }
};

TEST_P(F4Oracle, ProvenModularF4BasisMatchesSingular) { expect_singular_basis(/*prove=*/true); }

// The labelled unproven mode (groebner --proof random_primes) gives the same basis.
TEST_P(F4Oracle, UnprovenModularF4BasisMatchesSingular) { expect_singular_basis(/*prove=*/false); }

INSTANTIATE_TEST_SUITE_P(ClassicIdeals, F4Oracle, ::testing::Values("cyclic5", "katsura5", "cyclic6"),
                         [](const auto& test) { return std::string(test.param); });

}  // namespace
}  // namespace implicitizer
