// LimbRow (lib/src/groebner/limb_row.hpp) against GMP's mpz arithmetic: random
// products of every size class added into entries of both signs, scalings, widening
// with entries of both signs, and the measured sizes.
#include "limb_row.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <random>
#include <vector>

namespace implicitizer::detail {
namespace {

// A random integer of 1..max_bits bits and random sign.
mpz_class random_integer(gmp_randclass& random, std::mt19937_64& engine, std::size_t max_bits) {
  const std::size_t bits = 1 + engine() % max_bits;
  mpz_class x = random.get_z_bits(bits);
  if (x == 0) x = 1;
  if (engine() % 2 == 0) x = -x;
  return x;
}

mpz_class entry(const LimbRow& row, std::size_t c) {
  mpz_class out;
  row.get(c, out.get_mpz_t());
  return out;
}

std::size_t bits_of(const mpz_class& x) { return x == 0 ? 0 : mpz_sizeinbase(x.get_mpz_t(), 2); }

// Runs random updates on `columns` entries, the row widened ahead of each as the
// reducer does, and compares every entry with the same updates on mpz.
void check_random_updates(std::size_t max_factor_bits, std::size_t max_coefficient_bits, std::uint64_t seed) {
  constexpr std::size_t kColumns = 16;
  std::mt19937_64 engine(seed);
  gmp_randclass random(gmp_randinit_default);
  random.seed(seed);
  LimbRow row;
  row.reserve_columns(kColumns);
  std::vector<mpz_class> expected(kColumns);
  for (int step = 0; step < 400; ++step) {
    const std::size_t c = engine() % kColumns;
    const mpz_class f = random_integer(random, engine, max_factor_bits);
    if (engine() % 5 == 0) {
      const mpz_class s = abs(f);
      row.ensure_bits(bits_of(expected[c]) + bits_of(s));
      expected[c] *= s;
      if (row.written(c)) row.multiply(c, s.get_mpz_t());
    } else {
      const mpz_class m = random_integer(random, engine, max_coefficient_bits);
      const mpz_class sum = expected[c] + f * m;
      row.ensure_bits(std::max(bits_of(expected[c]), bits_of(f) + bits_of(m)) + 1);
      row.add_product(c, f.get_mpz_t(), m.get_mpz_t());
      expected[c] = sum;
    }
    ASSERT_EQ(entry(row, c), expected[c]) << "step " << step << ", column " << c;
    if (engine() % 7 == 0) {
      row.clear(c);
      expected[c] = 0;
      EXPECT_TRUE(row.is_zero(c));
    }
  }
  std::size_t most = 0;
  for (std::size_t c = 0; c < kColumns; ++c) {
    EXPECT_EQ(entry(row, c), expected[c]) << "column " << c;
    EXPECT_EQ(row.is_zero(c), expected[c] == 0) << "column " << c;
    most = std::max(most, bits_of(expected[c]));
  }
  EXPECT_EQ(row.max_bits(0, kColumns - 1), most);
}

TEST(LimbRowTest, OneLimbCoefficientsMatchMpz) { check_random_updates(400, 64, 1); }

TEST(LimbRowTest, FewLimbCoefficientsMatchMpz) { check_random_updates(400, 256, 2); }

TEST(LimbRowTest, LongProductsMatchMpz) { check_random_updates(3000, 1500, 3); }

// add_multiple, the proof's update (one factor times a packed polynomial's
// coefficients, by column), against mpz: coefficients of one limb (its fast path)
// and of several, of both signs.
TEST(LimbRowTest, AddMultipleMatchesMpz) {
  constexpr std::size_t kColumns = 40;
  std::mt19937_64 engine(7);
  gmp_randclass random(gmp_randinit_default);
  random.seed(7);
  std::vector<IntPolynomial> polynomials(3);
  for (IntPolynomial& p : polynomials) {
    for (int t = 0; t < 12; ++t) {
      const std::size_t bits = t % 3 == 0 ? 200 : 64;
      p.coefficients.push_back(random_integer(random, engine, bits));
    }
  }
  const PackedCoefficients packed(polynomials);
  LimbRow row;
  row.reserve_columns(kColumns);
  std::vector<mpz_class> expected(kColumns);
  for (int step = 0; step < 300; ++step) {
    const std::size_t i = engine() % polynomials.size();
    const mpz_class f = random_integer(random, engine, 400);
    std::vector<std::uint32_t> columns;
    for (std::size_t t = 0; t < polynomials[i].size(); ++t) {
      columns.push_back(static_cast<std::uint32_t>((engine() % 3) + 3 * t));
    }
    const std::size_t from = engine() % 2;
    std::size_t most = 0;
    for (std::size_t t = from; t < columns.size(); ++t) {
      expected[columns[t]] += f * polynomials[i].coefficients[t];
      most = std::max(most, bits_of(expected[columns[t]]));
    }
    row.ensure_bits(std::max<std::size_t>(most, bits_of(f) + 200) + 2);
    row.add_multiple(columns.data(), columns.size(), from, f.get_mpz_t(), packed, i);
    for (std::size_t c = 0; c < kColumns; ++c)
      ASSERT_EQ(entry(row, c), expected[c]) << "step " << step << ", column " << c;
  }
}

TEST(LimbRowTest, WideningKeepsSignsAndValues) {
  LimbRow row;
  row.reserve_columns(3);
  const mpz_class minus = -(mpz_class(1) << 60) + 12345;
  const mpz_class plus = (mpz_class(1) << 62) - 1;
  row.set(0, minus.get_mpz_t());
  row.set(2, plus.get_mpz_t());
  EXPECT_EQ(row.capacity_bits(), 63u);
  row.ensure_bits(500);
  EXPECT_GE(row.capacity_bits(), 500u);
  EXPECT_EQ(entry(row, 0), minus);
  EXPECT_EQ(entry(row, 1), 0);
  EXPECT_EQ(entry(row, 2), plus);
  EXPECT_TRUE(row.is_zero(1));
  // Columns added later start at zero, and the old ones keep their values.
  row.reserve_columns(5);
  EXPECT_TRUE(row.is_zero(4));
  EXPECT_EQ(entry(row, 0), minus);
  EXPECT_EQ(row.max_bits(0, 4), 62u);
}

// A row cleared to zero can take any width, narrower too, and computes as before.
TEST(LimbRowTest, AZeroRowChangesWidthFreely) {
  LimbRow row;
  row.reserve_columns(4);
  row.ensure_bits(2000);
  const mpz_class big = -(mpz_class(3) << 1900);
  row.set(1, big.get_mpz_t());
  row.set(3, big.get_mpz_t());
  EXPECT_EQ(entry(row, 3), big);
  row.clear(1);
  row.clear(3);
  row.reset_width(60);
  EXPECT_LT(row.capacity_bits(), 200u);
  for (std::size_t c = 0; c < 4; ++c) EXPECT_TRUE(row.is_zero(c)) << "column " << c;
  const mpz_class f = -12345, m = 678;
  row.add_product(2, f.get_mpz_t(), m.get_mpz_t());
  EXPECT_EQ(entry(row, 2), f * m);
  EXPECT_TRUE(row.is_zero(1));
  EXPECT_TRUE(row.is_zero(3));
}

TEST(LimbRowTest, CancellationToZeroIsSeen) {
  LimbRow row;
  row.reserve_columns(1);
  row.ensure_bits(200);
  const mpz_class f("123456789012345678901234567890");
  const mpz_class m("-98765432109876543210");
  row.add_product(0, f.get_mpz_t(), m.get_mpz_t());
  EXPECT_FALSE(row.is_zero(0));
  const mpz_class minus_f = -f;
  row.add_product(0, minus_f.get_mpz_t(), m.get_mpz_t());
  EXPECT_TRUE(row.written(0));
  EXPECT_TRUE(row.is_zero(0));
  EXPECT_EQ(row.max_bits(0, 0), 0u);
}

}  // namespace
}  // namespace implicitizer::detail
