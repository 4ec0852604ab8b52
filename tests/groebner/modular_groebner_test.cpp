// Tests of lib/src/groebner/modular_groebner.cpp (and mod_polynomial.cpp): the
// multi-modular basis equals the rational one on the property sweep's random ideals
// under every order, on Katsura and Cyclic, and on ideals whose coefficients need
// many primes; unlucky and bad primes are detected when small primes are forced; the
// proof rejects what is not a basis; the random checks of the unproven mode refute a
// candidate the sequence's primes confirm; limits stop it.

#include "implicitizer/groebner/modular_groebner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <span>
#include <string>
#include <thread>
#include <utility>

#include "groebner/groebner_support.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/groebner/elimination.hpp"
#include "implicitizer/groebner/f4.hpp"

namespace implicitizer {
namespace {

using testing::parse_all;
using testing::print_all;

GroebnerResult modular(const std::vector<Polynomial>& generators, ModularGroebnerStats* stats = nullptr,
                       std::uint64_t first_prime = 0, bool prove = true) {
  ModularGroebnerParams params;
  params.first_prime = first_prime;
  params.prove = prove;
  // One thread: the batch size then never depends on how long a prime took (and so
  // on the machine's load), and the counters asserted below are the same every run.
  params.threads = 1;
  params.buchberger.budget.set_timeout(60);
  return compute_groebner_basis_modular(generators, params, stats);
}

class ModularGroebnerPropertyTest : public ::testing::TestWithParam<testing::NamedOrder> {};

// The random ideals of the Buchberger sweep: the proven modular basis is the rational
// reduced basis, letter for letter, under every order (homogenized ones included).
TEST_P(ModularGroebnerPropertyTest, EqualsTheRationalBasis) {
  const RingPtr ring = Ring::make({"x", "y", "z"}, GetParam().order);
  std::size_t homogenized = 0;
  for (const auto& generators : testing::random_ideals(ring, 30)) {
    SCOPED_TRACE("ideal " + ::testing::PrintToString(print_all(generators)));
    const std::optional<GroebnerResult> rational = testing::compute_bounded(generators);
    ASSERT_TRUE(rational);
    ModularGroebnerStats stats;
    const GroebnerResult r = modular(generators, &stats);
    EXPECT_EQ(print_all(r.basis), print_all(rational->basis));
    EXPECT_TRUE(stats.proven);
    EXPECT_GE(stats.lifted_primes, 1u);
    if (stats.homogenized) ++homogenized;
  }
  EXPECT_GT(homogenized, 0u) << "the sweep must exercise the homogenized proof";
}

INSTANTIATE_TEST_SUITE_P(Orders, ModularGroebnerPropertyTest, ::testing::ValuesIn(testing::property_orders()),
                         [](const ::testing::TestParamInfo<testing::NamedOrder>& order) { return order.param.name; });

TEST(ModularGroebnerTest, KatsuraAndCyclicAgreeWithBuchberger) {
  for (const MonomialOrder& order : {MonomialOrder::grevlex(), MonomialOrder::lex()}) {
    const RingPtr k = Ring::make({"u0", "u1", "u2", "u3"}, order);
    const RingPtr c = Ring::make({"a", "b", "c", "d"}, order);
    for (const auto& generators : {testing::katsura(k), testing::cyclic(c)}) {
      ModularGroebnerStats stats;
      EXPECT_EQ(print_all(modular(generators, &stats).basis), print_all(compute_groebner_basis(generators).basis));
      EXPECT_TRUE(stats.proven);
    }
  }
}

// Coefficients of 150 digits in the answer need several 62-bit primes, and the
// lifted basis must still be exact.
TEST(ModularGroebnerTest, LargeCoefficientsNeedSeveralPrimes) {
  const RingPtr ring = Ring::make({"x", "y"});
  const std::string big = "123456789012345678901234567890123456789012345678901234567890123456789012345";
  const auto generators = parse_all({"x^2-" + big + "/7*y", "x*y-" + big + "*" + big + "/11"}, ring);
  ModularGroebnerStats stats;
  EXPECT_EQ(print_all(modular(generators, &stats).basis), print_all(compute_groebner_basis(generators).basis));
  EXPECT_GE(stats.lifted_primes, 4u);
  EXPECT_TRUE(stats.proven);
}

// With primes forced to start at 10: 11 and 17 divide the leading coefficient 187 of
// a generator and are skipped as bad; 13 divides no leading coefficient but cancels
// terms of the basis (1/13 appears in it), so the reduced basis modulo 13 has other
// leading monomials: unlucky, outvoted by the primes that agree. The answer is still
// the rational basis, and the candidate lifted before enough primes agreed was
// rejected by the check on the next prime.
TEST(ModularGroebnerTest, SmallPrimesUnluckyAndBadAreDropped) {
  const RingPtr ring = Ring::make({"x", "y", "z"});
  const auto generators = parse_all({"187*x^2+y", "x*y-13*z^2+1", "y^3-z"}, ring);
  ModularGroebnerStats stats;
  const GroebnerResult r = modular(generators, &stats, /*first_prime=*/10);
  EXPECT_EQ(print_all(r.basis), print_all(compute_groebner_basis(generators).basis));
  EXPECT_EQ(stats.bad_primes, 2u);
  EXPECT_EQ(stats.unlucky_primes, 1u);
  EXPECT_EQ(stats.lifted_primes + stats.unlucky_primes + stats.checking_primes, stats.primes);
  EXPECT_TRUE(stats.proven);
}

// A prime that divides a leading coefficient is skipped before any work, even the
// first one tried (101 here).
TEST(ModularGroebnerTest, ABadFirstPrimeIsSkipped) {
  const RingPtr ring = Ring::make({"x", "y"});
  const auto generators = parse_all({"101*x*y+y^2+x", "x^2-y"}, ring);
  ModularGroebnerStats stats;
  const GroebnerResult r = modular(generators, &stats, /*first_prime=*/100);
  EXPECT_EQ(print_all(r.basis), print_all(compute_groebner_basis(generators).basis));
  EXPECT_TRUE(stats.proven);
  EXPECT_EQ(stats.bad_primes, 1u);
}

// The proof rejects what is not the basis: a candidate lifted from too few small
// primes reconstructs wrong rationals (here the 1/31603 of the basis needs a modulus
// above 2·31603²), fails the check on the next prime, and is counted.
TEST(ModularGroebnerTest, WrongCandidatesAreRejected) {
  const RingPtr ring = Ring::make({"x", "y", "z"});
  const auto generators = parse_all({"187*x^2+y", "x*y-13*z^2+1", "y^3-z"}, ring);
  ModularGroebnerStats stats;
  modular(generators, &stats, /*first_prime=*/10);
  EXPECT_GE(stats.rejected_candidates, 1u);
  EXPECT_GT(stats.reconstructions, stats.rejected_candidates);
}

TEST(ModularGroebnerTest, UnitAndZeroIdeals) {
  const RingPtr ring = Ring::make({"x", "y"});
  EXPECT_EQ(print_all(modular(parse_all({"x^2+1", "x^2"}, ring)).basis), (std::vector<std::string>{"1"}));
  EXPECT_TRUE(modular(parse_all({"0"}, ring)).basis.empty());
  EXPECT_TRUE(modular({}).basis.empty());
}

// Without the proof the candidate is returned after one confirming prime (the runs
// are still homogenized, then taken to h = 1 modulo p); on these ideals it is the
// right one.
TEST(ModularGroebnerTest, WithoutProofTheAffineCandidate) {
  const RingPtr ring = Ring::make({"x", "y", "z"}, MonomialOrder::lex());
  for (const auto& generators : testing::random_ideals(ring, 10)) {
    ModularGroebnerStats stats;
    const GroebnerResult r = modular(generators, &stats, 0, /*prove=*/false);
    EXPECT_EQ(print_all(r.basis), print_all(compute_groebner_basis(generators).basis));
    EXPECT_FALSE(stats.proven);
    EXPECT_EQ(stats.verification_pairs, 0u);
  }
}

// The hole the random checks close. x − c·y with c = 1/2 + p1·p2, p1 and p2 the first
// two primes after 1000: modulo both, c is 1/2, so the candidate lifted from p1 is
// x − y/2 and the sequence's next prime, p2, confirms it. Without the proof and
// without random checks that wrong basis is the answer; with them, two random 62-bit
// primes (which cannot divide p1·p2) refute it, join the lift, and the right c is
// reconstructed and confirmed on two fresh random primes.
TEST(ModularGroebnerTest, RandomChecksRefuteACandidateTheSequenceConfirms) {
  const RingPtr ring = Ring::make({"x", "y"});
  const std::string c = "(1+2*1009*1013)/2";  // 1009 and 1013: the primes after 1000
  const auto generators = parse_all({"x-" + c + "*y"}, ring);
  const std::vector<std::string> right = print_all(compute_groebner_basis(generators).basis);
  ModularGroebnerParams params;
  params.first_prime = 1000;
  params.prove = false;
  params.threads = 1;
  ModularGroebnerStats sequence_only;
  EXPECT_EQ(print_all(compute_groebner_basis_modular(generators, params, &sequence_only).basis),
            (std::vector<std::string>{"x-1/2*y"}));
  EXPECT_TRUE(sequence_only.random_primes.empty());

  params.random_checks = 2;
  ModularGroebnerStats stats;
  EXPECT_EQ(print_all(compute_groebner_basis_modular(generators, params, &stats).basis), right);
  EXPECT_FALSE(stats.proven);
  EXPECT_EQ(stats.rejected_candidates, 1u);
  ASSERT_EQ(stats.random_primes.size(), 2u);
  for (const std::uint64_t p : stats.random_primes) {
    EXPECT_GE(p, std::uint64_t{1} << 61);
    EXPECT_LT(p, std::uint64_t{1} << 62);
  }
}

// The labelled unproven basis of Katsura and Cyclic (homogenized runs taken to h = 1)
// is the proven one, checked on two random primes and not called proven.
TEST(ModularGroebnerTest, UnprovenWithRandomChecksIsTheBasis) {
  const RingPtr k = Ring::make({"u0", "u1", "u2", "u3", "u4"});
  const RingPtr c = Ring::make({"a", "b", "c", "d", "e"});
  for (const auto& generators : {testing::katsura(k), testing::cyclic(c)}) {
    ModularGroebnerParams params;
    params.algorithm = ModularAlgorithm::f4;
    params.prove = false;
    params.random_checks = 2;
    ModularGroebnerStats stats;
    const GroebnerResult r = compute_groebner_basis_modular(generators, params, &stats);
    EXPECT_EQ(print_all(r.basis), print_all(modular(generators).basis));
    EXPECT_FALSE(stats.proven);
    EXPECT_EQ(stats.verification_pairs, 0u);
    EXPECT_EQ(stats.random_primes.size(), 2u);
    EXPECT_EQ(stats.checking_primes, 2u);
  }
}

// eliminate_modular without the proof, lifting only the elimination ideal: the same
// generators as Buchberger's elimination, for the twisted cubic's projections and a
// rational surface (the unit sphere's stereographic parametrization).
TEST(ModularGroebnerTest, EliminationLiftsOnlyTheEliminationIdeal) {
  const RingPtr ring = Ring::make({"w", "s", "t", "x", "y", "z"});
  const auto sphere =
      parse_all({"(1+s^2+t^2)*x-2*s", "(1+s^2+t^2)*y-2*t", "(1+s^2+t^2)*z-(1-s^2-t^2)", "1-w*(1+s^2+t^2)"}, ring);
  const RingPtr curve_ring = Ring::make({"t", "x", "y", "z"});
  const auto cubic = parse_all({"x-t", "y-t^2", "z-t^3"}, curve_ring);
  const std::vector<std::string> wst = {"w", "s", "t"}, t = {"t"};
  for (const auto& [generators, eliminated] :
       {std::pair{sphere, std::span<const std::string>(wst)}, std::pair{cubic, std::span<const std::string>(t)}}) {
    ModularGroebnerParams params;
    params.prove = false;
    params.lift_only_free_of_first = eliminated.size();
    ModularGroebnerStats stats;
    const EliminationResult m = eliminate_modular(generators, eliminated, params, MonomialOrder::grevlex(), &stats);
    const EliminationResult q = eliminate(generators, eliminated);
    EXPECT_EQ(print_all(m.elimination), print_all(q.elimination));
    EXPECT_EQ(m.groebner.basis.size(), q.elimination.size()) << "only the elimination ideal is lifted";
  }
}

TEST(ModularGroebnerTest, BudgetStopsIt) {
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3", "u4", "u5", "u6"});
  ModularGroebnerParams params;
  // A nanosecond: spent before the first check on any machine, however fast (a
  // deadline of milliseconds would make the verdict depend on the machine's speed).
  params.buchberger.budget.set_timeout(1e-9);
  try {
    compute_groebner_basis_modular(testing::katsura(ring), params);
    FAIL() << "Katsura-6 within a nanosecond";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
  params.buchberger.budget = Budget();
  params.buchberger.budget.cancel();
  EXPECT_THROW(compute_groebner_basis_modular(testing::katsura(ring), params), LimitExceeded);
}

// The proof over ℚ checks its budget between and within its row reductions: a work
// allowance that runs out halfway through the proof stops it there, with the proof
// named as the phase and its progress between none and all of its checks. Work, not
// time: one thread charges the same units on every run, so the stop falls at the same
// place on every machine.
TEST(ModularGroebnerTest, AWorkAllowanceStopsTheProofHalfway) {
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3", "u4"});
  const auto generators = testing::katsura(ring);
  // The stop, if any, under an allowance of `units` (0: none, the work is counted).
  struct Stop {
    bool stopped = false;
    std::string message;
    ProgressReport step;
    std::uint64_t work = 0;
  };
  auto run = [&](std::uint64_t units) {
    ModularGroebnerParams params;
    params.algorithm = ModularAlgorithm::f4;
    params.threads = 1;
    params.buchberger.budget.set_max_work(units == 0 ? std::numeric_limits<std::uint64_t>::max() : units);
    Stop stop;
    try {
      compute_groebner_basis_modular(generators, params);
    } catch (const LimitExceeded& e) {
      EXPECT_EQ(e.limit(), Limit::work);
      stop.stopped = true;
      stop.message = e.what();
    }
    stop.step = params.buchberger.budget.progress().step();
    stop.work = params.buchberger.budget.work_done();
    return stop;
  };
  const Stop whole = run(0);
  ASSERT_FALSE(whole.stopped);
  constexpr const char* kProof = "the proof over Q";
  auto in_proof = [&](const Stop& s) { return s.stopped && s.message.find(kProof) != std::string::npos; };
  // The least allowance that reaches the proof: every smaller one stops before it.
  std::uint64_t before = 0, reaches = whole.work;
  while (reaches - before > 1) {
    const std::uint64_t middle = before + (reaches - before) / 2;
    const Stop s = run(middle);
    (s.stopped && !in_proof(s) ? before : reaches) = middle;
  }
  ASSERT_LT(reaches, whole.work);
  const Stop halfway = run(reaches + (whole.work - reaches) / 2);
  ASSERT_TRUE(in_proof(halfway)) << halfway.message;
  ASSERT_NE(halfway.step.phase, nullptr);
  EXPECT_STREQ(halfway.step.phase, kProof);
  EXPECT_GT(halfway.step.done, 0u);
  EXPECT_LT(halfway.step.done, halfway.step.total);
}

// `basis` (over ℚ) with every coefficient taken modulo p into [0, p), printed and
// sorted: compute_groebner_basis_modulo's form of the same basis, for p dividing no
// denominator.
std::vector<std::string> printed_modulo(const std::vector<Polynomial>& basis, std::uint64_t p) {
  const mpz_class prime(static_cast<unsigned long>(p));
  std::vector<Polynomial> reduced;
  for (const Polynomial& g : basis) {
    const mpq_class content = to_mpq(g.content());
    mpz_class inverse;
    mpz_invert(inverse.get_mpz_t(), mpz_class(content.get_den()).get_mpz_t(), prime.get_mpz_t());
    const std::size_t w = g.ring()->monomial_size();
    std::vector<Integer> coefficients;
    std::vector<std::int32_t> monomials;
    for (std::size_t i = 0; i < g.num_terms(); ++i) {
      mpz_class c = content.get_num() * g.integer_coefficients()[i] * inverse;
      mpz_fdiv_r(c.get_mpz_t(), c.get_mpz_t(), prime.get_mpz_t());
      if (c == 0) continue;
      coefficients.push_back(c);
      monomials.insert(monomials.end(), g.monomial(i), g.monomial(i) + w);
    }
    reduced.push_back(Polynomial::from_terms(g.ring(), Rational(1), std::move(coefficients), std::move(monomials)));
  }
  std::vector<std::string> printed = print_all(reduced);
  std::sort(printed.begin(), printed.end());
  return printed;
}

// A proof row whose entries outgrow the candidate's largest coefficient eightfold is
// divided by its content, and the proof still goes through. Cyclic-6 after the change
// of variables x_i -> x_i + (i+1)·x_(i+1) gets there (one row, on one thread), where
// the classic ideals stay below two thirds of the threshold. The proven basis, taken
// modulo a prime the route does not use, is F4's basis modulo that prime.
TEST(ModularGroebnerTest, ARowThatOutgrowsTheCoefficientsIsDividedByItsContent) {
  const RingPtr ring = Ring::make({"x1", "x2", "x3", "x4", "x5", "x6"});
  const std::size_t n = 6;
  std::vector<std::string> v;
  for (std::size_t i = 0; i < n; ++i) {
    v.push_back("(x" + std::to_string(i + 1) + "+" + std::to_string(i + 2) + "*x" + std::to_string((i + 1) % n + 1) +
                ")");
  }
  std::vector<std::string> cyclic;
  for (std::size_t k = 1; k < n; ++k) {
    std::string sum;
    for (std::size_t i = 0; i < n; ++i) {
      std::string product;
      for (std::size_t j = 0; j < k; ++j) product += (j > 0 ? "*" : "") + v[(i + j) % n];
      sum += (i > 0 ? "+" : "") + product;
    }
    cyclic.push_back(sum);
  }
  std::string all;
  for (std::size_t i = 0; i < n; ++i) all += (i > 0 ? "*" : "") + v[i];
  cyclic.push_back(all + "-1");
  const auto generators = parse_all(cyclic, ring);
  ModularGroebnerParams params;
  params.algorithm = ModularAlgorithm::f4;
  params.threads = 1;
  params.buchberger.budget.set_timeout(60);
  ModularGroebnerStats stats;
  const GroebnerResult r = compute_groebner_basis_modular(generators, params, &stats);
  EXPECT_TRUE(stats.proven);
  EXPECT_GE(stats.proof_content_divisions, 1u);
  constexpr std::uint64_t kOtherPrime = 1000003;
  std::vector<std::string> f4 = print_all(compute_groebner_basis_modulo(generators, kOtherPrime, ModularAlgorithm::f4));
  std::sort(f4.begin(), f4.end());
  EXPECT_EQ(printed_modulo(r.basis, kOtherPrime), f4);
}

// The basis with two threads, which must be the one of one thread; `two` gets the
// two threads' counters.
void expect_one_thread_and_two_agree(const std::vector<Polynomial>& generators, ModularAlgorithm algorithm,
                                     ModularGroebnerStats& two_stats) {
  ModularGroebnerParams one, two;
  one.algorithm = two.algorithm = algorithm;
  one.threads = 1;
  two.threads = 2;
  ModularGroebnerStats one_stats;
  EXPECT_EQ(print_all(compute_groebner_basis_modular(generators, one, &one_stats).basis),
            print_all(compute_groebner_basis_modular(generators, two, &two_stats).basis));
  EXPECT_EQ(one_stats.threads, 1u);
  EXPECT_EQ(two_stats.threads, 2u);
  EXPECT_TRUE(one_stats.proven);
  EXPECT_TRUE(two_stats.proven);
}

TEST(ModularGroebnerTest, OneThreadAndTwoGiveTheSameBasis) {
  ModularGroebnerStats stats;
  expect_one_thread_and_two_agree(testing::katsura(Ring::make({"u0", "u1", "u2", "u3"})), ModularAlgorithm::buchberger,
                                  stats);
}

// Katsura-8's learning run takes long enough (about 100 ms here) for a follower to
// replay primes behind it on the second thread (trace_followers.hpp): however many it
// replayed, which depends on the machine, the proven basis is the one of one thread.
TEST(ModularGroebnerTest, PrimesFollowedBehindTheLearningRunGiveTheSameBasis) {
  ModularGroebnerStats stats;
  expect_one_thread_and_two_agree(testing::katsura(Ring::make({"u0", "u1", "u2", "u3", "u4", "u5", "u6", "u7", "u8"})),
                                  ModularAlgorithm::f4, stats);
  EXPECT_EQ(stats.lifted_primes + stats.unlucky_primes + stats.checking_primes, stats.primes);
  EXPECT_EQ(stats.replayed_primes + 1, stats.primes);  // every prime but the learning one
}

}  // namespace
}  // namespace implicitizer
