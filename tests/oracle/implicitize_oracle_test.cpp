// Oracle: the implicit equation of every surface of ../shared/bench/surfaces_public.json
// from implicitize(), against Singular run live in the same test and against the stored
// answers ../shared/bench/expected/NAME.txt, each up to a rational factor. The Singular
// side shares no code with ours: it reads the surface's own text in the fraction field
// Q(params), takes numerators and denominators there, and eliminates with the common
// denominator formulation of the bench README, <q_i*X_i - p_i, 1 - L*w> with L the lcm
// of the denominators (L = 1 for polynomial surfaces).

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <ostream>
#include <string>
#include <vector>

#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "oracle/oracle_support.hpp"

namespace implicitizer {
namespace {

const std::string kBench = std::string(IMPLICITIZER_SHARED_DIR) + "/bench";

// Singular reads `2/3` as one rational literal (so `s^3/3` is s^(3/3)) and divides
// int by int as integers (so `2 / 4` is 0). Turning every integer literal that is not
// an exponent into `number(N)` makes the contract's syntax mean the same in Singular.
std::string singular_arithmetic(const std::string& text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) {
      out += text[i++];
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
    const std::size_t before = out.find_last_not_of(' ');
    const bool exponent = before != std::string::npos && out[before] == '^';
    const std::string digits = text.substr(i, j - i);
    out += exponent ? digits : "number(" + digits + ")";
    i = j;
  }
  return out;
}

// Prints the generators of the elimination ideal after the marker "begin", then "end".
std::string singular_elimination_script(const testing::Surface& s, const std::vector<std::string>& parameters) {
  const std::string params = testing::join(parameters, ",");
  std::string script = "ring F = (0," + params + "), (x), dp;\nshort = 0;\n";
  const char* coordinate[3] = {"X", "Y", "Z"};
  const std::string texts[3] = {s.x, s.y, s.z};
  for (int v = 0; v < 3; ++v) {
    const std::string c = coordinate[v];
    script += "number " + c + " = " + singular_arithmetic(texts[v]) + ";\nstring num" + c + " = string(numerator(" + c +
              "));\nstring den" + c + " = string(denominator(" + c + "));\n";
  }
  script += "ring r = 0, (w," + params +
            ",x,y,z), dp;\n"
            "short = 0;\n"
            "execute(\"poly pX = \" + numX + \"; poly qX = \" + denX + \";\");\n"
            "execute(\"poly pY = \" + numY + \"; poly qY = \" + denY + \";\");\n"
            "execute(\"poly pZ = \" + numZ + \"; poly qZ = \" + denZ + \";\");\n"
            "poly L = 1;\n"
            "L = L * qX / gcd(L, qX);\n"
            "L = L * qY / gcd(L, qY);\n"
            "L = L * qZ / gcd(L, qZ);\n"
            "ideal I = qX*x - pX, qY*y - pY, qZ*z - pZ, 1 - L*w;\n"
            "ideal J = eliminate(I, w*" +
            testing::join(parameters, "*") +
            ");\n"
            "\"" +
            testing::section_marker("begin") +
            "\";\n"
            "int i;\n"
            "for (i = 1; i <= size(J); i++) { print(J[i]); }\n"
            "\"" +
            testing::section_marker("end") +
            "\";\n"
            "quit;\n";
  return script;
}

std::vector<testing::Surface> public_surfaces() { return testing::read_surfaces(kBench + "/surfaces_public.json"); }

TEST(BenchData, PublicSurfacesAreAllRead) {
  // The parametrized test below runs once per surface read; make sure none was lost.
  EXPECT_GE(public_surfaces().size(), 12u);
}

class ImplicitizeOracle : public ::testing::TestWithParam<testing::Surface> {};

TEST_P(ImplicitizeOracle, EquationMatchesSingularAndExpected) {
  const testing::Surface& s = GetParam();
  SCOPED_TRACE(s.name + ": x = " + s.x + ", y = " + s.y + ", z = " + s.z);
  const Parametrization parametrization = parse_parametrization(s.x, s.y, s.z);
  ImplicitizeOptions options;
  options.groebner.budget.set_timeout(30);
  const ImplicitizeResult ours = implicitize(parametrization, options);
  EXPECT_TRUE(ours.verified);
  EXPECT_EQ(ours.degree, s.degree);

  const Polynomial expected =
      parse_polynomial(testing::read_text(kBench + "/expected/" + s.name + ".txt"), space_ring());
  EXPECT_TRUE(testing::equal_up_to_scalar(ours.implicit, expected)) << "against expected/" << s.name << ".txt";

  if (!testing::is_runnable(testing::kSingular)) {
    GTEST_SKIP() << "Singular not found (SINGULAR_EXECUTABLE=\"" << testing::kSingular << "\")";
  }
  const std::vector<std::string>& parameters = parametrization.parameter_ring->variables();
  ASSERT_EQ(std::count(parameters.begin(), parameters.end(), "w"), 0) << "w is the script's extra variable";
  const std::string script = singular_elimination_script(s, parameters);
  const testing::ScriptRun run = testing::run_singular(script);
  ASSERT_EQ(run.exit_code, 0) << run.describe();
  auto sections = testing::split_sections(run.out);
  ASSERT_TRUE(sections.count("end")) << "Singular stopped early:\n" << script << run.describe();
  ASSERT_TRUE(sections[""].empty()) << "stray output:\n" << script << run.describe();
  ASSERT_EQ(sections["begin"].size(), 1u) << "not one generator:\n" << run.describe();
  const Polynomial theirs = parse_polynomial(sections["begin"][0], space_ring());
  EXPECT_TRUE(testing::equal_up_to_scalar(ours.implicit, theirs)) << "against Singular, live";
}

INSTANTIATE_TEST_SUITE_P(PublicSurfaces, ImplicitizeOracle, ::testing::ValuesIn(public_surfaces()),
                         [](const auto& test) { return test.param.name; });

}  // namespace
}  // namespace implicitizer
