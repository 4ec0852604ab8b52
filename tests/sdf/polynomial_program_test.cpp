#include "implicitizer/sdf/polynomial_program.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "sdf/sdf_support.hpp"

namespace implicitizer {
namespace {

using testing::parse_xyz;

// The double run of the program against exact values of G and its partials: the
// Horner nesting and the forward-mode derivatives are right for sparse and dense
// polynomials, with gaps in every variable.
TEST(PolynomialProgram, ValueAndGradientMatchExactArithmetic) {
  for (const char* text : {"x", "z", "1/2+y", "x^3*z-y^2/4+1/8", "x^5-x*y^3*z^2+z^7/3-1/2",
                           "x^2*y^2+y^2*z^2+z^2*x^2-x*y*z", "(x+y+z-1/3)^6/729", "y^4*z^4-x^4/5"}) {
    const Polynomial g = parse_xyz(text);
    const PolynomialProgram program = PolynomialProgram::compile(g);
    EXPECT_EQ(program.degree(), g.total_degree()) << text;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-1, 1);
    for (int i = 0; i < 20; ++i) {
      const double u = coordinate(random), v = coordinate(random), w = coordinate(random);
      const Rational point[3] = {Rational(u), Rational(v), Rational(w)};
      const ValueAndGradient<double> r = program.evaluate(u, v, w);
      EXPECT_NEAR(r.value, to_mpq(g.evaluate(point)).get_d(), 1e-13) << text;
      for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_NEAR(r.gradient[k], to_mpq(g.derivative(k).evaluate(point)).get_d(), 1e-12) << text << " d" << k;
      }
    }
  }
}

TEST(PolynomialProgram, FloatLiteralsReadBackExactly) {
  for (float x : {1.0f, -1.0f, 0.1f, 1e-30f, 3.4e38f, 1.17549435e-38f, 0.333333343f, 16777217.0f}) {
    const std::string text = format_glsl_float(x);
    EXPECT_NE(text.find('.'), std::string::npos) << text;
    EXPECT_NE(text.find('e'), std::string::npos) << text;
    EXPECT_EQ(std::strtof(text.c_str(), nullptr), x) << text;
  }
}

TEST(PolynomialProgram, GlslHasNoPowAndOnlyFloatLiterals) {
  const PolynomialProgram program = PolynomialProgram::compile(parse_xyz("x^7-2*y^3*z+1/3"));
  const std::string glsl = program.to_glsl("  ");
  EXPECT_EQ(glsl.find("pow"), std::string::npos);
  // Constants are written as d.dddddddde±dd: no bare integer after an operator.
  EXPECT_EQ(glsl.find("+ 1;"), std::string::npos);
  EXPECT_NE(glsl.find("3.33333343e-01"), std::string::npos);
}

TEST(PolynomialProgram, DropsCoefficientsFloatCannotHoldAsNormals) {
  // 1e-40 is subnormal in float: a GPU flushes it, so the program drops it.
  const PolynomialProgram program = PolynomialProgram::compile(parse_xyz("x-1e-40"));
  EXPECT_EQ(program.evaluate(0.0f, 0.0f, 0.0f).value, 0.0f);
  EXPECT_EQ(program.evaluate(0.5, 0.0, 0.0).value, 0.5);
  EXPECT_EQ(program.dropped_terms(), 1u);
  EXPECT_EQ(PolynomialProgram::compile(parse_xyz("x-1e-30")).dropped_terms(), 0u);
}

// The value-only program runs the value steps of the full one, in the same order:
// its float results are bit-identical, with fewer steps and only a, b, g in GLSL.
TEST(PolynomialProgram, ValueOnlyProgramRoundsLikeTheFullOne) {
  for (const char* text : {"x", "1/2+y", "x^5-x*y^3*z^2+z^7/3-1/2", "(x+y+z-1/3)^6/729", "y^4*z^4-x^4/5"}) {
    const Polynomial g = parse_xyz(text);
    const PolynomialProgram full = PolynomialProgram::compile(g);
    const PolynomialProgram value = PolynomialProgram::compile(g, ProgramOutputs::value);
    EXPECT_EQ(value.outputs(), ProgramOutputs::value);
    EXPECT_EQ(value.degree(), full.degree());
    EXPECT_LT(value.steps().size(), full.steps().size()) << text;
    std::mt19937 random(9);
    std::uniform_real_distribution<float> coordinate(-2, 2);
    for (int i = 0; i < 50; ++i) {
      const float u = coordinate(random), v = coordinate(random), w = coordinate(random);
      const ValueAndGradient<float> r = value.evaluate(u, v, w);
      EXPECT_EQ(r.value, full.evaluate(u, v, w).value) << text;
      EXPECT_EQ(r.gradient[0], 0.0f);
    }
    const std::string glsl = value.to_glsl("");
    EXPECT_EQ(glsl.rfind("float a = 0.0, b = 0.0, g = 0.0;\n", 0), 0u) << glsl;
    EXPECT_EQ(glsl.find("gu"), std::string::npos);
    EXPECT_EQ(glsl.find("aw"), std::string::npos);
  }
}

}  // namespace
}  // namespace implicitizer

