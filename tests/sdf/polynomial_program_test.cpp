#include "implicitizer/sdf/polynomial_program.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

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
