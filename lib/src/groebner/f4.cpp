#include "implicitizer/groebner/f4.hpp"

#include <stdexcept>

#include "buchberger_engine.hpp"
#include "f4_engine.hpp"
#include "f4_interreduce.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "int_polynomial.hpp"
#include "mod_polynomial.hpp"

namespace implicitizer {

namespace detail {

F4Outcome run_modular_algorithm(const Ring& ring, const ModularArithmetic& arithmetic,
                                std::vector<ModPolynomial> generators, ModularAlgorithm algorithm,
                                const BuchbergerParams& params, BuchbergerStats& stats, std::size_t threads) {
  if (algorithm == ModularAlgorithm::f4) {
    return run_f4(ring, arithmetic, std::move(generators), params, stats, nullptr, threads);
  }
  BuchbergerEngine<ModularArithmetic> engine(arithmetic, ring, params, stats);
  BuchbergerEngine<ModularArithmetic>::Outcome outcome;
  engine.run(std::move(generators), outcome);
  return F4Outcome{outcome.unit, std::move(outcome.basis)};
}

std::vector<ModPolynomial> reduce_modular_basis(const Ring& ring, const ModularArithmetic& arithmetic,
                                                std::vector<ModPolynomial> basis, ModularAlgorithm algorithm,
                                                const Budget& budget, const InterreductionPlan* replay,
                                                InterreductionPlan* record) {
  if (algorithm == ModularAlgorithm::f4) {
    return reduce_basis_by_matrix(ring, arithmetic, std::move(basis), budget, replay, record);
  }
  return arithmetic.reduce_basis(std::move(basis), budget);
}

}  // namespace detail

namespace {

// The reduced Gröbner basis modulo p by `algorithm` ({1} for the unit ideal).
std::vector<detail::ModPolynomial> groebner_basis_modulo(const Ring& ring, const detail::ModularArithmetic& arithmetic,
                                                         std::vector<detail::ModPolynomial> input,
                                                         ModularAlgorithm algorithm, const BuchbergerParams& params,
                                                         BuchbergerStats& stats) {
  detail::F4Outcome outcome =
      detail::run_modular_algorithm(ring, arithmetic, std::move(input), algorithm, params, stats);
  if (outcome.unit) {
    detail::ModPolynomial one;
    one.coefficients.push_back(1);
    one.monomials.assign(ring.monomial_size(), 0);
    return {std::move(one)};
  }
  return detail::reduce_modular_basis(ring, arithmetic, std::move(outcome.basis), algorithm, params.budget);
}

}  // namespace

std::vector<Polynomial> compute_groebner_basis_modulo(std::span<const Polynomial> generators, std::uint64_t prime,
                                                      ModularAlgorithm algorithm, const BuchbergerParams& params,
                                                      BuchbergerStats* stats_out) {
  if (generators.empty()) return {};
  const RingPtr& ring = generators.front().ring();
  for (const auto& g : generators) {
    if (g.ring() != ring && !(*g.ring() == *ring)) throw std::invalid_argument("generators from different rings");
  }
  const Stopwatch timer;
  const detail::ModularArithmetic arithmetic(*ring, prime);
  std::vector<detail::ModPolynomial> input;
  for (const auto& g : generators) {
    if (g.is_zero()) continue;
    detail::ModPolynomial reduced = arithmetic.reduce_coefficients(detail::to_int_polynomial(g));
    if (!reduced.empty()) input.push_back(std::move(reduced));
  }
  BuchbergerStats stats;
  std::vector<Polynomial> out;
  for (const auto& g : groebner_basis_modulo(*ring, arithmetic, std::move(input), algorithm, params, stats)) {
    std::vector<Integer> coefficients;
    for (std::uint64_t c : g.coefficients) coefficients.emplace_back(static_cast<unsigned long>(c));
    out.push_back(Polynomial::from_terms(ring, Rational(1), std::move(coefficients), g.monomials));
  }
  stats.basis_size = out.size();
  stats.elapsed_ms = timer.elapsed_ms();
  if (stats_out != nullptr) *stats_out = stats;
  return out;
}

}  // namespace implicitizer