namespace implicitizer {
namespace {

// Cells (safe_sdf.hpp): one program over the union of the supports, one row of the
// table per polynomial. Each row evaluates to that polynomial's own program's values
// (a coefficient a cell lacks is 0: a·x + 0 is a·x, exactly), in float and double;
// the GLSL reads coefficient i as TABLEi[cell], abs() of it for a majorant, and the
// table holds one const array of cells() entries per coefficient.
TEST(PolynomialProgram, CellsShareOneProgramAndEvaluateAsTheirOwn) {
  const std::vector<Polynomial> cells = {parse_xyz("x^3*z-y^2/4+1/8"), parse_xyz("y^4*z^4-x^4/5"),
                                         parse_xyz("-x+1/3*z^2")};
  const PolynomialProgram shared = PolynomialProgram::compile_cells(cells);
  EXPECT_EQ(shared.cells(), 3u);
  EXPECT_EQ(shared.coefficients_per_cell(), 7u);  // x^3z, y^2, 1, y^4z^4, x^4, x, z^2
  EXPECT_EQ(shared.table_float().size(), 21u);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  for (std::size_t cell = 0; cell < cells.size(); ++cell) {
    const PolynomialProgram own = PolynomialProgram::compile(cells[cell]);
    for (int i = 0; i < 50; ++i) {
      const float u = static_cast<float>(coordinate(random)), v = static_cast<float>(coordinate(random)),
                  w = static_cast<float>(coordinate(random));
      const ValueAndGradient<float> a = shared.evaluate_in_cell(cell, u, v, w), b = own.evaluate(u, v, w);
      EXPECT_EQ(a.value, b.value) << cell;
      for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(a.gradient[k], b.gradient[k]) << cell;
      EXPECT_EQ(shared.evaluate_in_cell<double>(cell, u, v, w).value, own.evaluate<double>(u, v, w).value);
    }
  }
  const std::string glsl = shared.to_glsl("  ", "T");
  EXPECT_NE(glsl.find("T0[cell]"), std::string::npos) << glsl;
  EXPECT_EQ(glsl.find("1.25000000e-01"), std::string::npos) << "1/8 is read from the table: " << glsl;
  EXPECT_NE(shared.to_glsl("  ", "T", true).find("abs(T0[cell])"), std::string::npos);
  const std::string table = shared.glsl_table("T");
  EXPECT_NE(table.find("const float T6[3] = float[3]("), std::string::npos) << table;
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 7);
  // One polynomial: compile() itself, literals in the GLSL as before.
  EXPECT_EQ(PolynomialProgram::compile_cells({cells[0]}).to_glsl("  "),
            PolynomialProgram::compile(cells[0]).to_glsl("  "));
}

}  // namespace
}  // namespace implicitizer

namespace implicitizer {
namespace {

// A reader of exactly the statements to_glsl() writes for a full program, run in
// float with GLSL's rule that a vector assignment reads every operand before it
// writes: "V = vecN(...)", "V.sw = V.sw * r + vecN(...)" (or one term), "V = V * r",
// the operands literals or registers (u, v, w, A.x, ...). Written from the GLSL
// specification's semantics, not from the emitter, so it checks the emitter's claim
// that each statement computes its components exactly as the scalar steps do.
class VectorGlslRunner {
 public:
  VectorGlslRunner(float u, float v, float w) : inputs_{u, v, w} {}

  void run(const std::string& glsl) {
    std::istringstream lines(glsl);
    std::string line;
    while (std::getline(lines, line)) {
      const std::size_t start = line.find_first_not_of(' ');
      line = line.substr(start, line.size() - start - 1);                      // no indent, no ';'
      if (line.rfind("vec", 0) == 0 || line.rfind("float", 0) == 0) continue;  // the declarations, all 0
      statement(line);
    }
  }
  float get(char vector, int component) const { return registers_.at(vector)[component]; }

