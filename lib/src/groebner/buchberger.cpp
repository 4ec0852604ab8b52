#include "implicitizer/groebner/buchberger.hpp"

#include <stdexcept>

#include "buchberger_engine.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/groebner/reduced_basis.hpp"
#include "int_polynomial.hpp"

namespace implicitizer {

namespace {

// Units of work a millisecond: the median of BuchbergerStats::work / groebner_ms over
// the benchmark surfaces' runs of 0.4 ms or more (docs/algorithms.md, "Head starts in
// units of work", has the command that measures it and the spread).
constexpr double kWorkPerMillisecond = 350000;

}  // namespace

std::uint64_t buchberger_work_of_milliseconds(double ms) {
  return static_cast<std::uint64_t>(ms * kWorkPerMillisecond);
}

GroebnerResult compute_groebner_basis(std::span<const Polynomial> generators, const BuchbergerParams& params) {
  if (generators.empty()) return GroebnerResult{};
  const RingPtr& ring = generators.front().ring();
  for (const auto& g : generators) {
    if (g.ring() != ring && !(*g.ring() == *ring)) throw std::invalid_argument("generators from different rings");
  }
  const Stopwatch timer;
  std::vector<detail::IntPolynomial> input;
  for (const auto& g : generators) {
    if (!g.is_zero()) input.push_back(detail::to_int_polynomial(g));
  }
  GroebnerResult result;
  const detail::IntegerArithmetic arithmetic(*ring);
  detail::BuchbergerEngine<detail::IntegerArithmetic> engine(arithmetic, *ring, params, result.stats);
  detail::BuchbergerEngine<detail::IntegerArithmetic>::Outcome outcome;
  engine.run(std::move(input), outcome);
  if (outcome.unit) {
    result.basis.push_back(Polynomial::constant(ring, Rational(1)));
  } else {
    std::vector<Polynomial> kept;
    for (const auto& p : outcome.basis) kept.push_back(detail::to_monic_polynomial(ring, p));
    result.basis = reduce_basis(kept, params.budget);
  }
  result.stats.basis_size = result.basis.size();
  result.stats.elapsed_ms = timer.elapsed_ms();
  return result;
}

}  // namespace implicitizer
