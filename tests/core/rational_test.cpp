// Tests of the number conversions (lib/src/core/rational.cpp).

#include "implicitizer/core/rational.hpp"

#include <gtest/gtest.h>

namespace implicitizer {
namespace {

TEST(Rational, RoundTripsThroughGmp) {
  const mpq_class q("-123456789012345678901234567890/98765432109876543210987654321");
  EXPECT_EQ(to_mpq(to_rational(q)), q);
  EXPECT_EQ(to_rational(Integer("123456789012345678901234567890")),
            to_rational(mpq_class("123456789012345678901234567890")));
}

TEST(Rational, PrintsInLowestTermsWithTheSignOnTheNumerator) {
  EXPECT_EQ(to_string(Rational(6, -4)), "-3/2");
  EXPECT_EQ(to_string(Rational(4, 2)), "2");
  EXPECT_EQ(to_string(Rational(0, 5)), "0");
  EXPECT_EQ(to_string(to_rational(mpq_class(1, mpz_class("100000000000000000000000000000")))),
            "1/100000000000000000000000000000");
}

}  // namespace
}  // namespace implicitizer
