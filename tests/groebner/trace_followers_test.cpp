// Replays of a trace while it is learned (lib/src/groebner/trace_followers.hpp). How
// far the follower gets depends on the machine (on a loaded one it may not have run
// at all); what is checked does not: every prime it was given comes back
// replayed, bad or untaken, in order, and every replay it began gives, once finished,
// the basis of a run in full.
#include "trace_followers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "groebner/groebner_support.hpp"
#include "implicitizer/core/errors.hpp"
#include "int_polynomial.hpp"

namespace implicitizer::detail {
namespace {

constexpr std::uint64_t kLearningPrime = 4611686018427387847;  // a 62-bit prime

std::vector<ModPolynomial> modulo(const std::vector<Polynomial>& generators, const ModularArithmetic& arithmetic) {
  std::vector<ModPolynomial> reduced;
  for (const auto& g : generators) reduced.push_back(arithmetic.reduce_coefficients(to_int_polynomial(g)));
  return reduced;
}

TEST(TraceFollowersTest, EveryPrimeComesBackReplayedBadOrUntaken) {
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3", "u4", "u5", "u6"});
  const std::vector<Polynomial> generators = testing::katsura(ring);
  const std::vector<std::uint64_t> primes = {2147483629, 2147483587, 2147483579, 2147483563, 2147483549};
  const std::uint64_t bad_prime = primes[1];  // the follower is told it divides a leading coefficient
  const TraceFollowers::Prepare prepare = [&](std::uint64_t p) -> std::optional<std::vector<ModPolynomial>> {
    if (p == bad_prime) return std::nullopt;
    return modulo(generators, ModularArithmetic(*ring, p));
  };
  const Budget budget;
  F4Trace trace;
  std::optional<TraceFollowers> followers;
  trace.set_after_step([&] {
    if (!followers) followers.emplace(*ring, trace, primes, prepare, budget);
  });
  const ModularArithmetic learning(*ring, kLearningPrime);
  BuchbergerStats stats;
  run_f4(*ring, learning, modulo(generators, learning), BuchbergerParams{}, stats, &trace);
  trace.close();
  ASSERT_TRUE(followers);
  TraceFollowers::Followed followed = followers->stop();

  // Taken in order: the replays and the bad prime are a prefix, the rest untaken.
  std::vector<std::uint64_t> taken;
  for (const F4Trace::Replay& r : followed.replays) taken.push_back(r.prime());
  EXPECT_LE(followed.bad.size(), 1u);
  if (!followed.bad.empty()) {
    EXPECT_EQ(followed.bad.front(), bad_prime);
    taken.insert(taken.begin() + 1, bad_prime);
  }
  taken.insert(taken.end(), followed.untaken.begin(), followed.untaken.end());
  EXPECT_EQ(taken, primes);

  for (F4Trace::Replay& r : followed.replays) {
    SCOPED_TRACE("prime " + std::to_string(r.prime()));
    const ModularArithmetic arithmetic(*ring, r.prime());
    BuchbergerStats replay_stats, full_stats;
    const std::optional<F4Outcome> outcome = trace.replay(*ring, r, budget, replay_stats);
    ASSERT_TRUE(outcome);
    const F4Outcome full = run_f4(*ring, arithmetic, modulo(generators, arithmetic), BuchbergerParams{}, full_stats);
    const std::vector<ModPolynomial> got = arithmetic.reduce_basis(outcome->basis, budget);
    const std::vector<ModPolynomial> expected = arithmetic.reduce_basis(full.basis, budget);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].coefficients, expected[i].coefficients) << "element " << i;
      EXPECT_EQ(got[i].monomials, expected[i].monomials) << "element " << i;
    }
  }
}

TEST(TraceFollowersTest, AFollowerStopsWhenTheLearningRunStops) {
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3", "u4", "u5"});
  const std::vector<Polynomial> generators = testing::katsura(ring);
  BuchbergerParams params;
  F4Trace trace;
  std::optional<TraceFollowers> followers;
  std::size_t recorded = 0;
  trace.set_after_step([&] {
    if (!followers) {
      followers.emplace(
          *ring, trace, std::vector<std::uint64_t>{2147483629, 2147483587},
          [&](std::uint64_t p) { return std::optional(modulo(generators, ModularArithmetic(*ring, p))); },
          params.budget);
    }
    if (++recorded == 3) params.budget.cancel();
  });
  const ModularArithmetic learning(*ring, kLearningPrime);
  BuchbergerStats stats;
  EXPECT_THROW(run_f4(*ring, learning, modulo(generators, learning), params, stats, &trace), LimitExceeded);
  trace.close();
  ASSERT_TRUE(followers);
  // The follower stops at its next step or wait (a hang would time the test out); it
  // may have met the cancelled budget itself, which stop() then rethrows.
  try {
    const TraceFollowers::Followed followed = followers->stop();
    for (const F4Trace::Replay& r : followed.replays) EXPECT_LE(r.steps(), recorded);
  } catch (const LimitExceeded&) {
  }
  EXPECT_FALSE(trace.complete());
}

}  // namespace
}  // namespace implicitizer::detail
