#pragma once
// Private to the groebner module: Buchberger's algorithm over one coefficient domain.
// The engine owns the basis, the pair queue (which owns the criteria) and the reducer
// list; the domain (`Arithmetic`) owns the polynomials' representation, their
// S-polynomials and reductions. Two domains use it: the fraction-free integers
// (buchberger.cpp, exact over ℚ) and the integers modulo a word-size prime
// (modular_groebner.cpp). One engine for both keeps the pair selection, the
// criteria and the sugar bookkeeping identical, so that a basis modulo p is computed
// the way the rational one is, pair for pair.
//
// Arithmetic provides:
//   using Polynomial = ...;                       // .monomials, .size(), .empty()
//   Polynomial s_polynomial(const Polynomial&, const Polynomial&) const;
//   Polynomial reduce(Polynomial, const std::vector<BasicReducer<Polynomial>>&, bool full,
//                     const Budget&, ReductionCounters&, std::int32_t* sugar) const;

#include <algorithm>
#include <vector>

#include "growing_basis.hpp"
#include "implicitizer/groebner/buchberger.hpp"
#include "reducer.hpp"
#include "s_pair_queue.hpp"

namespace implicitizer::detail {

template <class Arithmetic>
class BuchbergerEngine {
 public:
  using Poly = typename Arithmetic::Polynomial;

  // What a run leaves: the unit ideal, or the elements that are not redundant (a
  // Gröbner basis, minimal but neither interreduced nor normalized).
  struct Outcome {
    bool unit = false;
    std::vector<Poly> basis;
  };

  BuchbergerEngine(const Arithmetic& arithmetic, const Ring& ring, const BuchbergerParams& params,
                   BuchbergerStats& stats)
      : arithmetic_(arithmetic), ring_(ring), params_(params), stats_(stats), queue_(ring_, params_, stats_) {}

  // Buchberger's algorithm on `generators` (non-zero polynomials of the ring). With
  // `stop_at_nonzero`, the first S-polynomial that does not reduce to zero ends the
  // run with `false`: run on a candidate basis, that decides whether it is a
  // Gröbner basis, the pairs being those the criteria leave (Gebauer–Möller's
  // update is correct for a run, and a run whose every pair reduces to zero ends
  // with its input as the basis). Returns true otherwise.
  bool run(std::vector<Poly> generators, Outcome& out, bool stop_at_nonzero = false) {
    if (!basis_.insert_generators(std::move(generators), params_.budget, "Buchberger's algorithm (the generators)")) {
      out.unit = true;
      return true;
    }
    SPair pair;
    while (queue_.pop(basis_.entries(), pair)) {
      params_.budget.check("Buchberger's algorithm");
      ++stats_.reductions;
      // Pairs done of those known so far: the total grows as new elements form pairs.
      params_.budget.report_step("Buchberger's algorithm (S-pairs)", stats_.reductions,
                                 stats_.reductions + queue_.pairs_left());
      stats_.max_degree = std::max(stats_.max_degree, pair.lcm_degree);
      Poly s = arithmetic_.s_polynomial(basis_.polynomials()[pair.i], basis_.polynomials()[pair.j]);
      std::int32_t sugar = pair.sugar;
      ReductionCounters counters;
      counters.work = kWorkPerTerm * s.size();
      params_.budget.charge_work(counters.work, "Buchberger's algorithm");
      Poly h = arithmetic_.reduce(std::move(s), basis_.reducers(), false, params_.budget, counters, &sugar);
      if (!h.empty() && stop_at_nonzero) {
        stats_.reduction_steps += counters.steps;
        stats_.work += counters.work;
        return false;
      }
      if (!h.empty() && params_.variant.tail_reduce) {
        h = arithmetic_.reduce(std::move(h), basis_.reducers(), true, params_.budget, counters, &sugar);
      }
      stats_.reduction_steps += counters.steps;
      stats_.work += counters.work;
      if (h.empty()) {
        ++stats_.zero_reductions;
        continue;
      }
      if (basis_.is_constant(h)) {
        out.unit = true;
        return true;
      }
      basis_.insert(std::move(h), sugar);
    }
    out.basis = basis_.take_nonredundant();
    return true;
  }

 private:
  const Arithmetic& arithmetic_;
  const Ring& ring_;
  const BuchbergerParams& params_;
  BuchbergerStats& stats_;
  SPairQueue queue_;
  GrowingBasis<Poly> basis_{ring_, queue_};
};

}  // namespace implicitizer::detail