 private:
  // The components `lhs` names ("G" all, "G.yw" some).
  std::vector<int> components(const std::string& lhs) const {
    std::vector<int> out;
    if (lhs.size() == 1) {
      for (int i = 0; i < 2 + static_cast<int>(std::string("ABG").find(lhs[0])); ++i) out.push_back(i);
    } else {
      for (char c : lhs.substr(2)) out.push_back(static_cast<int>(std::string("xyzw").find(c)));
    }
    return out;
  }
  float operand(const std::string& text) const {
    if (text == "u" || text == "v" || text == "w") return inputs_[text[0] - 'u'];
    if (text.size() == 3 && text[1] == '.') return registers_.at(text[0])[std::string("xyzw").find(text[2])];
    return std::strtof(text.c_str(), nullptr);
  }
  // "vecN(a, b, ...)" or one operand.
  std::vector<float> operands(const std::string& text) const {
    if (text.rfind("vec", 0) != 0) return {operand(text)};
    std::vector<float> out;
    std::istringstream list(text.substr(5, text.size() - 6));
    std::string item;
    while (std::getline(list, item, ',')) out.push_back(operand(item.substr(item.find_first_not_of(' '))));
    return out;
  }
  void statement(const std::string& line) {
    const std::size_t eq = line.find(" = ");
    const std::string lhs = line.substr(0, eq), rhs = line.substr(eq + 3);
    const std::vector<int> slots = components(lhs);
    std::vector<float> result(slots.size());
    const std::array<float, 4> old = registers_.at(lhs[0]);
    if (rhs.rfind(lhs + " * ", 0) == 0) {
      const std::string rest = rhs.substr(lhs.size() + 3);
      const std::size_t plus = rest.find(" + ");
      const float by = operand(rest.substr(0, plus));
      const std::vector<float> add =
          plus == std::string::npos ? std::vector<float>(slots.size(), 0.0f) : operands(rest.substr(plus + 3));
      ASSERT_EQ(add.size(), slots.size()) << line;
      for (std::size_t i = 0; i < slots.size(); ++i) {
        const float product = old[static_cast<std::size_t>(slots[i])] * by;
        result[i] = plus == std::string::npos ? product : product + add[i];
      }
    } else {
      result = operands(rhs);
      ASSERT_EQ(result.size(), slots.size()) << line;
    }
    for (std::size_t i = 0; i < slots.size(); ++i) registers_[lhs[0]][static_cast<std::size_t>(slots[i])] = result[i];
  }

  std::array<float, 3> inputs_;
  std::map<char, std::array<float, 4>> registers_{{'A', {}}, {'B', {}}, {'G', {}}};
};

// The full program's GLSL states a Horner level and its derivatives in one vector
// statement: fewer statements than steps, and run as GLSL runs it, bit-identical to
// the C++ float evaluator (without fma: the reader rounds each product).
TEST(PolynomialProgram, VectorStatementsComputeTheScalarSteps) {
  for (const char* text : {"x", "1/2+y", "x^3*z-y^2/4+1/8", "x^5-x*y^3*z^2+z^7/3-1/2", "(x+y+z-1/3)^6/729",
                           "y^4*z^4-x^4/5", "(x-2*y+z/3+1/5)^9/4096"}) {
    const PolynomialProgram program = PolynomialProgram::compile(parse_xyz(text));
    const std::string glsl = program.to_glsl("  ");
    EXPECT_NE(glsl.find("vec4 G = vec4(0.0);"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("float g = G.x, gu = G.y, gv = G.z, gw = G.w;"), std::string::npos) << glsl;
    const auto statements = static_cast<std::size_t>(std::count(glsl.begin(), glsl.end(), '\n')) - 4;
    EXPECT_LT(statements, program.steps().size()) << text;
    std::mt19937 random(5);
    std::uniform_real_distribution<float> coordinate(-2, 2);
    for (int i = 0; i < 40; ++i) {
      const float u = coordinate(random), v = coordinate(random), w = coordinate(random);
      VectorGlslRunner runner(u, v, w);
      runner.run(glsl);
      const ValueAndGradient<float> expected = program.evaluate(u, v, w);
      EXPECT_EQ(runner.get('G', 0), expected.value) << text;
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(runner.get('G', k + 1), expected.gradient[static_cast<std::size_t>(k)]) << text;
    }
  }
  // A dense polynomial takes fewer than half as many statements as steps.
  const PolynomialProgram dense = PolynomialProgram::compile(parse_xyz("(x-2*y+z/3+1/5)^9/4096"));
  const std::string glsl = dense.to_glsl("");
  EXPECT_LT(2 * static_cast<std::size_t>(std::count(glsl.begin(), glsl.end(), '\n')), dense.steps().size());
}

}  // namespace
}  // namespace implicitizer
