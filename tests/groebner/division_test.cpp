/// Tests of lib/src/groebner/division.cpp: multivariate division by an ordered list
/// (Cox–Little–O'Shea, Thm 2.3.3), the normal form and the S-polynomial.
/// The textbook examples pin down the exact quotients and remainders (the division
/// depends on the list order, so both orders of Example 2.3.2 are checked); the
/// property tests check the theorem's conclusions on seeded random input in every
/// kind of order.

#include "implicitizer/groebner/division.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "groebner/groebner_support.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

using testing::parse_all;
using testing::print_all;
using testing::RandomSource;

constexpr std::uint64_t kSeed = 20240612;
constexpr int kCasesPerOrder = 40;

// The four conclusions of the division theorem, for the list-order algorithm:
//  1. f = Σ q_i·g_i + r, exactly;
//  2. no term of r is divisible by any lm(g_i);
//  3. lm(q_i·g_i) <= lm(f) whenever q_i ≠ 0;
//  4. (the "first divisor" rule) for every term m of q_i, m·lm(g_i) is divisible by
//     no lm(g_j) with j < i: each term of q_i comes from one step, at which g_i was
//     the first divisor whose leading monomial divided the leading term.
void expect_division_theorem(const Polynomial& f, const std::vector<Polynomial>& divisors, const DivisionResult& d) {
  const RingPtr& ring = f.ring();
  ASSERT_EQ(d.quotients.size(), divisors.size());
  Polynomial sum = d.remainder;
  for (std::size_t i = 0; i < divisors.size(); ++i) sum += d.quotients[i] * divisors[i];
  EXPECT_EQ(sum, f) << to_string(f) << " != " << to_string(sum);
  EXPECT_TRUE(d.remainder.is_canonical());
  for (std::size_t t = 0; t < d.remainder.num_terms(); ++t) {
    for (const auto& g : divisors) {
      EXPECT_FALSE(ring->divides(g.leading_monomial(), d.remainder.monomial(t)))
          << "remainder " << to_string(d.remainder) << " has a term divisible by lm(" << to_string(g) << ")";
    }
    // The remainder only collects leading terms of f's successive differences.
    EXPECT_LE(ring->compare(d.remainder.monomial(t), f.leading_monomial()), 0);
  }
  for (std::size_t i = 0; i < divisors.size(); ++i) {
    const Polynomial& q = d.quotients[i];
    EXPECT_TRUE(q.is_canonical());
    if (q.is_zero()) continue;
    ASSERT_FALSE(f.is_zero());
    const Polynomial product = q * divisors[i];
    EXPECT_LE(ring->compare(product.leading_monomial(), f.leading_monomial()), 0)
        << "lm(q_" << i << "·g_" << i << ") > lm(f) for f = " << to_string(f);
    for (std::size_t t = 0; t < q.num_terms(); ++t) {
      std::vector<std::int32_t> m(ring->monomial_size());
      ring->multiply(q.monomial(t), divisors[i].leading_monomial(), m.data());
      for (std::size_t j = 0; j < i; ++j) {
        EXPECT_FALSE(ring->divides(divisors[j].leading_monomial(), m.data()))
            << "quotient " << i << " took a term that divisor " << j << " comes first for";
      }
    }
  }
}

struct Expected {
  std::vector<std::string> quotients;
  std::string remainder;
};

// Divides `f` by `divisors` in lex with x > y and compares with the book's answer.
void expect_lex_division(const std::string& f, const std::vector<std::string>& divisors, const Expected& expected) {
  const RingPtr ring = Ring::make({"x", "y"}, MonomialOrder::lex());
  const std::vector<Polynomial> gs = parse_all(divisors, ring);
  const DivisionResult d = divide(parse_polynomial(f, ring), gs);
  EXPECT_EQ(print_all(d.quotients), expected.quotients);
  EXPECT_EQ(to_string(d.remainder), expected.remainder);
  expect_division_theorem(parse_polynomial(f, ring), gs, d);
}

// CLO Example 2.3.1: xy^2 + 1 by (xy + 1, y + 1) in lex.
TEST(DivisionTest, CloExample1) { expect_lex_division("x*y^2+1", {"x*y+1", "y+1"}, {{"y", "-1"}, "2"}); }

