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
#include <random>
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
  ImplicitizeParams options;
  options.budget.set_timeout(30);
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

// The hard surfaces Singular finishes within seconds, and seeded random tensor-product
// and triangular patches (polynomial and rational) small enough for it.
std::vector<testing::Surface> resultant_surfaces() {
  std::vector<testing::Surface> out;
  for (const auto& s : testing::read_surfaces(kBench + "/surfaces_hard.json")) {
    if (s.name == "tri_quadratic" || s.name == "tp_11_rational" || s.name == "tp_21" || s.name == "tp_22") {
      out.push_back(s);
    }
  }
  std::mt19937_64 rng(44);
  std::uniform_int_distribution<int> c(-4, 4);
  auto random_polynomial = [&](int m, int n, bool tensor, int constant) {
    std::string p = std::to_string(constant);
    for (int i = 0; i <= m; ++i) {
      for (int j = 0; j <= n; ++j) {
        if (!tensor && i + j > n) continue;
        const int a = c(rng);
        p += "+(" + std::to_string(a == 0 ? 1 : a) + ")*s^" + std::to_string(i) + "*t^" + std::to_string(j);
      }
    }
    return p;
  };
  struct Shape {
    const char* name;
    int m, n;
    bool tensor, rational;
  };
  const Shape shapes[] = {{"random_tp_11", 1, 1, true, false},     {"random_tp_11_rational", 1, 1, true, true},
                          {"random_tp_21", 2, 1, true, false},     {"random_tp_12", 1, 2, true, false},
                          {"random_tri_2", 2, 2, false, false},    {"random_tri_1_rational", 1, 1, false, true}};
  for (const Shape& shape : shapes) {
    testing::Surface s;
    s.name = shape.name;
    std::string p[3];
    for (auto& q : p) q = random_polynomial(shape.m, shape.n, shape.tensor, 0);
    if (shape.rational) {
      const std::string w = random_polynomial(shape.m, shape.n, shape.tensor, 30);
      for (auto& q : p) q = "(" + q + ")/(" + w + ")";
    }
    s.x = p[0];
    s.y = p[1];
    s.z = p[2];
    s.degree = shape.tensor ? 2 * shape.m * shape.n : shape.n * shape.n;
    out.push_back(s);
  }
  return out;
}

class ResultantOracle : public ::testing::TestWithParam<testing::Surface> {};

TEST_P(ResultantOracle, ResultantRouteMatchesSingularsEliminate) {
  const testing::Surface& s = GetParam();
  SCOPED_TRACE(s.name + ": x = " + s.x + ", y = " + s.y + ", z = " + s.z);
  const Parametrization parametrization = parse_parametrization(s.x, s.y, s.z);
  ImplicitizeParams options;
  options.method = ImplicitizationMethod::resultant;
  const ImplicitizeResult ours = implicitize(parametrization, options);
  EXPECT_EQ(ours.method, "resultant");
  EXPECT_TRUE(ours.verified);
  EXPECT_EQ(ours.degree, s.degree);
  if (!testing::is_runnable(testing::kSingular)) {
    GTEST_SKIP() << "Singular not found (SINGULAR_EXECUTABLE=\"" << testing::kSingular << "\")";
  }
  const testing::ScriptRun run =
      testing::run_singular(singular_elimination_script(s, parametrization.parameter_ring->variables()));
  ASSERT_EQ(run.exit_code, 0) << run.describe();
  auto sections = testing::split_sections(run.out);
  ASSERT_EQ(sections["begin"].size(), 1u) << "not one generator:\n" << run.describe();
  EXPECT_TRUE(testing::equal_up_to_scalar(ours.implicit, parse_polynomial(sections["begin"][0], space_ring())));
}

INSTANTIATE_TEST_SUITE_P(Patches, ResultantOracle, ::testing::ValuesIn(resultant_surfaces()),
                         [](const auto& test) { return test.param.name; });

}  // namespace
}  // namespace implicitizer
