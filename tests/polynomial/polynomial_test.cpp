// Tests of Polynomial (lib/src/polynomial/polynomial.cpp): construction, the
// content × primitive representation, and ring identities checked on seeded random
// polynomials in every kind of order, with is_canonical() after every operation.

#include "implicitizer/polynomial/polynomial.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "implicitizer/core/memory_account.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

using testing::RandomSource;

constexpr int kSeedsPerOrder = 40;

Rational evaluate_at(const Polynomial& p, const std::vector<Rational>& point) { return p.evaluate(point); }

// Runs `body(ring, random)` for every order over the variables x, y, z, w.
template <typename Body>
void for_every_order(std::uint64_t seed, Body body) {
  const std::vector<std::string> names = {"x", "y", "z", "w"};
  for (const MonomialOrder& order : testing::all_orders(names.size())) {
    SCOPED_TRACE(order.name());
    const RingPtr ring = Ring::make(names, order);
    RandomSource random(seed);
    for (int i = 0; i < kSeedsPerOrder; ++i) body(ring, random);
  }
}

#define EXPECT_CANONICAL(p) EXPECT_TRUE((p).is_canonical()) << to_string(p)

class PolynomialTest : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"x", "y", "z"});
  Polynomial parse(const std::string& text) const { return parse_polynomial(text, ring_); }
};

TEST_F(PolynomialTest, ZeroConstantsVariablesTerms) {
  const Polynomial zero(ring_);
  EXPECT_TRUE(zero.is_zero());
  EXPECT_TRUE(zero.is_constant());
  EXPECT_EQ(zero.num_terms(), 0u);
  EXPECT_EQ(zero.total_degree(), -1);
  EXPECT_EQ(zero.degree_in(0), -1);
  EXPECT_EQ(zero.content(), Rational(0));
  EXPECT_CANONICAL(zero);

  const Polynomial c = Polynomial::constant(ring_, Rational(-3, 4));
  EXPECT_TRUE(c.is_constant());
  EXPECT_EQ(c.total_degree(), 0);
  EXPECT_EQ(c.coefficient(0), Rational(-3, 4));
  EXPECT_CANONICAL(c);
  EXPECT_TRUE(Polynomial::constant(ring_, Rational(0)).is_zero());

  const Polynomial y = Polynomial::variable(ring_, 1);
  EXPECT_FALSE(y.is_constant());
  EXPECT_EQ(y.exponents(0), (std::vector<std::int32_t>{0, 1, 0}));
  EXPECT_TRUE(y.involves(1));
  EXPECT_FALSE(y.involves(0));
  EXPECT_THROW(Polynomial::variable(ring_, 3), std::out_of_range);

  const std::vector<std::int32_t> e = {2, 0, 5};
  const Polynomial t = Polynomial::term(ring_, Rational(7, 3), e);
  EXPECT_EQ(t.exponents(0), e);
  EXPECT_EQ(t.leading_coefficient(), Rational(7, 3));
  EXPECT_EQ(t.total_degree(), 7);
  EXPECT_EQ(t.degree_in(2), 5);
  EXPECT_CANONICAL(t);
  EXPECT_TRUE(Polynomial::term(ring_, Rational(0), e).is_zero());
  const std::vector<std::int32_t> short_e = {1, 2};
  EXPECT_THROW(Polynomial::term(ring_, Rational(1), short_e), std::invalid_argument);
}

// A ring without variables holds only constants; its monomials have no words, and
// the product must not index its empty scratch vector (found by fuzz/).
TEST(PolynomialWithoutVariables, ConstantsMultiply) {
  const RingPtr ring = Ring::make({});
  const Polynomial p = Polynomial::constant(ring, Rational(2)) * Polynomial::constant(ring, Rational(3));
  EXPECT_EQ(p, Polynomial::constant(ring, Rational(6)));
  EXPECT_EQ(p.pow(3), Polynomial::constant(ring, Rational(216)));
}

