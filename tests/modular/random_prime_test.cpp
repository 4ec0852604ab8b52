// Tests of lib/src/modular/random_prime.cpp: every draw is a prime of exactly 62 bits
// (checked with GMP, not with the FLINT test the source uses), draws do not repeat,
// and two sources seeded from the system differ. None of these can fail by chance
// with a probability above 10^-12 (200 draws among 5.4·10^16 primes).

#include "implicitizer/modular/random_prime.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>

namespace implicitizer {
namespace {

TEST(RandomPrimesTest, PrimesOfSixtyTwoBitsThatDoNotRepeat) {
  RandomPrimes source;
  std::set<std::uint64_t> seen;
  std::set<std::uint64_t> residues_mod_4;
  for (int i = 0; i < 200; ++i) {
    const std::uint64_t p = source.next();
    EXPECT_GE(p, std::uint64_t{1} << 61);
    EXPECT_LT(p, std::uint64_t{1} << 62);
    const mpz_class z(std::to_string(p));
    EXPECT_GT(mpz_probab_prime_p(z.get_mpz_t(), 40), 0) << p;
    EXPECT_TRUE(seen.insert(p).second) << p << " drawn twice";
    residues_mod_4.insert(p % 4);
  }
  // Both odd classes occur: all 200 in one would have probability 2^-199.
  EXPECT_EQ(residues_mod_4.size(), 2u);
}

TEST(RandomPrimesTest, TwoSourcesDrawDifferentPrimes) {
  RandomPrimes a, b;
  EXPECT_NE(a.next(), b.next());
}

}  // namespace
}  // namespace implicitizer