// CLO Example 2.3.2: x^2y + xy^2 + y^2 by (xy - 1, y^2 - 1) in lex; the remainder
// collects x and y on the way, which is the point of the example.
TEST(DivisionTest, CloExample2) { expect_lex_division("x^2*y+x*y^2+y^2", {"x*y-1", "y^2-1"}, {{"x+y", "1"}, "x+y+1"}); }

// The same with the divisors swapped: another quotient and remainder, so the
// remainder of a plain list is not unique (CLO §2.3, after Example 2).
TEST(DivisionTest, CloExample2ReversedList) {
  expect_lex_division("x^2*y+x*y^2+y^2", {"y^2-1", "x*y-1"}, {{"x+1", "x"}, "2*x+1"});
}

// CLO Example 2.3.5: xy^2 - x lies in (xy + 1, y^2 - 1), yet dividing by that list
// leaves -x - y; the reversed list gives remainder 0.
TEST(DivisionTest, CloExample5IdealMemberWithNonZeroRemainder) {
  expect_lex_division("x*y^2-x", {"x*y+1", "y^2-1"}, {{"y", "0"}, "-x-y"});
  expect_lex_division("x*y^2-x", {"y^2-1", "x*y+1"}, {{"x", "0"}, "0"});
}

TEST(DivisionTest, EmptyListAndZeroDividend) {
  const RingPtr ring = Ring::make({"x", "y", "z"});
  const Polynomial f = parse_polynomial("x^2-3/4*y*z+1", ring);
  const DivisionResult by_nothing = divide(f, {});
  EXPECT_TRUE(by_nothing.quotients.empty());
  EXPECT_EQ(by_nothing.remainder, f);

  const std::vector<Polynomial> gs = parse_all({"x-y", "z^2"}, ring);
  const DivisionResult of_zero = divide(Polynomial(ring), gs);
  ASSERT_EQ(of_zero.quotients.size(), 2u);
  EXPECT_TRUE(of_zero.quotients[0].is_zero());
  EXPECT_TRUE(of_zero.quotients[1].is_zero());
  EXPECT_TRUE(of_zero.remainder.is_zero());
}

// A constant divisor divides everything: the remainder is 0 and, being first in the
// list, it takes every term.
TEST(DivisionTest, ConstantDivisorLeavesNoRemainder) {
  const RingPtr ring = Ring::make({"x", "y"});
  const Polynomial f = parse_polynomial("x^3*y-2/3*x+5", ring);
  const std::vector<Polynomial> gs = parse_all({"-2", "x"}, ring);
  const DivisionResult d = divide(f, gs);
  EXPECT_TRUE(d.remainder.is_zero());
  EXPECT_EQ(d.quotients[0], f.scaled(Rational(-1, 2)));
  EXPECT_TRUE(d.quotients[1].is_zero());
}

TEST(DivisionTest, ZeroDivisorIsRejected) {
  const RingPtr ring = Ring::make({"x", "y"});
  const std::vector<Polynomial> gs = {parse_polynomial("x", ring), Polynomial(ring)};
  EXPECT_THROW(divide(parse_polynomial("x*y", ring), gs), std::invalid_argument);
}

