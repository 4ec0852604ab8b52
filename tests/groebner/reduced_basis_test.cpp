/// Tests of lib/src/groebner/reduced_basis.cpp: reduce_basis() turns any Gröbner
/// basis of an ideal into the one reduced basis (CLO Thm 2.7.5), and the two slow
/// checks is_groebner() (Buchberger's S-pair criterion) and is_reduced() say no
/// exactly when they should: the property tests lean on them, so a check that always
/// says yes would make those tests worthless.

#include "implicitizer/groebner/reduced_basis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "groebner/groebner_support.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {
namespace {

using testing::parse_all;
using testing::print_all;

constexpr unsigned kSeed = 20240614;
constexpr int kIdealsPerOrder = 10;

using Strings = std::vector<std::string>;

// A Gröbner basis of the same ideal that is far from reduced: the reduced basis plus
// ideal members (combinations of basis elements), scaled copies and duplicates, with
// every element's tail spoiled by multiples of the others, shuffled. Adding ideal
// members to a Gröbner basis keeps it one; so does replacing g by c·g + h·g' with
// lm(h·g') < lm(g), since the leading monomials stay the same.
std::vector<Polynomial> spoiled_basis(const std::vector<Polynomial>& reduced, std::mt19937& rng) {
  const RingPtr& ring = reduced.front().ring();
  std::vector<Polynomial> out;
  std::uniform_int_distribution<int> small(-4, 4);
  const auto nonzero = [&] {
    const int c = small(rng);
    return Rational(c == 0 ? 3 : c);
  };
  for (std::size_t i = 0; i < reduced.size(); ++i) {
    Polynomial g = reduced[i].scaled(nonzero());
    // Smaller elements (sorted increasingly) added to a larger one leave its
    // leading monomial alone.
    for (std::size_t j = 0; j < i; ++j) g += reduced[j].scaled(nonzero());
    out.push_back(g);
    out.push_back(reduced[i].scaled(Rational(-2, 7)));
  }
  const Polynomial x = Polynomial::variable(ring, 0), y = Polynomial::variable(ring, 1);
  for (std::size_t i = 0; i < reduced.size(); ++i) {
    out.push_back(reduced[i] * x + reduced[(i + 1) % reduced.size()] * y);
  }
  out.push_back(Polynomial(ring));  // a zero element is ignored
  std::shuffle(out.begin(), out.end(), rng);
  return out;
}

// Property: for random ideals in every order, reduce_basis() of a spoiled basis is
// the reduced basis itself, on one thread or several; is_groebner accepts the spoiled basis and is_reduced
// rejects it.
TEST(ReducedBasisTest, SpoiledBasisReducesToTheReducedBasis) {
  std::mt19937 rng(kSeed);
  for (const auto& [name, order] : testing::property_orders()) {
    SCOPED_TRACE(name);
    const RingPtr ring = Ring::make({"x", "y", "z"}, order);
    for (const auto& generators : testing::random_ideals(ring, kIdealsPerOrder)) {
      const std::optional<GroebnerResult> bounded = testing::compute_bounded(generators);
      ASSERT_TRUE(bounded);
      const std::vector<Polynomial>& reduced = bounded->basis;
      SCOPED_TRACE(::testing::PrintToString(print_all(reduced)));
      const std::vector<Polynomial> spoiled = spoiled_basis(reduced, rng);
      EXPECT_TRUE(is_groebner(spoiled));
      EXPECT_FALSE(is_reduced(spoiled));
      const std::vector<Polynomial> again = reduce_basis(spoiled);
      EXPECT_EQ(print_all(again), print_all(reduced));
      // The tails shared among threads: the same basis.
      EXPECT_EQ(print_all(reduce_basis(spoiled, Budget(), 3)), print_all(reduced));
      EXPECT_TRUE(is_reduced(again));
      // Idempotent.
      EXPECT_EQ(reduce_basis(again), again);
    }
  }
}

// Equal leading monomials: one element survives, and which one does not matter.
TEST(ReducedBasisTest, EqualLeadingMonomialsKeepOne) {
  const RingPtr ring = Ring::make({"x", "y", "z"});
  // The grevlex basis of the twisted cubic, with x^2 - y replaced by two elements
  // with leading monomial x^2: x^2 - y + (xy - z) and 3x^2 - 3y.
  const std::vector<Polynomial> basis = parse_all({"x^2+x*y-y-z", "y^2-x*z", "3*x^2-3*y", "x*y-z"}, ring);
  ASSERT_TRUE(is_groebner(basis));
  EXPECT_EQ(print_all(reduce_basis(basis)), (Strings{"y^2-x*z", "x*y-z", "x^2-y"}));
}

// is_groebner() on generators: when some leading monomial of the reduced basis is
// divisible by no generator's leading monomial, the leading terms of the generators
// do not generate the leading ideal, so they are not a Gröbner basis (CLO Def.
// 2.5.5); adding the reduced basis to them always makes one.
TEST(ReducedBasisTest, IsGroebnerRejectsGeneratorsThatAreNotABasis) {
  const RingPtr cubic_ring = Ring::make({"x", "y", "z"});
  EXPECT_FALSE(is_groebner(parse_all({"y-x^2", "z-x^3"}, cubic_ring)));

  int rejected = 0;
  for (const auto& [name, order] : testing::property_orders()) {
    SCOPED_TRACE(name);
    const RingPtr ring = Ring::make({"x", "y", "z"}, order);
    for (const auto& generators : testing::random_ideals(ring, kIdealsPerOrder)) {
      const std::optional<GroebnerResult> bounded = testing::compute_bounded(generators);
      ASSERT_TRUE(bounded);
      const std::vector<Polynomial>& reduced = bounded->basis;
      SCOPED_TRACE(::testing::PrintToString(print_all(generators)));
      const bool leading_terms_missing = std::any_of(reduced.begin(), reduced.end(), [&](const Polynomial& g) {
        return std::none_of(generators.begin(), generators.end(), [&](const Polynomial& f) {
          return ring->divides(f.leading_monomial(), g.leading_monomial());
        });
      });
      if (leading_terms_missing) {
        EXPECT_FALSE(is_groebner(generators));
        ++rejected;
      }
      std::vector<Polynomial> completed = generators;
      completed.insert(completed.end(), reduced.begin(), reduced.end());
      EXPECT_TRUE(is_groebner(completed));
      EXPECT_EQ(reduce_basis(completed), reduced);
    }
  }
  // Random generators are rarely a Gröbner basis already: the check did say no.
  EXPECT_GT(rejected, 10);
}

// CLO §2.7 Example 1: (x^3 - 2xy, x^2y - 2y^2 + x) in grlex is not a Gröbner basis
// (S = -x^2 has no leading monomial among the leading terms), but its completion,
// from the same section, is; the reduced one is (x^2, xy, y^2 - x/2).
TEST(ReducedBasisTest, TextbookNonBasisAndItsCompletion) {
  const RingPtr ring = Ring::make({"x", "y"}, MonomialOrder::grlex());
  const std::vector<Polynomial> f = parse_all({"x^3-2*x*y", "x^2*y-2*y^2+x"}, ring);
  EXPECT_FALSE(is_groebner(f));
  std::vector<Polynomial> completed = f;
  for (const auto& g : parse_all({"-x^2", "-2*x*y", "-2*y^2+x"}, ring)) completed.push_back(g);
  EXPECT_TRUE(is_groebner(completed));
  EXPECT_FALSE(is_reduced(completed));
  EXPECT_EQ(print_all(reduce_basis(completed)), (Strings{"y^2-1/2*x", "x*y", "x^2"}));
}

TEST(ReducedBasisTest, IsReducedRejectsEachDefect) {
  const RingPtr ring = Ring::make({"x", "y", "z"});
  const std::vector<Polynomial> reduced = parse_all({"y^2-x*z", "x*y-z", "x^2-y"}, ring);
  ASSERT_TRUE(is_reduced(reduced));
  ASSERT_TRUE(is_groebner(reduced));

  std::vector<Polynomial> not_monic = reduced;
  not_monic[1] = not_monic[1].scaled(Rational(2));
  EXPECT_FALSE(is_reduced(not_monic));
  EXPECT_TRUE(is_groebner(not_monic));

  // A tail term divisible by another element's leading monomial (xy in x^2 - y + xy).
  std::vector<Polynomial> tail = reduced;
  tail[2] = parse_polynomial("x^2+x*y-y", ring);
  EXPECT_FALSE(is_reduced(tail));

  // A leading monomial divisible by another's (not minimal).
  std::vector<Polynomial> not_minimal = reduced;
  not_minimal.push_back(parse_polynomial("x^3-x*y", ring));
  EXPECT_FALSE(is_reduced(not_minimal));

  // The same element twice: each leading monomial divides the other.
  std::vector<Polynomial> duplicate = reduced;
  duplicate.push_back(reduced[0]);
  EXPECT_FALSE(is_reduced(duplicate));

  std::vector<Polynomial> with_zero = reduced;
  with_zero.push_back(Polynomial(ring));
  EXPECT_FALSE(is_reduced(with_zero));
}

TEST(ReducedBasisTest, TrivialBases) {
  const RingPtr ring = Ring::make({"x", "y"});
  EXPECT_TRUE(reduce_basis({}).empty());
  EXPECT_TRUE(is_reduced({}));
  EXPECT_TRUE(is_groebner({}));

  const std::vector<Polynomial> zeros = {Polynomial(ring)};
  EXPECT_TRUE(reduce_basis(zeros).empty());

  // Any non-zero constant makes the whole list collapse to {1}.
  const std::vector<Polynomial> unit = parse_all({"x^2-y", "-4", "x*y+1"}, ring);
  EXPECT_TRUE(is_groebner(unit));
  EXPECT_EQ(print_all(reduce_basis(unit)), (Strings{"1"}));
  EXPECT_TRUE(is_reduced(reduce_basis(unit)));

  const std::vector<Polynomial> single = parse_all({"-2*x*y+6"}, ring);
  EXPECT_TRUE(is_groebner(single));
  EXPECT_FALSE(is_reduced(single));
  EXPECT_EQ(print_all(reduce_basis(single)), (Strings{"x*y-3"}));
}

// The checks consult the budget they are given.
TEST(ReducedBasisTest, CancelledBudgetStopsTheChecks) {
  const RingPtr ring = Ring::make({"x", "y", "z"});
  // Checking this basis needs a reduction step (S(xy - z, x^2 - y) = y^2 - xz), and
  // so does reducing the tail x^2 of y^3 - x^2 by x^2 - y.
  const std::vector<Polynomial> basis = parse_all({"y^2-x*z", "x*y-z", "x^2-y"}, ring);
  const std::vector<Polynomial> to_reduce = parse_all({"x^2-y", "y^3-x^2"}, ring);
  Budget budget;
  budget.cancel();
  try {
    is_groebner(basis, budget);
    ADD_FAILURE() << "is_groebner: no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
  try {
    reduce_basis(to_reduce, budget);
    ADD_FAILURE() << "reduce_basis: no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
}

}  // namespace
}  // namespace implicitizer