TEST_F(PolynomialTest, ContentTimesPrimitivePart) {
  const Polynomial p = parse("6x+4y");
  EXPECT_EQ(p.content(), Rational(2));
  EXPECT_EQ(p.integer_coefficients(), (std::vector<Integer>{3, 2}));

  const Polynomial q = parse("-6x+4y");
  EXPECT_EQ(q.content(), Rational(-2));
  EXPECT_EQ(q.integer_coefficients(), (std::vector<Integer>{3, -2}));
  EXPECT_EQ(q.coefficient(1), Rational(4));

  const Polynomial r = parse("x/6 + y/4");
  EXPECT_EQ(r.content(), Rational(1, 12));
  EXPECT_EQ(r.integer_coefficients(), (std::vector<Integer>{2, 3}));
  EXPECT_CANONICAL(r);

  EXPECT_EQ(q.primitive_part(), parse("3x-2y"));
  EXPECT_EQ(parse("-3/4*x^2+y").primitive_part(), parse("3x^2-4y"));
  EXPECT_EQ(parse("-3/4*x^2+y").monic(), parse("x^2-4/3*y"));
  EXPECT_TRUE(Polynomial(ring_).primitive_part().is_zero());
  EXPECT_TRUE(Polynomial(ring_).monic().is_zero());
}

TEST_F(PolynomialTest, FromTermsSortsAndCombines) {
  const std::size_t w = ring_->monomial_size();
  std::vector<std::int32_t> monomials(4 * w);
  const std::int32_t ex[4][3] = {{1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 0}};
  for (int i = 0; i < 4; ++i) ring_->encode(ex[i], &monomials[i * w]);
  const Polynomial p = Polynomial::from_terms(ring_, Rational(1, 2), {3, 5, -3, 4}, monomials);
  EXPECT_EQ(p, parse("5/2*y+2"));
  EXPECT_CANONICAL(p);
  const Polynomial zero =
      Polynomial::from_terms(ring_, Rational(1), {3, -3}, {monomials.begin(), monomials.begin() + 2 * w});
  EXPECT_FALSE(zero.is_zero());  // x and y do not cancel
  std::vector<std::int32_t> xx(monomials.begin(), monomials.begin() + w);
  xx.insert(xx.end(), monomials.begin(), monomials.begin() + w);
  EXPECT_TRUE(Polynomial::from_terms(ring_, Rational(1), {3, -3}, xx).is_zero());
}

TEST_F(PolynomialTest, EqualRingsAreInterchangeable) {
  const RingPtr other = Ring::make({"x", "y", "z"});
  const Polynomial a = parse("x+y");
  const Polynomial b = parse_polynomial("x+y", other);
  EXPECT_EQ(a, b);
  EXPECT_EQ(a + b, parse("2x+2y"));
}

TEST_F(PolynomialTest, DifferentRingsAreRefused) {
  const RingPtr lex = Ring::make({"x", "y", "z"}, MonomialOrder::lex());
  const Polynomial a = parse("x+y");
  const Polynomial b = parse_polynomial("x+y", lex);
  EXPECT_FALSE(a == b);
  EXPECT_THROW(a + b, std::logic_error);
  EXPECT_THROW(a * b, std::logic_error);
}

TEST_F(PolynomialTest, DivisionByZeroConstant) {
  EXPECT_TRUE(testing::throws_input_error([&] { parse("x").divided_by(Rational(0)); }, "division_by_zero"));
  EXPECT_EQ(parse("3x").divided_by(Rational(3, 2)), parse("2x"));
  EXPECT_TRUE(parse("x").scaled(Rational(0)).is_zero());
}

TEST_F(PolynomialTest, MultiplicationRespectsTheTermBudget) {
  const Polynomial a = parse("(x+1)*(y+1)");
  const Polynomial b = parse("(z+1)*(z-2)");
  Budget budget;
  budget.set_max_terms(8);
  try {
    a.multiply(b, budget);  // 4 · 3 = 12 terms
    FAIL();
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
    EXPECT_NE(std::string(e.what()).find("polynomial multiplication"), std::string::npos) << e.what();
  }
  budget.set_max_terms(12);
  EXPECT_EQ(a.multiply(b, budget).num_terms(), 12u);
}

