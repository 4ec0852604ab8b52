#pragma once
// Private to the groebner module: the basis a pair-based algorithm grows (the
// Buchberger engine, buchberger_engine.hpp, and F4, f4_engine.hpp), for any
// coefficient domain: the elements as the pair queue sees them (leading monomial,
// sugar, redundancy), their polynomials, and the reducer list over all of them. One
// class for both keeps the sugar bookkeeping and the choice of reducers identical.

#include <algorithm>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "reducer.hpp"
#include "s_pair_queue.hpp"

namespace implicitizer::detail {

template <class Poly>
class GrowingBasis {
 public:
  GrowingBasis(const Ring& ring, SPairQueue& queue) : ring_(ring), queue_(queue) {}

  std::vector<BasisEntry>& entries() { return entries_; }
  const std::vector<Poly>& polynomials() const { return polynomials_; }
  const std::vector<BasicReducer<Poly>>& reducers() const { return reducers_; }

  bool is_constant(const Poly& p) const { return p.size() == 1 && ring_.total_degree(p.monomials.data()) == 0; }

  // The sugar of an input polynomial: its largest order degree over all terms.
  std::int32_t sugar_of(const Poly& p) const {
    const std::size_t w = ring_.monomial_size();
    std::int32_t d = 0;
    for (std::size_t i = 0; i < p.size(); ++i) d = std::max(d, ring_.sugar_degree(p.monomials.data() + i * w));
    return d;
  }

  // Appends p (non-zero) with `sugar` (raised to its leading degree), lets the queue
  // form its pairs and apply the criteria, and rebuilds the reducer list.
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

  // Inserts the non-zero generators, each with its own sugar; false (and stops) at a
  // non-zero constant: the unit ideal. Checks `budget` between generators.
  bool insert_generators(std::vector<Poly> generators, const Budget& budget, const char* where) {
    for (auto& g : generators) {
      budget.check(where);
      if (g.empty()) continue;
      if (is_constant(g)) return false;
      const std::int32_t sugar = sugar_of(g);
      insert(std::move(g), sugar);
    }
    return true;
  }

  // The elements that are not redundant, moved out (the basis is spent).
  std::vector<Poly> take_nonredundant() {
    std::vector<Poly> out;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      if (!entries_[i].redundant) out.push_back(std::move(polynomials_[i]));
    }
    return out;
  }

 private:
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

  const Ring& ring_;
  SPairQueue& queue_;
  std::vector<BasisEntry> entries_;
  std::vector<Poly> polynomials_;
  std::vector<BasicReducer<Poly>> reducers_;
};

}  // namespace implicitizer::detail
