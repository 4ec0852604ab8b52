// Tests of Ring (lib/src/polynomial/ring.cpp): construction errors and the monomial
// arithmetic on packed [key | exponents] arrays.

#include "implicitizer/polynomial/ring.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

using Exponents = std::vector<std::int32_t>;
using testing::throws_input_error;

class RingTest : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"x", "y", "z"});

  std::vector<std::int32_t> encode(const Exponents& e) const {
    std::vector<std::int32_t> m(ring_->monomial_size());
    ring_->encode(e.data(), m.data());
    return m;
  }
  Exponents exponents_of(const std::vector<std::int32_t>& m) const {
    const std::int32_t* e = ring_->exponents(m.data());
    return Exponents(e, e + ring_->num_variables());
  }
};

TEST(RingMake, RejectsBadVariableLists) {
  EXPECT_TRUE(throws_input_error([] { Ring::make({"x", "y", "x"}); }, "invalid_variables"));
  EXPECT_TRUE(throws_input_error([] { Ring::make({"x", ""}); }, "invalid_variables"));
  EXPECT_TRUE(throws_input_error(
      [] {
        Ring::make({"x", "y"}, MonomialOrder::weighted({1}, MonomialOrder::lex()));
      },
      "invalid_order"));
  EXPECT_TRUE(throws_input_error(
      [] { Ring::make({"x"}, MonomialOrder::block(2, MonomialOrder::lex(), MonomialOrder::lex())); }, "invalid_order"));
}

TEST(RingMake, EmptyRingHasOnlyConstants) {
  const RingPtr ring = Ring::make({});
  EXPECT_EQ(ring->num_variables(), 0u);
  EXPECT_EQ(ring->monomial_size(), 0u);
}

TEST_F(RingTest, VariablesAndIndices) {
  EXPECT_EQ(ring_->variables(), (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(ring_->index_of("y"), std::optional<std::size_t>(1));
  EXPECT_FALSE(ring_->index_of("w").has_value());
  EXPECT_FALSE(ring_->index_of("X").has_value());
  EXPECT_EQ(ring_->order(), MonomialOrder::grevlex());
  EXPECT_EQ(ring_->monomial_size(), ring_->key_size() + 3);
}

TEST_F(RingTest, EncodeKeepsExponentsAndDegree) {
  const auto m = encode({2, 0, 5});
  EXPECT_EQ(exponents_of(m), (Exponents{2, 0, 5}));
  EXPECT_EQ(ring_->total_degree(m.data()), 7);
}

TEST_F(RingTest, MultiplyDivideLcmCoprime) {
  const auto a = encode({2, 1, 0}), b = encode({0, 3, 1});
  std::vector<std::int32_t> out(ring_->monomial_size());

  ring_->multiply(a.data(), b.data(), out.data());
  EXPECT_EQ(out, encode({2, 4, 1}));  // keys add too, since they are linear

  EXPECT_TRUE(ring_->divides(a.data(), out.data()));
  EXPECT_FALSE(ring_->divides(out.data(), a.data()));
  EXPECT_FALSE(ring_->divides(a.data(), b.data()));
  ring_->divide(out.data(), a.data(), out.data());
  EXPECT_EQ(out, b);

  ring_->lcm(a.data(), b.data(), out.data());
  EXPECT_EQ(out, encode({2, 3, 1}));

  EXPECT_FALSE(ring_->coprime(a.data(), b.data()));  // both contain y
  EXPECT_TRUE(ring_->coprime(encode({2, 0, 0}).data(), encode({0, 3, 1}).data()));
  EXPECT_TRUE(ring_->equal(a.data(), encode({2, 1, 0}).data()));
}

TEST(RingProperties, DivisorMaskIsANecessaryCondition) {
  testing::RandomSource random(99);
  for (std::size_t n : {1u, 3u, 7u, 70u}) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < n; ++i) names.push_back("v" + std::to_string(i));
    const RingPtr ring = Ring::make(names);
    const std::size_t w = ring->monomial_size();
    std::size_t divisible = 0;
    for (int i = 0; i < 3000; ++i) {
      const Exponents a = random.exponents(n, 3);
      Exponents b = random.exponents(n, 2);
      if (random.uniform(0, 1)) {
        for (std::size_t k = 0; k < n; ++k) b[k] += a[k];  // make a divide b half of the time
      }
      std::vector<std::int32_t> ma(w), mb(w);
      ring->encode(a.data(), ma.data());
      ring->encode(b.data(), mb.data());
      bool divides = true;
      for (std::size_t k = 0; k < n; ++k) divides = divides && a[k] <= b[k];
      ASSERT_EQ(ring->divides(ma.data(), mb.data()), divides);
      if (divides) {
        ++divisible;
        ASSERT_EQ(ring->divisor_mask(ma.data()) & ~ring->divisor_mask(mb.data()), 0u);
      }
    }
    EXPECT_GT(divisible, 1000u);
  }
}

TEST(RingProperties, LcmIsTheLeastCommonMultiple) {
  const RingPtr ring = Ring::make({"a", "b", "c", "d"}, MonomialOrder::lex());
  testing::RandomSource random(5);
  const std::size_t w = ring->monomial_size();
  for (int i = 0; i < 500; ++i) {
    const Exponents a = random.exponents(4, 4), b = random.exponents(4, 4);
    std::vector<std::int32_t> ma(w), mb(w), l(w), ab(w);
    ring->encode(a.data(), ma.data());
    ring->encode(b.data(), mb.data());
    ring->lcm(ma.data(), mb.data(), l.data());
    EXPECT_TRUE(ring->divides(ma.data(), l.data()));
    EXPECT_TRUE(ring->divides(mb.data(), l.data()));
    ring->multiply(ma.data(), mb.data(), ab.data());
    EXPECT_TRUE(ring->divides(l.data(), ab.data()));
    EXPECT_EQ(ring->coprime(ma.data(), mb.data()), ring->equal(l.data(), ab.data()));
  }
}

TEST(RingEquality, SameVariablesAndOrder) {
  EXPECT_TRUE(*Ring::make({"x", "y"}) == *Ring::make({"x", "y"}));
  EXPECT_FALSE(*Ring::make({"x", "y"}) == *Ring::make({"y", "x"}));
  EXPECT_FALSE(*Ring::make({"x", "y"}) == *Ring::make({"x", "y"}, MonomialOrder::lex()));
}

}  // namespace
}  // namespace implicitizer
