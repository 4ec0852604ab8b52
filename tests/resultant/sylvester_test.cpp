// Tests of lib/src/resultant/sylvester.cpp: splitting a polynomial into its
// coefficients in one variable, the shape of the Sylvester matrix, and Bareiss'
// determinant against a Laplace expansion (its deliberately slow twin, here).

#include "implicitizer/resultant/sylvester.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

class SylvesterTest : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"x", "t", "y"});
  static constexpr std::size_t kT = 1;
  Polynomial parse(const std::string& text) const { return parse_polynomial(text, ring_); }

  PolynomialMatrix matrix_of(const std::vector<std::vector<std::string>>& rows) const {
    PolynomialMatrix m(ring_, rows.size(), rows.empty() ? 0 : rows.front().size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      for (std::size_t j = 0; j < rows[i].size(); ++j) m.set(i, j, parse(rows[i][j]));
    }
    return m;
  }
};

// The determinant by cofactor expansion along the first row: n! products, fine for
// the 4 × 4 matrices it checks.
Polynomial determinant_by_expansion(const PolynomialMatrix& m) {
  const std::size_t n = m.rows();
  if (n == 0) return Polynomial::constant(m.ring(), Rational(1));
  Polynomial det(m.ring());
  for (std::size_t j = 0; j < n; ++j) {
    PolynomialMatrix minor(m.ring(), n - 1, n - 1);
    for (std::size_t r = 1; r < n; ++r) {
      for (std::size_t c = 0, cc = 0; c < n; ++c) {
        if (c != j) minor.set(r - 1, cc++, m.at(r, c));
      }
    }
    const Polynomial term = m.at(0, j) * determinant_by_expansion(minor);
    det = j % 2 == 0 ? det + term : det - term;
  }
  return det;
}

TEST_F(SylvesterTest, CoefficientsInOneVariable) {
  const std::vector<Polynomial> c = coefficients_in(parse("x*t^3-2*t*y+x^2+3/4*t^3*y"), kT);
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0], parse("x^2"));
  EXPECT_EQ(c[1], parse("-2*y"));
  EXPECT_TRUE(c[2].is_zero());
  EXPECT_EQ(c[3], parse("x+3/4*y"));
  for (const Polynomial& ci : c) EXPECT_TRUE(ci.is_canonical());
  EXPECT_TRUE(coefficients_in(Polynomial(ring_), kT).empty());
  const std::vector<Polynomial> free = coefficients_in(parse("x*y+1"), kT);
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(free[0], parse("x*y+1"));
  EXPECT_THROW(coefficients_in(parse("x"), 3), std::invalid_argument);
}

TEST_F(SylvesterTest, CoefficientsReassembleThePolynomial) {
  testing::RandomSource random(7);
  for (const MonomialOrder& order : testing::all_orders(3)) {
    const RingPtr ring = Ring::make({"x", "t", "y"}, order);
    const Polynomial tt = Polynomial::variable(ring, kT);
    for (int k = 0; k < 20; ++k) {
      const Polynomial f = random.polynomial(ring, 8, 4);
      const std::vector<Polynomial> c = coefficients_in(f, kT);
      Polynomial back(ring);
      for (std::size_t i = 0; i < c.size(); ++i) {
        EXPECT_FALSE(c[i].involves(kT));
        back += c[i] * tt.pow(static_cast<unsigned>(i));
      }
      EXPECT_EQ(back, f) << order.name() << ": " << to_string(f);
      if (!c.empty()) {
        EXPECT_FALSE(c.back().is_zero());
      }
    }
  }
}

TEST_F(SylvesterTest, MatrixShape) {
  // f = a t^2 + b t + c, g = d t + e: rows f, then x^1·g and g.
  const PolynomialMatrix s = sylvester_matrix(parse("x*t^2+y*t+1"), parse("2*t-x*y"), kT);
  EXPECT_EQ(s, matrix_of({{"x", "y", "1"}, {"2", "-x*y", "0"}, {"0", "2", "-x*y"}}));
  // deg g = 2, deg f = 1: two rows of f, one of g.
  EXPECT_EQ(sylvester_matrix(parse("t+y"), parse("t^2-x"), kT),
            matrix_of({{"1", "y", "0"}, {"0", "1", "y"}, {"1", "0", "-x"}}));
  // A factor free of t: c times the identity of size deg g.
  EXPECT_EQ(sylvester_matrix(parse("x+1"), parse("t^2+y"), kT), matrix_of({{"x+1", "0"}, {"0", "x+1"}}));
  EXPECT_EQ(sylvester_matrix(parse("x"), parse("y"), kT).rows(), 0u);
}

