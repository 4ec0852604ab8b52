// Tests of lib/src/modular/crt_lift.cpp: integers and rationals lifted from their
// images modulo primes come back exactly, the margin holds a value back until the
// modulus has the bits to spare, a shared denominator lifts a normalized vector from
// fewer primes, and a value that a later prime refutes is replaced. The images are
// computed here with GMP (n · d⁻¹ mod p), independently of FLINT's reconstruction.

#include "implicitizer/modular/crt_lift.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "implicitizer/modular/prime_sequence.hpp"

namespace implicitizer {
namespace {

// n/d modulo p, d invertible modulo p.
mp_limb_t image_of(const mpq_class& q, mp_limb_t p) {
  const mpz_class modulus(static_cast<unsigned long>(p));
  mpz_class inverse;
  if (mpz_invert(inverse.get_mpz_t(), q.get_den_mpz_t(), modulus.get_mpz_t()) == 0) {
    throw std::logic_error("test: the denominator vanishes modulo p");
  }
  mpz_class r = q.get_num() * inverse;
  mpz_fdiv_r(r.get_mpz_t(), r.get_mpz_t(), modulus.get_mpz_t());
  return r.get_ui();
}

std::vector<mp_limb_t> images_of(const std::vector<mpq_class>& values, mp_limb_t p) {
  std::vector<mp_limb_t> out;
  for (const auto& v : values) out.push_back(image_of(v, p));
  return out;
}

// n/d in lowest terms.
mpq_class fraction(const char* n, const char* d) {
  mpq_class q{mpz_class(n), mpz_class(d)};
  q.canonicalize();
  return q;
}

// The lift's values as rationals: integer_values()[i] / common_denominator().
std::vector<mpq_class> values_of(const CrtLift& lift) {
  const Integer l = lift.common_denominator();
  std::vector<mpq_class> out;
  for (const Integer& v : lift.integer_values()) {
    mpq_class q(v, l);
    q.canonicalize();
    out.push_back(q);
  }
  return out;
}

TEST(CrtLift, IntegersComeBackInTheSymmetricRangeAndThenStopChanging) {
  const std::vector<mpq_class> values = {mpq_class(0), mpq_class(-1), mpq_class("123456789012345678901234567890"),
                                         mpq_class("-98765432109876543210987654321")};
  CrtLift lift(values.size());
  PrimeSequence primes;
  // 97 bits need two 62-bit primes; the third changes nothing.
  mp_limb_t p = primes.next();
  EXPECT_TRUE(lift.add(images_of(values, p), p));
  p = primes.next();
  EXPECT_TRUE(lift.add(images_of(values, p), p));
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(lift.integer(i), values[i].get_num()) << i;
  p = primes.next();
  EXPECT_FALSE(lift.add(images_of(values, p), p));
  EXPECT_EQ(lift.primes(), 3u);
  EXPECT_GT(lift.modulus_bits(), 62u * 3);
}

TEST(CrtLift, RationalsComeBackUnderWangsBound) {
  const std::vector<mpq_class> values = {mpq_class(-3, 7), mpq_class(22), mpq_class(0), mpq_class("123456789/1000003"),
                                         mpq_class("-1/4294967311")};
  CrtLift lift(values.size());
  PrimeSequence primes;
  for (int i = 0; i < 2; ++i) {
    const mp_limb_t p = primes.next();
    lift.add(images_of(values, p), p);
  }
  ASSERT_TRUE(lift.reconstruct());
  EXPECT_EQ(values_of(lift), values);
  EXPECT_EQ(lift.common_denominator(), mpz_class(7) * 1000003 * mpz_class("4294967311"));
}

TEST(CrtLift, NoValueWhileTheModulusIsTooSmall) {
  // |n| and d of 2^40 need M > 2^101 with 20 bits to spare: one 62-bit prime cannot
  // give the value, two can. (Without a margin one prime would give some wrong
  // rational more often than not; the next test but one shows it refuted.)
  const mpq_class big(mpz_class(1) << 40, mpz_class("1099511627689"));  // 2^40 / (a prime below 2^40)
  const std::vector<mpq_class> values = {mpq_class(1), big};
  CrtLift lift(values.size(), CrtLiftParams{.margin_bits = 20});
  PrimeSequence primes;
  mp_limb_t p = primes.next();
  lift.add(images_of(values, p), p);
  EXPECT_FALSE(lift.reconstruct());
  p = primes.next();
  lift.add(images_of(values, p), p);
  ASSERT_TRUE(lift.reconstruct());
  EXPECT_EQ(values_of(lift), values);
}

TEST(CrtLift, TheMarginHoldsAValueBackThatWangsBoundWouldTake) {
  // n, d near 2^55: under √(M/2) ≈ 2^61 for M of two 62-bit primes, but not under
  // √(M/2^21) ≈ 2^51.5; a third prime gives the 20 bits to spare.
  const mpq_class value = fraction("36028797018963971", "36028797018963913");
  const std::vector<mpq_class> values = {value};
  CrtLift wang(1);
  CrtLift margin(1, CrtLiftParams{.margin_bits = 20});
  PrimeSequence primes;
  for (int i = 0; i < 2; ++i) {
    const mp_limb_t p = primes.next();
    wang.add(images_of(values, p), p);
    margin.add(images_of(values, p), p);
  }
  ASSERT_TRUE(wang.reconstruct());
  EXPECT_EQ(values_of(wang), values);
  EXPECT_FALSE(margin.reconstruct());
  const mp_limb_t p = primes.next();
  margin.add(images_of(values, p), p);
  ASSERT_TRUE(margin.reconstruct());
  EXPECT_EQ(values_of(margin), values);
}

TEST(CrtLift, ASharedDenominatorLiftsANormalizedVectorFromOnePrime) {
  // A kernel vector divided by its leading entry 2209: 1, 1/2209 and 2^28/2209. The
  // balanced bound of one 62-bit prime with 20 bits to spare is about 2^20.5, too
  // small for 2^28/2209; the trial denominator 2209 from the second entry makes
  // 2^28 small enough.
  const std::vector<mpq_class> values = {mpq_class(1), mpq_class(1, 2209), mpq_class(268435457, 2209)};
  CrtLift shared(values.size(), CrtLiftParams{.margin_bits = 20, .shared_denominator = true});
  CrtLift balanced(values.size(), CrtLiftParams{.margin_bits = 20});
  PrimeSequence primes;
  const mp_limb_t p = primes.next();
  shared.add(images_of(values, p), p);
  balanced.add(images_of(values, p), p);
  EXPECT_FALSE(balanced.reconstruct());
  ASSERT_TRUE(shared.reconstruct());
  EXPECT_EQ(values_of(shared), values);
  EXPECT_EQ(shared.integer_values(), (std::vector<Integer>{2209, 1, 268435457}));
}

TEST(CrtLift, AValueThatALaterPrimeRefutesIsReconstructedAgain) {
  // Without a margin a residue that is not yet the image of its value can look like
  // a small rational: the integer X ≡ 1/3 modulo the first prime p reconstructs to
  // 1/3 from p alone; the second prime refutes 1/3 and X (about p/3, below Wang's
  // bound for two primes) follows.
  PrimeSequence primes;
  const mp_limb_t p = primes.next();
  const mpz_class first(static_cast<unsigned long>(p));
  const mpz_class x = first % 3 == 2 ? mpz_class((first + 1) / 3) : mpz_class((2 * first + 1) / 3);
  const std::vector<mpq_class> values = {mpq_class(x)};
  CrtLift lift(1);
  lift.add(images_of(values, p), p);
  ASSERT_TRUE(lift.reconstruct());
  EXPECT_EQ(values_of(lift), (std::vector<mpq_class>{mpq_class(1, 3)}));
  const mp_limb_t q = primes.next();
  lift.add(images_of(values, q), q);
  ASSERT_TRUE(lift.reconstruct());
  EXPECT_EQ(values_of(lift), values);
}

TEST(CrtLift, AConfirmedValueStandsForTheIntegerUntilAPrimeRefutesIt) {
  // X ≡ 1/3 modulo p·q, X an integer of about p·q/3: p alone reconstructs 1/3, q
  // confirms it, and while it stands the integer is computed from it; the third
  // prime r refutes it, and the integer of the three primes is X again.
  PrimeSequence primes;
  const mp_limb_t p = primes.next(), q = primes.next(), r = primes.next();
  const mpz_class pq = mpz_class(static_cast<unsigned long>(p)) * static_cast<unsigned long>(q);
  const mpz_class x = pq % 3 == 2 ? mpz_class((pq + 1) / 3) : mpz_class((2 * pq + 1) / 3);
  const std::vector<mpq_class> values = {mpq_class(x), mpq_class(-7)};
  CrtLift lift(values.size());
  lift.add(images_of(values, p), p);
  ASSERT_TRUE(lift.reconstruct());
  EXPECT_EQ(values_of(lift), (std::vector<mpq_class>{mpq_class(1, 3), mpq_class(-7)}));
  EXPECT_TRUE(lift.add(images_of(values, q), q));  // 1/3 is not an integer
  EXPECT_EQ(lift.integer(0), x);
  EXPECT_EQ(lift.integer(1), -7);
  // r refutes 1/3: the integer brought back from it is X, which r does not change.
  EXPECT_FALSE(lift.add(images_of(values, r), r));
  EXPECT_EQ(lift.integer(0), x);
  EXPECT_EQ(lift.integer(1), -7);
  EXPECT_FALSE(lift.reconstruct());  // X has 122 bits, past Wang's bound for three primes
  // -7 stood for its integer through q and r; a fourth prime changes nothing of it.
  const mp_limb_t s = primes.next();
  const std::vector<mpq_class> settled = {mpq_class(-7)};
  CrtLift integral(1);
  integral.add(images_of(settled, p), p);
  ASSERT_TRUE(integral.reconstruct());
  integral.add(images_of(settled, q), q);
  EXPECT_FALSE(integral.add(images_of(settled, s), s));
  EXPECT_EQ(integral.integer(0), -7);
}

TEST(CrtLift, SpreadInsertsEntriesThatAreZeroModuloEveryPrimeSoFar) {
  const std::vector<mpq_class> before = {mpq_class(5, 3), mpq_class(-7)};
  // After the spread: a new entry first, the old ones at 1 and 3, a new one at 2.
  const std::vector<mpq_class> after = {mpq_class(0), mpq_class(5, 3), mpq_class(0), mpq_class(-7)};
  CrtLift lift(before.size());
  PrimeSequence primes;
  mp_limb_t p = primes.next();
  lift.add(images_of(before, p), p);
  ASSERT_TRUE(lift.reconstruct());
  const std::vector<std::size_t> positions = {1, 3};
  lift.spread(positions, 4);
  EXPECT_EQ(lift.size(), 4u);
  EXPECT_EQ(lift.integer(0), 0);
  p = primes.next();
  lift.add(images_of(after, p), p);
  ASSERT_TRUE(lift.reconstruct());
  EXPECT_EQ(values_of(lift), after);
}

TEST(CrtLift, RejectsMisuse) {
  EXPECT_THROW(CrtLift(1, CrtLiftParams{.margin_bits = 0, .shared_denominator = true}), std::invalid_argument);
  CrtLift lift(2);
  const std::vector<mp_limb_t> one = {1};
  EXPECT_THROW(lift.add(one, 101), std::invalid_argument);
  const std::vector<mp_limb_t> two = {1, 2};
  EXPECT_THROW(lift.add(two, (mp_limb_t{1} << 63) + 29), std::invalid_argument);  // a prime past 2^63
  const std::vector<std::size_t> decreasing = {1, 0};
  EXPECT_THROW(lift.spread(decreasing, 3), std::invalid_argument);
}

}  // namespace
}  // namespace implicitizer