// The division loop consults the budget: a cancelled budget stops it and says so.
TEST(DivisionTest, CancelledBudgetStopsDivision) {
  const RingPtr ring = Ring::make({"x", "y"});
  const std::vector<Polynomial> gs = parse_all({"x-y"}, ring);
  Budget budget;
  budget.cancel();
  try {
    divide(parse_polynomial("x^5+y", ring), gs, budget);
    FAIL() << "no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
}

// The division theorem on random dividends and random lists of 1 to 4 divisors, in
// every kind of order; random rationals include very large and very small ones.
TEST(DivisionTest, RandomDivisionsSatisfyTheDivisionTheorem) {
  for (const MonomialOrder& order : testing::all_orders(3)) {
    SCOPED_TRACE(order.name());
    const RingPtr ring = Ring::make({"x", "y", "z"}, order);
    RandomSource random(kSeed);
    for (int c = 0; c < kCasesPerOrder; ++c) {
      const Polynomial f = random.polynomial(ring, 8, 5);
      std::vector<Polynomial> gs;
      const long count = random.uniform(1, 4);
      while (static_cast<long>(gs.size()) < count) {
        Polynomial g = random.polynomial(ring, 3, 2);
        if (!g.is_zero()) gs.push_back(g);
      }
      SCOPED_TRACE(to_string(f));
      expect_division_theorem(f, gs, divide(f, gs));
    }
  }
}

// normal_form() modulo a Gröbner basis: ideal members (random combinations of the
// generators) reduce to 0, and the normal form of anything does not depend on the
// order of the basis list (CLO Prop. 2.6.1), unlike the remainder of a plain list.
TEST(DivisionTest, NormalFormModuloGroebnerBasis) {
  std::mt19937 rng(kSeed);
  for (const auto& [name, order] : testing::property_orders()) {
    SCOPED_TRACE(name);
    const RingPtr ring = Ring::make({"x", "y", "z"}, order);
    for (const auto& generators : testing::random_ideals(ring, 10)) {
      const std::optional<GroebnerResult> bounded = testing::compute_bounded(generators);
      ASSERT_TRUE(bounded);
      std::vector<Polynomial> basis = bounded->basis;
      ASSERT_FALSE(basis.empty());
      SCOPED_TRACE(::testing::PrintToString(print_all(basis)));
      Polynomial member(ring);
      for (const auto& g : generators) member += testing::random_small_polynomial(rng, ring, 3, 2) * g;
      EXPECT_TRUE(normal_form(member, basis).is_zero()) << to_string(member);

      const Polynomial f = testing::random_small_polynomial(rng, ring, 5, 4);
      const Polynomial r = normal_form(f, basis);
      std::shuffle(basis.begin(), basis.end(), rng);
      EXPECT_EQ(normal_form(f, basis), r);
      // f - nf(f) is in the ideal, nf(nf(f)) = nf(f), and nf is linear.
      EXPECT_TRUE(normal_form(f - r, basis).is_zero());
      EXPECT_EQ(normal_form(r, basis), r);
      EXPECT_EQ(normal_form(f.scaled(Rational(-3, 7)) + member, basis), r.scaled(Rational(-3, 7)));
    }
  }
}

// CLO §2.6, after Definition 4: in grlex with x > y,
// S(x^3y^2 - x^2y^3 + x, 3x^4y + y^2) = -x^3y^3 + x^2 - y^3/3 (printed in grlex
// order, y^3 before x^2).
TEST(DivisionTest, SPolynomialTextbookExample) {
  const RingPtr ring = Ring::make({"x", "y"}, MonomialOrder::grlex());
  const Polynomial f = parse_polynomial("x^3*y^2-x^2*y^3+x", ring);
  const Polynomial g = parse_polynomial("3*x^4*y+y^2", ring);
  EXPECT_EQ(to_string(s_polynomial(f, g)), "-x^3*y^3-1/3*y^3+x^2");
  // Antisymmetric, and blind to scaling of either argument (it uses monic multiples).
  EXPECT_EQ(s_polynomial(g, f), -s_polynomial(f, g));
  EXPECT_EQ(s_polynomial(f.scaled(Rational(-7, 2)), g), s_polynomial(f, g));
  EXPECT_THROW(s_polynomial(f, Polynomial(ring)), std::invalid_argument);
}

// The leading terms cancel in every S-polynomial: lm(S(f, g)) < lcm(lm f, lm g).
TEST(DivisionTest, SPolynomialCancelsLeadingTerms) {
  for (const MonomialOrder& order : testing::all_orders(3)) {
    SCOPED_TRACE(order.name());
    const RingPtr ring = Ring::make({"x", "y", "z"}, order);
    RandomSource random(kSeed + 1);
    for (int c = 0; c < kCasesPerOrder; ++c) {
      const Polynomial f = random.polynomial(ring, 4, 3);
      const Polynomial g = random.polynomial(ring, 4, 3);
      if (f.is_zero() || g.is_zero()) continue;
      const Polynomial s = s_polynomial(f, g);
      if (s.is_zero()) continue;
      std::vector<std::int32_t> l(ring->monomial_size());
      ring->lcm(f.leading_monomial(), g.leading_monomial(), l.data());
      EXPECT_LT(ring->compare(s.leading_monomial(), l.data()), 0) << to_string(f) << ", " << to_string(g);
    }
  }
}

}  // namespace
}  // namespace implicitizer
