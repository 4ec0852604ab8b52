// Tests of lib/src/groebner/f4*.cpp: F4 modulo a prime gives the same reduced basis as
// the Buchberger engine modulo that prime on the property sweep's random ideals under
// every order and selection setting, for primes below 2^31 (delayed reduction), above
// 2^62 (FLINT's multiplication) and tiny ones (many coefficients vanish); its output
// is a reduced Gröbner basis; Katsura and Cyclic agree; the multi-modular route with
// F4 equals the rational basis and proves it; budgets stop F4 with the limit named.

#include "implicitizer/groebner/f4.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "groebner/groebner_support.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/groebner/modular_groebner.hpp"

namespace implicitizer {
namespace {

using testing::print_all;

// A prime below 2^31 (the delayed path), one above 2^62 (nmod on every product), and
// small ones under which the random ideals' coefficients often vanish.
constexpr std::uint64_t kSmallWordPrime = 2147483629;              // 2^31 − 19
constexpr std::uint64_t kLargeWordPrime = 4611686018427388039ULL;  // the first prime above 2^62
constexpr std::uint64_t kTinyPrimes[] = {2, 3, 7, 32003};

std::vector<Polynomial> modulo(const std::vector<Polynomial>& generators, std::uint64_t prime,
                               ModularAlgorithm algorithm, BuchbergerParams params = BuchbergerParams()) {
  params.budget.set_timeout(60);
  return compute_groebner_basis_modulo(generators, prime, algorithm, params);
}

// The F4 basis is what Buchberger's engine finds, and is a reduced Gröbner basis: it
// is reduced, and the Buchberger engine run on it returns it unchanged (a reduced
// basis is the reduced Gröbner basis of its own ideal exactly when it is one).
void expect_same_as_buchberger(const std::vector<Polynomial>& generators, std::uint64_t prime,
                               const BuchbergerParams& params = BuchbergerParams()) {
  SCOPED_TRACE("prime " + std::to_string(prime));
  const std::vector<Polynomial> f4 = modulo(generators, prime, ModularAlgorithm::f4, params);
  const std::vector<Polynomial> buchberger = modulo(generators, prime, ModularAlgorithm::buchberger, params);
  EXPECT_EQ(print_all(f4), print_all(buchberger));
  EXPECT_TRUE(is_reduced(f4));
  EXPECT_EQ(print_all(modulo(f4, prime, ModularAlgorithm::buchberger)), print_all(f4));
}

class F4PropertyTest : public ::testing::TestWithParam<testing::NamedOrder> {};

TEST_P(F4PropertyTest, SameReducedBasisAsBuchbergerModuloEveryPrime) {
  const RingPtr ring = Ring::make({"x", "y", "z"}, GetParam().order);
  for (const auto& generators : testing::random_ideals(ring, 30)) {
    SCOPED_TRACE("ideal " + ::testing::PrintToString(print_all(generators)));
    for (std::uint64_t prime : {kSmallWordPrime, kLargeWordPrime}) expect_same_as_buchberger(generators, prime);
    for (std::uint64_t prime : kTinyPrimes) expect_same_as_buchberger(generators, prime);
  }
}

// Every selection strategy and criterion setting of the sweep gives the same basis.
TEST_P(F4PropertyTest, EverySettingGivesTheSameBasis) {
  const RingPtr ring = Ring::make({"x", "y", "z"}, GetParam().order);
  for (const auto& generators : testing::random_ideals(ring, 10)) {
    SCOPED_TRACE("ideal " + ::testing::PrintToString(print_all(generators)));
    const auto reference = print_all(modulo(generators, kSmallWordPrime, ModularAlgorithm::buchberger));
    for (const BuchbergerParams& params : testing::all_settings()) {
      EXPECT_EQ(print_all(modulo(generators, kSmallWordPrime, ModularAlgorithm::f4, params)), reference);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Orders, F4PropertyTest, ::testing::ValuesIn(testing::property_orders()),
                         [](const ::testing::TestParamInfo<testing::NamedOrder>& order) { return order.param.name; });

TEST(F4Test, KatsuraAndCyclicAgreeWithBuchbergerModuloP) {
  for (const MonomialOrder& order : {MonomialOrder::grevlex(), MonomialOrder::grlex(), MonomialOrder::lex()}) {
    const RingPtr k = Ring::make({"u0", "u1", "u2", "u3", "u4"}, order);
    const RingPtr c = Ring::make({"a", "b", "c", "d"}, order);
    for (const auto& generators : {testing::katsura(k), testing::cyclic(c)}) {
      expect_same_as_buchberger(generators, kSmallWordPrime);
    }
  }
  const RingPtr c5 = Ring::make({"a", "b", "c", "d", "e"});
  expect_same_as_buchberger(testing::cyclic(c5), kSmallWordPrime);
}

TEST(F4Test, UnitAndZeroIdeals) {
  const RingPtr ring = Ring::make({"x", "y"});
  const auto unit = testing::parse_all({"x*y-1", "x"}, ring);
  EXPECT_EQ(print_all(modulo(unit, kSmallWordPrime, ModularAlgorithm::f4)), std::vector<std::string>{"1"});
  // A term whose coefficient p divides vanishes; the content of 6x + 3y (3) is dropped
  // first, leaving 2x + y, which is x + 2y modulo 3, not 0.
  EXPECT_EQ(print_all(modulo(testing::parse_all({"6*x+3*y"}, ring), 3, ModularAlgorithm::f4)),
            std::vector<std::string>{"x+2*y"});
  const auto vanishing = testing::parse_all({"3*x+y"}, ring);
  EXPECT_EQ(print_all(modulo(vanishing, 3, ModularAlgorithm::f4)), std::vector<std::string>{"y"});
  EXPECT_TRUE(modulo({}, kSmallWordPrime, ModularAlgorithm::f4).empty());
}

// The multi-modular route with F4 modulo each prime, on one thread (so that which
// primes run, and the counters asserted, never depend on the machine's load).
ModularGroebnerParams f4_route(std::uint64_t first_prime = 0) {
  ModularGroebnerParams params;
  params.algorithm = ModularAlgorithm::f4;
  params.first_prime = first_prime;
  params.threads = 1;
  params.buchberger.budget.set_timeout(60);
  return params;
}

// The multi-modular route with F4 for each prime: the proven basis over ℚ is the
// rational one, under every order (homogenized generators included).
TEST(F4Test, ModularRouteWithF4EqualsTheRationalBasis) {
  for (const auto& named : testing::property_orders()) {
    const RingPtr ring = Ring::make({"x", "y", "z"}, named.order);
    for (const auto& generators : testing::random_ideals(ring, 15)) {
      SCOPED_TRACE(std::string(named.name) + " ideal " + ::testing::PrintToString(print_all(generators)));
      const std::optional<GroebnerResult> rational = testing::compute_bounded(generators);
      ASSERT_TRUE(rational);
      const ModularGroebnerParams params = f4_route();
      ModularGroebnerStats stats;
      EXPECT_EQ(print_all(compute_groebner_basis_modular(generators, params, &stats).basis),
                print_all(rational->basis));
      EXPECT_TRUE(stats.proven);
    }
  }
}

// Small primes force unlucky ones: the route still lifts and proves the right basis.
TEST(F4Test, ModularRouteWithF4SurvivesUnluckyPrimes) {
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3"});
  const auto generators = testing::katsura(ring);
  const ModularGroebnerParams params = f4_route(/*first_prime=*/3);
  ModularGroebnerStats stats;
  EXPECT_EQ(print_all(compute_groebner_basis_modular(generators, params, &stats).basis),
            print_all(compute_groebner_basis(generators).basis));
  EXPECT_TRUE(stats.proven);
  EXPECT_GT(stats.unlucky_primes + stats.bad_primes, 0u);
}

// The first prime's F4 run replayed on the others (f4_trace.hpp): the proven basis is
// the same with the trace and without, and on ideals that need several primes the
// replays happen (a candidate is only ever checked on primes run in full).
TEST(F4Test, ReplayedPrimesGiveTheBasisFullRunsGive) {
  std::vector<std::vector<Polynomial>> ideals;
  const RingPtr xyz = Ring::make({"x", "y", "z"}, MonomialOrder::grevlex());
  for (auto& generators : testing::random_ideals(xyz, 10)) ideals.push_back(std::move(generators));
  const std::string big = "123456789012345678901234567890123456789012345678901234567890123456789012345";
  ideals.push_back(testing::parse_all({"x^2-" + big + "/7*y", "x*y-" + big + "*" + big + "/11*z", "z^3-x"}, xyz));
  const RingPtr u = Ring::make({"u0", "u1", "u2", "u3", "u4"});
  ideals.push_back(testing::katsura(u));
  std::size_t replayed = 0;
  for (const auto& generators : ideals) {
    SCOPED_TRACE(::testing::PrintToString(print_all(generators)));
    ModularGroebnerParams params = f4_route();
    ModularGroebnerStats traced, full;
    const GroebnerResult with = compute_groebner_basis_modular(generators, params, &traced);
    params.trace = false;
    const GroebnerResult without = compute_groebner_basis_modular(generators, params, &full);
    EXPECT_EQ(print_all(with.basis), print_all(without.basis));
    EXPECT_TRUE(traced.proven);
    EXPECT_FALSE(traced.trace_dropped);
    EXPECT_EQ(traced.replay_failures, 0u);
    EXPECT_EQ(full.replayed_primes, 0u);
    replayed += traced.replayed_primes;
  }
  EXPECT_GT(replayed, 0u);
}

// A trace learned on an unlucky prime: 13 cancels terms of this ideal's basis (1/13
// appears in it), so the basis modulo 13 has other leading monomials, and replays of
// its path would copy them. A prime run in full contradicts it, the trace and every
// lift are dropped, and the route still proves the rational basis.
TEST(F4Test, ATraceLearnedOnAnUnluckyPrimeIsDropped) {
  const RingPtr ring = Ring::make({"x", "y", "z"});
  const auto generators = testing::parse_all({"187*x^2+y", "x*y-13*z^2+1", "y^3-z"}, ring);
  const ModularGroebnerParams params = f4_route(/*first_prime=*/12);
  ModularGroebnerStats stats;
  EXPECT_EQ(print_all(compute_groebner_basis_modular(generators, params, &stats).basis),
            print_all(compute_groebner_basis(generators).basis));
  EXPECT_TRUE(stats.proven);
  EXPECT_TRUE(stats.trace_dropped);
}

// The limit that stopped F4 on `generators`, and where (the exception's message).
std::pair<Limit, std::string> limit_stopping(const std::vector<Polynomial>& generators, const Budget& budget) {
  BuchbergerParams params;
  params.budget = budget;
  try {
    compute_groebner_basis_modulo(generators, kSmallWordPrime, ModularAlgorithm::f4, params);
  } catch (const LimitExceeded& e) {
    return {e.limit(), e.what()};
  }
  ADD_FAILURE() << "F4 was not stopped";
  return {Limit::time, ""};
}

TEST(F4Test, BudgetsStopF4AndNameTheLimit) {
  const RingPtr ring = Ring::make({"a", "b", "c", "d", "e"});
  const auto generators = testing::cyclic(ring);
  Budget terms;
  terms.set_max_terms(20);
  EXPECT_EQ(limit_stopping(generators, terms).first, Limit::size);
  Budget cancelled;
  cancelled.cancel();
  EXPECT_EQ(limit_stopping(generators, cancelled).first, Limit::cancelled);
  Budget expired = Budget::with_timeout(1e-9);
  EXPECT_EQ(limit_stopping(generators, expired).first, Limit::time);
  // Work is charged row by row inside the matrix reduction, so a small allowance
  // stops F4 in the middle of one reduction, and the message says so.
  Budget work;
  work.set_max_work(1000);
  const auto [limit, where] = limit_stopping(generators, work);
  EXPECT_EQ(limit, Limit::work);
  EXPECT_NE(where.find("F4 matrix reduction"), std::string::npos) << where;
}

}  // namespace
}  // namespace implicitizer
