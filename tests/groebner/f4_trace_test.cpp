// F4's trace as the learning run publishes it (lib/src/groebner/f4_trace.hpp): a
// replay can take each step as soon as it is recorded, waits at the end of what is
// recorded until the trace is closed, and then gives the basis of a run in full.
#include "f4_trace.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "groebner/groebner_support.hpp"
#include "implicitizer/core/errors.hpp"
#include "int_polynomial.hpp"

namespace implicitizer::detail {
namespace {

constexpr std::uint64_t kLearningPrime = 4611686018427387847;  // a 62-bit prime
constexpr std::uint64_t kReplayedPrime = 2147483629;           // 2^31 − 19

std::vector<ModPolynomial> modulo(const std::vector<Polynomial>& generators, const ModularArithmetic& arithmetic) {
  std::vector<ModPolynomial> reduced;
  for (const auto& g : generators) reduced.push_back(arithmetic.reduce_coefficients(to_int_polynomial(g)));
  return reduced;
}

TEST(F4TraceTest, AReplayTakesEachStepAsSoonAsItIsRecorded) {
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3", "u4", "u5"});
  const std::vector<Polynomial> generators = testing::katsura(ring);
  const ModularArithmetic learning(*ring, kLearningPrime), replayed(*ring, kReplayedPrime);
  F4Trace trace;
  F4Trace::Replay replay(kReplayedPrime, modulo(generators, replayed));
  std::size_t recorded = 0;
  trace.set_after_step([&] {
    ++recorded;
    // One step was published since the last call, and the replay takes it; then it
    // is at the end of what is recorded, and must wait.
    EXPECT_EQ(trace.replay_step(*ring, replay, Budget()), F4Trace::StepResult::replayed);
    EXPECT_EQ(replay.steps(), recorded);
    EXPECT_EQ(trace.replay_step(*ring, replay, Budget()), F4Trace::StepResult::not_yet);
  });
  BuchbergerStats stats;
  run_f4(*ring, learning, modulo(generators, learning), BuchbergerParams{}, stats, &trace);
  EXPECT_GT(recorded, 3u);
  // Finished but not closed: the learning run's caller may still record the plan.
  EXPECT_EQ(trace.replay_step(*ring, replay, Budget()), F4Trace::StepResult::not_yet);
  trace.close();
  EXPECT_EQ(trace.replay_step(*ring, replay, Budget()), F4Trace::StepResult::end);
  EXPECT_FALSE(replay.left_path());

  const std::optional<F4Outcome> outcome = trace.replay(*ring, replay, Budget(), stats);
  ASSERT_TRUE(outcome);
  BuchbergerStats full_stats;
  const F4Outcome full = run_f4(*ring, replayed, modulo(generators, replayed), BuchbergerParams{}, full_stats);
  const std::vector<ModPolynomial> expected = replayed.reduce_basis(full.basis, Budget());
  const std::vector<ModPolynomial> got = replayed.reduce_basis(outcome->basis, Budget());
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].coefficients, expected[i].coefficients) << "element " << i;
    EXPECT_EQ(got[i].monomials, expected[i].monomials) << "element " << i;
  }
}

TEST(F4TraceTest, AReplayOfARunThatEndedWithoutABasisGivesNothing) {
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3", "u4"});
  const std::vector<Polynomial> generators = testing::katsura(ring);
  const ModularArithmetic learning(*ring, kLearningPrime), replayed(*ring, kReplayedPrime);
  F4Trace trace;
  BuchbergerParams params;
  std::size_t recorded = 0;
  trace.set_after_step([&] {
    if (++recorded == 2) params.budget.cancel();  // the run stops after two steps
  });
  BuchbergerStats stats;
  EXPECT_THROW(run_f4(*ring, learning, modulo(generators, learning), params, stats, &trace), LimitExceeded);
  trace.close();
  EXPECT_EQ(recorded, 2u);
  EXPECT_FALSE(trace.complete());
  EXPECT_FALSE(trace.replay(*ring, replayed, modulo(generators, replayed), Budget(), stats));
}

}  // namespace
}  // namespace implicitizer::detail
