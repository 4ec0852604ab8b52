// Tests of lib/src/approximation/patch_evaluator.cpp: DoublePolynomial's value and
// gradient, on its unrolled paths (two and three variables) and its general one
// (four), against each term evaluated on its own; the factors are multiplied in the
// same order, so the results agree to the bit.

#include "patch_evaluator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer::approximation {
namespace {

// c·Π x_v^e_v for every term, x^e as e − 1 products, in the order of the variables.
double term_by_term(const Polynomial& p, const std::vector<double>& x, std::vector<double>* gradient) {
  const auto power = [](double base, std::int32_t e) {
    double r = 1;
    for (std::int32_t k = 0; k < e; ++k) r *= base;
    return r;
  };
  const std::size_t n = x.size();
  if (gradient) gradient->assign(n, 0.0);
  double sum = 0;
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    const std::vector<std::int32_t> e = p.exponents(t);
    const double c = to_mpq(p.coefficient(t)).get_d();
    double term = c;
    for (std::size_t v = 0; v < n; ++v) term *= power(x[v], e[v]);
    sum += term;
    if (!gradient) continue;
    for (std::size_t v = 0; v < n; ++v) {
      if (e[v] == 0) continue;
      double d = c * e[v] * power(x[v], e[v] - 1);
      for (std::size_t w = 0; w < n; ++w) {
        if (w != v) d *= power(x[w], e[w]);
      }
      (*gradient)[v] += d;
    }
  }
  return sum;
}

void check_against_terms(const std::vector<std::string>& variables, const std::string& text) {
  const Polynomial p = parse_polynomial(text, Ring::make(variables));
  const DoublePolynomial q(p);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  for (int k = 0; k < 50; ++k) {
    std::vector<double> x(variables.size());
    for (double& c : x) c = coordinate(random);
    std::vector<double> expected_gradient, gradient(variables.size());
    EXPECT_EQ(q.value(x.data()), term_by_term(p, x, nullptr)) << text;
    EXPECT_EQ(q.value_and_gradient(x.data(), gradient.data()), term_by_term(p, x, &expected_gradient)) << text;
    EXPECT_EQ(gradient, expected_gradient) << text;
  }
}

TEST(DoublePolynomial, TwoVariablesAgreeWithEachTermToTheBit) {
  check_against_terms({"s", "t"}, "3*s^4*t^2-7/3*s*t^5+s^3-2*t+11/7");
}

TEST(DoublePolynomial, ThreeVariablesAgreeWithEachTermToTheBit) {
  check_against_terms({"x", "y", "z"}, "64*z^9-432*x^2*z^6+2187*x^4*y^2-6318*x^2*y^2*z^3+x*y*z-5/2*y^3+1");
}

TEST(DoublePolynomial, FourVariablesAgreeWithEachTermToTheBit) {
  check_against_terms({"a", "b", "c", "d"}, "a^3*b*c^2*d-2*a*d^4+7*b^2*c-c*d+1/3");
}

}  // namespace
}  // namespace implicitizer::approximation