TEST_F(SylvesterTest, MatrixRefusesZeroAndForeignRings) {
  EXPECT_THROW(sylvester_matrix(Polynomial(ring_), parse("t"), kT), std::invalid_argument);
  EXPECT_THROW(sylvester_matrix(parse("t"), Polynomial(ring_), kT), std::invalid_argument);
  const RingPtr other = Ring::make({"t", "x"});
  EXPECT_THROW(sylvester_matrix(parse("t"), parse_polynomial("t", other), kT), std::invalid_argument);
  EXPECT_THROW(sylvester_matrix(parse("t"), parse("t"), 5), std::invalid_argument);
  PolynomialMatrix m(ring_, 1, 1);
  EXPECT_THROW(m.set(0, 0, parse_polynomial("t", other)), std::invalid_argument);
  EXPECT_THROW(m.at(1, 0), std::out_of_range);
}

TEST_F(SylvesterTest, BareissKnownDeterminants) {
  // Vandermonde.
  EXPECT_EQ(determinant_bareiss(matrix_of({{"1", "x", "x^2"}, {"1", "y", "y^2"}, {"1", "t", "t^2"}})),
            parse("(y-x)*(t-x)*(t-y)"));
  // A zero pivot forces a row exchange (and a sign change).
  EXPECT_EQ(determinant_bareiss(matrix_of({{"0", "1", "0"}, {"1", "0", "0"}, {"0", "0", "x"}})), parse("-x"));
  EXPECT_EQ(determinant_bareiss(matrix_of({{"0", "0", "y"}, {"0", "x", "0"}, {"t", "0", "0"}})), parse("-x*y*t"));
  // Singular: a zero column, and dependent rows.
  EXPECT_TRUE(determinant_bareiss(matrix_of({{"0", "x"}, {"0", "y"}})).is_zero());
  EXPECT_TRUE(determinant_bareiss(matrix_of({{"x", "y", "1"}, {"2x", "2y", "2"}, {"t", "1", "0"}})).is_zero());
  EXPECT_EQ(determinant_bareiss(PolynomialMatrix(ring_, 0, 0)), parse("1"));
  EXPECT_EQ(determinant_bareiss(matrix_of({{"3/2*x"}})), parse("3/2*x"));
  EXPECT_THROW(determinant_bareiss(PolynomialMatrix(ring_, 2, 3)), std::invalid_argument);
}

TEST_F(SylvesterTest, BareissMatchesCofactorExpansion) {
  testing::RandomSource random(20240611);
  for (int k = 0; k < 40; ++k) {
    const std::size_t n = static_cast<std::size_t>(random.uniform(1, 4));
    PolynomialMatrix m(ring_, n, n);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        // Sparse entries, some zero, so that pivots vanish now and then.
        if (random.uniform(0, 3) != 0) m.set(i, j, random.polynomial(ring_, 3, 2));
      }
    }
    EXPECT_EQ(determinant_bareiss(m), determinant_by_expansion(m)) << "matrix " << k;
  }
}

TEST_F(SylvesterTest, BareissStopsWhenTheBudgetIsSpent) {
  PolynomialMatrix m(ring_, 3, 3);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) m.set(i, j, parse("x+t+y+" + std::to_string(i * 3 + j + 1)));
  }
  Budget cancelled;
  cancelled.cancel();
  try {
    determinant_bareiss(m, cancelled);
    ADD_FAILURE() << "no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
    EXPECT_NE(std::string(e.what()).find("cancelled"), std::string::npos);
  }
  Budget small;
  small.set_max_terms(2);
  EXPECT_THROW(determinant_bareiss(m, small), LimitExceeded);
}

}  // namespace
}  // namespace implicitizer
