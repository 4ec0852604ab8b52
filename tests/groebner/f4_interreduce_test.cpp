// F4's final interreduction by a recorded plan (lib/src/groebner/f4_interreduce.hpp):
// a basis modulo another prime with the recorded supports fits the plan and reduces
// by it to what the polynomial interreduction gives; a basis with other supports does
// not fit, and is reduced in full.
#include "f4_interreduce.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "f4_engine.hpp"
#include "groebner/groebner_support.hpp"
#include "int_polynomial.hpp"

namespace implicitizer::detail {
namespace {

constexpr std::uint64_t kFirstPrime = 2147483629;            // 2^31 − 19
constexpr std::uint64_t kSecondPrime = 4611686018427387847;  // a 62-bit prime

// F4's minimal basis of `generators` modulo the arithmetic's prime (not interreduced).
std::vector<ModPolynomial> f4_basis(const std::vector<Polynomial>& generators, const ModularArithmetic& arithmetic) {
  std::vector<ModPolynomial> reduced;
  for (const auto& g : generators) reduced.push_back(arithmetic.reduce_coefficients(to_int_polynomial(g)));
  BuchbergerStats stats;
  return run_f4(*generators.front().ring(), arithmetic, std::move(reduced), BuchbergerParams{}, stats).basis;
}

void expect_same(const std::vector<ModPolynomial>& a, const std::vector<ModPolynomial>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].coefficients, b[i].coefficients) << "element " << i;
    EXPECT_EQ(a[i].monomials, b[i].monomials) << "element " << i;
  }
}

TEST(F4InterreduceTest, APlanRecordedOnOnePrimeReducesAnother) {
  // Katsura in 7 variables: its interreduction needs multiples besides the elements.
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3", "u4", "u5", "u6"});
  const std::vector<Polynomial> generators = testing::katsura(ring);
  const ModularArithmetic first(*ring, kFirstPrime), second(*ring, kSecondPrime);
  InterreductionPlan plan;
  const std::vector<ModPolynomial> learned =
      reduce_basis_by_matrix(*ring, first, f4_basis(generators, first), Budget(), nullptr, &plan);
  ASSERT_FALSE(plan.empty());
  EXPECT_GT(plan.rows(), learned.size());
  expect_same(learned, first.reduce_basis(f4_basis(generators, first), Budget()));

  const std::vector<ModPolynomial> basis = f4_basis(generators, second);
  ASSERT_TRUE(plan.fits(second.minimal_basis(basis)));
  expect_same(reduce_basis_by_matrix(*ring, second, basis, Budget(), &plan), second.reduce_basis(basis, Budget()));
}

TEST(F4InterreduceTest, ABasisWithOtherSupportsIsReducedInFull) {
  const RingPtr ring = Ring::make({"a", "b", "c", "d", "e"});
  const ModularArithmetic arithmetic(*ring, kFirstPrime);
  InterreductionPlan plan;
  reduce_basis_by_matrix(*ring, arithmetic, f4_basis(testing::katsura(ring), arithmetic), Budget(), nullptr, &plan);
  const std::vector<ModPolynomial> other = f4_basis(testing::cyclic(ring), arithmetic);
  EXPECT_FALSE(plan.fits(arithmetic.minimal_basis(other)));
  expect_same(reduce_basis_by_matrix(*ring, arithmetic, other, Budget(), &plan),
              arithmetic.reduce_basis(other, Budget()));
}

}  // namespace
}  // namespace implicitizer::detail
