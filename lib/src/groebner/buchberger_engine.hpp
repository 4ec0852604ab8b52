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
    for (auto& g : generators) {
      params_.budget.check("Buchberger's algorithm (the generators)");
      if (g.empty()) continue;
      if (is_constant(g)) {
        out.unit = true;
        return true;
      }
      const std::int32_t sugar = sugar_of(g);
      insert(std::move(g), sugar);
    }
    SPair pair;
    while (queue_.pop(entries_, pair)) {
      params_.budget.check("Buchberger's algorithm");
      ++stats_.reductions;
      stats_.max_degree = std::max(stats_.max_degree, pair.lcm_degree);
      Poly s = arithmetic_.s_polynomial(polynomials_[pair.i], polynomials_[pair.j]);
      std::int32_t sugar = pair.sugar;
      ReductionCounters counters;
      counters.work = kWorkPerTerm * s.size();
      params_.budget.charge_work(counters.work, "Buchberger's algorithm");
      Poly h = arithmetic_.reduce(std::move(s), reducers_, false, params_.budget, counters, &sugar);
      if (!h.empty() && stop_at_nonzero) {
        stats_.reduction_steps += counters.steps;
        stats_.work += counters.work;
        return false;
      }
      if (!h.empty() && params_.variant.tail_reduce) {
        h = arithmetic_.reduce(std::move(h), reducers_, true, params_.budget, counters, &sugar);
      }
      stats_.reduction_steps += counters.steps;
      stats_.work += counters.work;
      if (h.empty()) {
        ++stats_.zero_reductions;
        continue;
      }
      if (is_constant(h)) {
        out.unit = true;
        return true;
      }
      insert(std::move(h), sugar);
    }
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      if (!entries_[i].redundant) out.basis.push_back(std::move(polynomials_[i]));
    }
    return true;
  }

 private:
  bool is_constant(const Poly& p) const { return p.size() == 1 && ring_.total_degree(p.monomials.data()) == 0; }

  void insert(Poly p, std::int32_t sugar) {
    BasisEntry e;
    const std::size_t w = ring_.monomial_size();
    e.lead_monomial.assign(p.monomials.begin(), p.monomials.begin() + static_cast<std::ptrdiff_t>(w));
    e.mask = ring_.divisor_mask(e.lead());
    e.lead_degree = ring_.sugar_degree(e.lead());
    e.sugar = std::max(sugar, e.lead_degree);
    entries_.push_back(std::move(e));
    polynomials_.push_back(std::move(p));
    queue_.add_element(entries_, entries_.size() - 1);
    rebuild_reducers();
  }

  // The sugar of an input polynomial: its largest order degree over all terms.
  std::int32_t sugar_of(const Poly& p) const {
    const std::size_t w = ring_.monomial_size();
    std::int32_t d = 0;
    for (std::size_t i = 0; i < p.size(); ++i) d = std::max(d, ring_.sugar_degree(p.monomials.data() + i * w));
    return d;
  }

  // The reducer list points into polynomials_, which may just have reallocated:
  // rebuild it (linear in the basis).
  void rebuild_reducers() {
    // Reducers: every element, redundant ones included. A redundant element forms no
    // new pairs (Gebauer–Möller), but it stays a reducer: the element t that made it
    // redundant often has a far higher sugar (a low-degree leading monomial found
    // late), and reducing by t instead raises the sugar of every result, so the
    // selection climbs in degree and coefficients swell. Katsura-3 in lex with sugar
    // took over 60 s without it and takes 0.3 ms with it; tp_22 2.0 s -> 0.6 s.
    // Reducing by any ideal member is sound: the elements ever added form a Gröbner
    // basis (a redundant r's pairs with later u are covered by the chain r–t–u).
    reducers_.clear();
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      reducers_.push_back(BasicReducer<Poly>{&polynomials_[i], entries_[i].mask, entries_[i].sugar});
    }
  }

  const Arithmetic& arithmetic_;
  const Ring& ring_;
  const BuchbergerParams& params_;
  BuchbergerStats& stats_;
  SPairQueue queue_;
  std::vector<BasisEntry> entries_;
  std::vector<Poly> polynomials_;
  std::vector<BasicReducer<Poly>> reducers_;
};

}  // namespace implicitizer::detail