// Issue 41: products of polynomials in separate parameters (the denominators of
// sin(u)^1000 and cos(v)^1000) were built to 16 million terms before the limit was
// read. Their size is known before multiplying, and the refusal comes first: the
// memory the computation held stays far below the product's.
TEST_F(PolynomialTest, ProductInDisjointVariablesIsRefusedBeforeItIsBuilt) {
  const Polynomial a = parse("(1+x^2)^300");  // 301 terms
  const Polynomial b = parse("(1+y^2)^300");
  Budget budget;
  budget.set_max_terms(20'000).set_max_memory(std::size_t{1} << 30);  // the account only measures
  const MemoryScope scope(budget.memory_account());
  const std::size_t before = budget.memory_account()->bytes();
  try {
    a.multiply(b, budget);
    FAIL();
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
    const std::string message = e.what();
    EXPECT_NE(message.find("the product of 301 and 301 terms in disjoint variables would have 90601 terms (limit "
                           "20000); refused before it was built"),
              std::string::npos)
        << message;
  }
  // 90 601 coefficients of about 540 bits would hold more than 6 MiB; the refusal holds
  // none of them.
  if (memory_accounting_enabled()) {
    EXPECT_LT(budget.memory_account()->peak_bytes() - before, std::size_t{1} << 20);
  }
}

// A product in shared variables can collapse far below na·nb, so no bound refuses it:
// (1+x)^300·(1−x)^300 = (1−x²)^300 has 301 terms though 301·301 pass the limit.
TEST_F(PolynomialTest, CollapsingProductIsNotRefusedByABound) {
  Budget budget;
  budget.set_max_terms(1000);
  const Polynomial p = parse("(1+x)^300").multiply(parse("(1-x)^300"), budget);
  EXPECT_EQ(p, parse("(1-x^2)^300"));
}

// A product in shared variables that does grow past the limit is refused while it
// grows, within one check interval of the limit, naming the limit it passed.
TEST_F(PolynomialTest, GrowingProductIsRefusedWhileItGrows) {
  Budget budget;
  budget.set_max_terms(2000);
  try {
    parse("(1+x+y)^60").multiply(parse("(1+x-z)^60"), budget);
    FAIL();
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
    EXPECT_NE(std::string(e.what()).find("a polynomial reached"), std::string::npos) << e.what();
  }
}

// A power whose terms are affinely independent monomials has exactly the binomial
// count of terms, C(m − 1 + e, e): refused before the first multiplication.
TEST_F(PolynomialTest, PowerIsRefusedByItsBinomialCount) {
  Budget budget;
  budget.set_max_terms(1000);
  try {
    parse("x+y+z").pow(60, budget);  // C(62, 2) = 1891 terms
    FAIL();
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
    EXPECT_NE(std::string(e.what()).find("the power 60 of 3 terms would have 1891 terms"), std::string::npos)
        << e.what();
  }
  budget.set_max_terms(1891);
  EXPECT_EQ(parse("x+y+z").pow(60, budget).num_terms(), 1891u);
  // 1 + x + x² is not affinely independent (its powers have 2e + 1 terms, not the
  // binomial count): no prediction, and the power goes through.
  budget.set_max_terms(200);
  EXPECT_EQ(parse("1+x+x^2").pow(60, budget).num_terms(), 121u);
}

TEST_F(PolynomialTest, PowerStopsOnTime) {
  const Budget budget = Budget::with_timeout(1e-6);
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  try {
    parse("x+y+1").pow(3, budget);
    FAIL();
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
}

TEST_F(PolynomialTest, DegreeLimit) {
  const std::vector<std::int32_t> e = {kMaxTotalDegree, 0, 0};
  const Polynomial big = Polynomial::term(ring_, Rational(1), e);
  try {
    big* parse("x");
    FAIL();
  } catch (const LimitExceeded& ex) {
    EXPECT_EQ(ex.limit(), Limit::size);
  }
  try {
    parse("x*y").pow(kMaxTotalDegree / 2 + 1);
    FAIL();
  } catch (const LimitExceeded& ex) {
    EXPECT_EQ(ex.limit(), Limit::size);
  }
}

TEST_F(PolynomialTest, HomogenizeKnownExample) {
  const RingPtr ring = Ring::make({"x", "y", "h"});
  const Polynomial p = parse_polynomial("x^3 - 2x*y + 5", ring);
  EXPECT_EQ(p.homogenize(2), parse_polynomial("x^3 - 2x*y*h + 5h^3", ring));
  EXPECT_THROW(p.homogenize(0), std::invalid_argument);
  EXPECT_THROW(p.homogenize(3), std::out_of_range);
  EXPECT_TRUE(Polynomial(ring).homogenize(2).is_zero());
}

TEST_F(PolynomialTest, DerivativeKnownExample) {
  EXPECT_EQ(parse("x^3*y - 2x*y^2 + 7z - 1").derivative(0), parse("3x^2*y - 2y^2"));
  // Leading term dies and the new leading coefficient is negative: sign must be renormalized.
  EXPECT_EQ(parse("x^2 - y^2*z").derivative(2), parse("-y^2"));
  EXPECT_CANONICAL(parse("x^2 - y^2*z").derivative(2));
  EXPECT_TRUE(parse("x^2").derivative(1).is_zero());
  EXPECT_THROW(parse("x").derivative(3), std::out_of_range);
}

TEST_F(PolynomialTest, EvaluateKnownExample) {
  const std::vector<Rational> point = {Rational(1, 2), Rational(-3), Rational(2, 3)};
  EXPECT_EQ(parse("4x^2*y - 9z^2 + 1/7").evaluate(point), Rational(-3 - 4) + Rational(1, 7));
  const std::vector<Rational> bad = {Rational(1)};
  EXPECT_THROW(parse("x").evaluate(bad), std::invalid_argument);
}

TEST_F(PolynomialTest, SubstituteAndComposeKnownExample) {
  EXPECT_EQ(parse("x^2 + y").substitute(0, parse("y - z")), parse("y^2 - 2y*z + z^2 + y"));
  const RingPtr params = Ring::make({"s", "t"});
  const std::vector<Polynomial> values = {parse_polynomial("s+t", params), parse_polynomial("s-t", params),
                                          parse_polynomial("2", params)};
  EXPECT_EQ(parse("x*y - z").compose(params, values), parse_polynomial("s^2 - t^2 - 2", params));
  EXPECT_THROW(parse("x").compose(params, std::span<const Polynomial>(values.data(), 2)), std::invalid_argument);
}

TEST(PolynomialProperties, AdditionIsACommutativeGroup) {
  for_every_order(1, [](const RingPtr& ring, RandomSource& random) {
    const Polynomial a = random.polynomial(ring), b = random.polynomial(ring), c = random.polynomial(ring);
    const Polynomial zero(ring);
    EXPECT_EQ(a + b, b + a);
    EXPECT_EQ((a + b) + c, a + (b + c));
    EXPECT_EQ(a + zero, a);
    EXPECT_TRUE((a - a).is_zero());
    EXPECT_CANONICAL(a - a);
    EXPECT_EQ(-(-a), a);
    EXPECT_EQ((a + b) - b, a);
    EXPECT_CANONICAL(a + b);
    EXPECT_CANONICAL(a - b);
    EXPECT_CANONICAL(-a);
  });
}

TEST(PolynomialProperties, MultiplicationIsACommutativeRing) {
  for_every_order(2, [](const RingPtr& ring, RandomSource& random) {
    const Polynomial a = random.polynomial(ring), b = random.polynomial(ring), c = random.polynomial(ring);
    const Polynomial one = Polynomial::constant(ring, Rational(1));
    EXPECT_EQ(a * b, b * a);
    EXPECT_EQ((a * b) * c, a * (b * c));
    EXPECT_EQ((a + b) * c, a * c + b * c);
    EXPECT_EQ(a * one, a);
    EXPECT_TRUE((a * Polynomial(ring)).is_zero());
    EXPECT_EQ((a - b) * (a + b), a * a - b * b);
    EXPECT_CANONICAL(a * b);
    EXPECT_CANONICAL((a + b) * c);
    if (!a.is_zero() && !b.is_zero()) {
      EXPECT_EQ((a * b).total_degree(), a.total_degree() + b.total_degree());
      EXPECT_EQ((a * b).num_terms() > 0, true);
    }
  });
}

TEST(PolynomialProperties, PowerIsRepeatedMultiplication) {
  for_every_order(3, [](const RingPtr& ring, RandomSource& random) {
    const Polynomial a = random.polynomial(ring, 4, 3);
    Polynomial repeated = Polynomial::constant(ring, Rational(1));
    for (unsigned k = 0; k <= 4; ++k) {
      const Polynomial power = a.pow(k);
      EXPECT_EQ(power, repeated) << "k = " << k;
      EXPECT_CANONICAL(power);
      repeated = repeated * a;
    }
    EXPECT_EQ(a.pow(2) * a.pow(3), a.pow(5));
  });
}

TEST(PolynomialProperties, ScalingTouchesOnlyTheContent) {
  for_every_order(4, [](const RingPtr& ring, RandomSource& random) {
    const Polynomial a = random.polynomial(ring);
    const Rational c = random.rational();
    const Polynomial scaled = a.scaled(c);
    EXPECT_CANONICAL(scaled);
    EXPECT_EQ(scaled.divided_by(c), a);
    EXPECT_EQ(scaled, a * Polynomial::constant(ring, c));
    if (a.is_zero()) return;
    EXPECT_EQ(a.primitive_part().scaled(a.content()), a);
    EXPECT_CANONICAL(a.primitive_part());
    EXPECT_EQ(a.monic().leading_coefficient(), Rational(1));
    EXPECT_EQ(a.monic().scaled(a.leading_coefficient()), a);
    EXPECT_CANONICAL(a.monic());
    EXPECT_GT(a.primitive_part().leading_coefficient(), Rational(0));
    for (std::size_t i = 0; i < a.num_terms(); ++i) {
      EXPECT_EQ(a.primitive_part().coefficient(i), to_rational(a.integer_coefficients()[i]));
    }
  });
}

TEST(PolynomialProperties, DerivativeIsADerivation) {
  for_every_order(5, [](const RingPtr& ring, RandomSource& random) {
    const Polynomial a = random.polynomial(ring), b = random.polynomial(ring);
    for (std::size_t v = 0; v < ring->num_variables(); ++v) {
      const Polynomial d = (a * b).derivative(v);
      EXPECT_EQ(d, a.derivative(v) * b + a * b.derivative(v));
      EXPECT_EQ((a + b).derivative(v), a.derivative(v) + b.derivative(v));
      EXPECT_CANONICAL(d);
      EXPECT_CANONICAL(a.derivative(v));
      if (a.degree_in(v) > 0) {
        EXPECT_EQ(a.derivative(v).degree_in(v), a.degree_in(v) - 1);
      }
    }
  });
}

TEST(PolynomialProperties, EvaluationIsARingHomomorphism) {
  for_every_order(6, [](const RingPtr& ring, RandomSource& random) {
    const Polynomial a = random.polynomial(ring), b = random.polynomial(ring);
    const std::vector<Rational> point = random.point(ring->num_variables());
    EXPECT_EQ(evaluate_at(a * b, point), evaluate_at(a, point) * evaluate_at(b, point));
    EXPECT_EQ(evaluate_at(a + b, point), evaluate_at(a, point) + evaluate_at(b, point));
    EXPECT_EQ(evaluate_at(-a, point), -evaluate_at(a, point));
    const Rational c = random.rational();
    EXPECT_EQ(evaluate_at(a.scaled(c), point), c * evaluate_at(a, point));
    EXPECT_EQ(evaluate_at(Polynomial::constant(ring, c), point), c);
  });
}

TEST(PolynomialProperties, ComposeAgreesWithEvaluate) {
  const RingPtr params = Ring::make({"s", "t"}, MonomialOrder::lex());
  for_every_order(7, [&](const RingPtr& ring, RandomSource& random) {
    const Polynomial p = random.polynomial(ring, 5, 3);
    std::vector<Polynomial> values;
    for (std::size_t i = 0; i < ring->num_variables(); ++i) values.push_back(random.polynomial(params, 3, 2));
    const Polynomial composed = p.compose(params, values);
    EXPECT_CANONICAL(composed);
    const std::vector<Rational> point = random.point(2);
    std::vector<Rational> image;
    for (const auto& v : values) image.push_back(v.evaluate(point));
    EXPECT_EQ(composed.evaluate(point), p.evaluate(image));
    // Composing with the variables themselves is the identity.
    std::vector<Polynomial> identity;
    for (std::size_t i = 0; i < ring->num_variables(); ++i) identity.push_back(Polynomial::variable(ring, i));
    EXPECT_EQ(p.compose(ring, identity), p);
  });
}

TEST(PolynomialProperties, SubstituteAgreesWithEvaluate) {
  for_every_order(8, [](const RingPtr& ring, RandomSource& random) {
    const Polynomial p = random.polynomial(ring, 5, 3);
    const Polynomial q = random.polynomial(ring, 3, 2);
    const std::size_t var = static_cast<std::size_t>(random.uniform(0, 3));
    const Polynomial s = p.substitute(var, q);
    EXPECT_CANONICAL(s);
    std::vector<Rational> point = random.point(ring->num_variables());
    std::vector<Rational> moved = point;
    moved[var] = q.evaluate(point);
    EXPECT_EQ(s.evaluate(point), p.evaluate(moved));
    EXPECT_EQ(p.substitute(var, Polynomial::variable(ring, var)), p);
  });
}

TEST(PolynomialProperties, HomogenizeThenDehomogenize) {
  const std::vector<std::string> names = {"x", "y", "z", "h"};
  for (const MonomialOrder& order : testing::all_orders(names.size())) {
    SCOPED_TRACE(order.name());
    const RingPtr small = Ring::make({"x", "y", "z"}, MonomialOrder::grevlex());
    const RingPtr ring = Ring::make(names, order);
    const std::vector<std::size_t> into = {0, 1, 2};
    RandomSource random(9);
    for (int i = 0; i < kSeedsPerOrder; ++i) {
      const Polynomial p = random.polynomial(small).map_to(ring, into);
      const Polynomial h = p.homogenize(3);
      EXPECT_CANONICAL(h);
      EXPECT_EQ(h.num_terms(), p.num_terms());
      for (std::size_t t = 0; t < h.num_terms(); ++t) EXPECT_EQ(ring->total_degree(h.monomial(t)), p.total_degree());
      EXPECT_EQ(h.substitute(3, Polynomial::constant(ring, Rational(1))), p);
    }
  }
}

TEST(PolynomialProperties, MapToRoundTrip) {
  for_every_order(10, [](const RingPtr& ring, RandomSource& random) {
    const Polynomial p = random.polynomial(ring);
    // Into a bigger ring with another order and the variables in reverse.
    const RingPtr big = Ring::make({"a", "w", "z", "y", "x", "b"}, MonomialOrder::lex());
    const std::vector<std::size_t> there = {4, 3, 2, 1};
    const std::vector<std::size_t> back = {0, 3, 2, 1, 0, 0};  // a and b never occur
    const Polynomial q = p.map_to(big, there);
    EXPECT_CANONICAL(q);
    EXPECT_EQ(to_string(q.map_to(ring, back)), to_string(p));
    EXPECT_EQ(q.map_to(ring, back), p);
    // Renaming preserves values at corresponding points.
    const std::vector<Rational> point = random.point(4);
    const std::vector<Rational> big_point = {Rational(5), point[3], point[2], point[1], point[0], Rational(-7)};
    EXPECT_EQ(q.evaluate(big_point), p.evaluate(point));
  });
}

TEST(PolynomialProperties, SumOfEqualsSequentialSum) {
  for_every_order(11, [](const RingPtr& ring, RandomSource& random) {
    std::vector<Polynomial> parts;
    Polynomial sequential(ring);
    const long n = random.uniform(0, 9);
    for (long i = 0; i < n; ++i) {
      parts.push_back(random.polynomial(ring));
      sequential += parts.back();
    }
    const Polynomial s = sum_of(ring, parts);
    EXPECT_EQ(s, sequential);
    EXPECT_CANONICAL(s);
  });
}

}  // namespace
}  // namespace implicitizer
