#pragma once
// Private to the groebner module: the S-pair queue. It owns the pair criteria
// (product, Gebauer–Möller, Buchberger's second criterion) and their counters, as
// mathicgb's SPairs does; the driver only asks for the next pair.

#include <cstdint>
#include <unordered_set>
#include <vector>

#include "implicitizer/groebner/buchberger.hpp"

namespace implicitizer::detail {

// A basis element as the queue sees it: its leading monomial, not its polynomial,
// so that one queue serves every coefficient domain (ℤ fraction-free, ℤ/p).
struct BasisEntry {
  std::vector<std::int32_t> lead_monomial;
  std::uint64_t mask = 0;  // divisor mask of the leading monomial
  std::int32_t sugar = 0;
  std::int32_t lead_degree = 0;
  bool redundant = false;  // its leading monomial is divisible by a later element's
  const std::int32_t* lead() const { return lead_monomial.data(); }
};

// One S-pair (i < j are basis indices).
struct SPair {
  std::size_t i = 0, j = 0;
  std::vector<std::int32_t> lcm;
  std::uint64_t lcm_mask = 0;  // divisor mask of lcm: a cheap necessary test of divisibility
  std::int32_t sugar = 0;
  std::int32_t lcm_degree = 0;
  std::uint64_t serial = 0;  // creation order: the final tie-break, for determinism
  bool alive = true;
};

class SPairQueue {
 public:
  SPairQueue(const Ring& ring, const BuchbergerParams& params, BuchbergerStats& stats)
      : ring_(ring),
        params_(params),
        stats_(stats),
        use_sugar_(params.variant.strategy == SelectionStrategy::sugar ||
                   (params.variant.strategy == SelectionStrategy::automatic && ring.is_elimination_order())) {}

  // Called after basis[t] was appended: forms the pairs (i, t), applies the
  // criteria of the chosen update, and marks elements made redundant.
  void add_element(std::vector<BasisEntry>& basis, std::size_t t);

  // Removes and returns the next pair to reduce, skipping those the selection-time
  // criteria (Buchberger's second criterion) discard. False when none is left.
  bool pop(const std::vector<BasisEntry>& basis, SPair& out);

  // Pairs still queued that no criterion has discarded yet (the progress of a run).
  std::size_t pairs_left() const { return alive_; }

 private:
  bool before(const SPair& a, const SPair& b) const;  // a is selected before b
  SPair make_pair(const std::vector<BasisEntry>& basis, std::size_t i, std::size_t t);
  void push(SPair pair);
  void update_gebauer_moller(std::vector<BasisEntry>& basis, std::size_t t);
  // Counts one pair or element examined by a criterion; every few thousand, charges
  // them as work and checks the budget.
  void examined(std::size_t& steps) const;
  bool buchberger_chain_applies(const std::vector<BasisEntry>& basis, const SPair& p) const;
  static std::uint64_t key(std::size_t i, std::size_t j) {
    return (std::uint64_t{std::min(i, j)} << 32) | std::max(i, j);
  }

  const Ring& ring_;
  const BuchbergerParams& params_;
  BuchbergerStats& stats_;
  bool use_sugar_;           // the strategy, with `automatic` resolved for this ring's order
  std::vector<SPair> heap_;  // binary heap on before(); dead pairs removed lazily
  std::size_t alive_ = 0;
  std::unordered_set<std::uint64_t> pending_;  // keys of pairs still queued (Buchberger's criterion)
  std::uint64_t next_serial_ = 0;
};

}  // namespace implicitizer::detail
