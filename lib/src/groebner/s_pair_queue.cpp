#include "s_pair_queue.hpp"

#include <algorithm>

#include "reducer.hpp"

namespace implicitizer::detail {

bool SPairQueue::before(const SPair& a, const SPair& b) const {
  if (use_sugar_ && a.sugar != b.sugar) return a.sugar < b.sugar;
  const int c = ring_.compare(a.lcm.data(), b.lcm.data());
  if (c != 0) return c < 0;
  return a.serial < b.serial;
}

SPair SPairQueue::make_pair(const std::vector<BasisEntry>& basis, std::size_t i, std::size_t t) {
  SPair p;
  p.i = std::min(i, t);
  p.j = std::max(i, t);
  p.lcm.resize(ring_.monomial_size());
  ring_.lcm(basis[i].lead(), basis[t].lead(), p.lcm.data());
  p.lcm_mask = ring_.divisor_mask(p.lcm.data());
  p.lcm_degree = ring_.total_degree(p.lcm.data());
  p.sugar = std::max(basis[i].sugar - basis[i].lead_degree, basis[t].sugar - basis[t].lead_degree) +
            ring_.sugar_degree(p.lcm.data());
  p.serial = next_serial_++;
  ++stats_.pairs_created;
  return p;
}

void SPairQueue::push(SPair pair) {
  pending_.insert(key(pair.i, pair.j));
  heap_.push_back(std::move(pair));
  ++alive_;
  std::push_heap(heap_.begin(), heap_.end(), [this](const SPair& a, const SPair& b) { return before(b, a); });
}

void SPairQueue::examined(std::size_t& steps) const {
  // Every 4096 pairs examined: the criteria are quadratic in the basis, and on an
  // ideal of 30 000 generators one update alone takes seconds.
  if ((++steps & 0xfff) == 0) {
    params_.budget.charge_work(kWorkPerPairExamined * 0x1000, "the S-pair criteria");
    params_.budget.check("the S-pair criteria");
  }
}

void SPairQueue::add_element(std::vector<BasisEntry>& basis, std::size_t t) {
  if (params_.variant.chain_criterion == ChainCriterion::gebauer_moller) {
    update_gebauer_moller(basis, t);
    return;
  }
  // Plain pair creation: every earlier element pairs with t; only the product
  // criterion filters here (Buchberger's chain criterion acts at selection time).
  std::size_t steps = 0;
  for (std::size_t i = 0; i < t; ++i) {
    examined(steps);
    SPair p = make_pair(basis, i, t);
    if (params_.variant.product_criterion && ring_.coprime(basis[i].lead(), basis[t].lead())) {
      ++stats_.product_criterion;
      continue;
    }
    push(std::move(p));
  }
}

// Gebauer–Möller's update (Gebauer & Möller 1988; Becker–Weispfenning, UPDATE):
//  M: a new pair (i,t) is dropped when another new pair's lcm properly divides its lcm;
//  F: of new pairs with equal lcm one is kept, none if one of them is coprime;
//  B: an old pair (i,j) is dropped when lm(t) | lcm(i,j) and lcm(i,t), lcm(j,t) both
//     differ from lcm(i,j): its S-polynomial reduces to zero through the chain i–t–j.
// Correctness rests on Buchberger's criteria; every dropped pair is counted.
void SPairQueue::update_gebauer_moller(std::vector<BasisEntry>& basis, std::size_t t) {
  std::size_t steps = 0;
  std::vector<SPair> fresh;
  for (std::size_t i = 0; i < t; ++i) {
    examined(steps);
    if (!basis[i].redundant) fresh.push_back(make_pair(basis, i, t));
  }
  const auto coprime = [&](const SPair& p) {
    const std::size_t other = p.i == t ? p.j : p.i;
    return params_.variant.product_criterion && ring_.coprime(basis[other].lead(), basis[t].lead());
  };
  const auto lcm_divides = [&](const SPair& a, const SPair& b) {
    return (a.lcm_mask & ~b.lcm_mask) == 0 && ring_.divides(a.lcm.data(), b.lcm.data());
  };
  // M and F: walk the new pairs; keep (i,t) if it is coprime (it then stands for its
  // lcm class) or no other remaining new pair (one not walked yet, or one kept) has an
  // lcm dividing its lcm.
  std::vector<SPair> kept;
  for (std::size_t a = 0; a < fresh.size(); ++a) {
    bool drop = false;
    if (!coprime(fresh[a])) {
      for (std::size_t b = a + 1; b < fresh.size() && !drop; ++b) {
        examined(steps);
        if (lcm_divides(fresh[b], fresh[a])) drop = true;
      }
      for (std::size_t b = 0; b < kept.size() && !drop; ++b) {
        examined(steps);
        if (lcm_divides(kept[b], fresh[a])) drop = true;
      }
    }
    if (drop) {
      ++stats_.chain_criterion;
    } else {
      kept.push_back(std::move(fresh[a]));
    }
  }
  // B on the old pairs.
  const std::int32_t* lt = basis[t].lead();
  const std::uint64_t lt_mask = basis[t].mask;
  const std::size_t w = ring_.monomial_size();
  std::vector<std::int32_t> lit(w), ljt(w);
  for (auto& p : heap_) {
    examined(steps);
    if (!p.alive || (lt_mask & ~p.lcm_mask) != 0 || !ring_.divides(lt, p.lcm.data())) continue;
    ring_.lcm(basis[p.i].lead(), lt, lit.data());
    ring_.lcm(basis[p.j].lead(), lt, ljt.data());
    if (!ring_.equal(lit.data(), p.lcm.data()) && !ring_.equal(ljt.data(), p.lcm.data())) {
      p.alive = false;
      --alive_;
      pending_.erase(key(p.i, p.j));
      ++stats_.chain_criterion;
    }
  }
  // Product criterion on what is left of the new pairs.
  for (auto& p : kept) {
    if (coprime(p)) {
      ++stats_.product_criterion;
    } else {
      push(std::move(p));
    }
  }
  // Elements whose leading monomial lm(t) divides need no new pairs any more.
  for (std::size_t i = 0; i < t; ++i) {
    examined(steps);
    if (!basis[i].redundant && (lt_mask & ~basis[i].mask) == 0 && ring_.divides(lt, basis[i].lead())) {
      basis[i].redundant = true;
    }
  }
}

// Buchberger's second criterion (Buchberger 1979), the corrected form of criterion 2
// of Theorem 1.6 in the seed thesis: S(i,j) may be skipped when some k has
// lm(k) | lcm(i,j) and neither (i,k) nor (j,k) is still waiting. The thesis asks
// only one of S(i,k), S(j,k) to reduce to zero, which is not enough: the proof
// rewrites S(i,j) through both.
bool SPairQueue::buchberger_chain_applies(const std::vector<BasisEntry>& basis, const SPair& p) const {
  std::size_t steps = 0;
  for (std::size_t k = 0; k < basis.size(); ++k) {
    examined(steps);
    if (k == p.i || k == p.j) continue;
    if (!ring_.divides(basis[k].lead(), p.lcm.data())) continue;
    if (pending_.count(key(p.i, k)) || pending_.count(key(p.j, k))) continue;
    return true;
  }
  return false;
}

bool SPairQueue::pop(const std::vector<BasisEntry>& basis, SPair& out) {
  const auto later = [this](const SPair& a, const SPair& b) { return before(b, a); };
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    SPair p = std::move(heap_.back());
    heap_.pop_back();
    if (!p.alive) continue;
    --alive_;
    pending_.erase(key(p.i, p.j));
    if (params_.variant.chain_criterion == ChainCriterion::buchberger && buchberger_chain_applies(basis, p)) {
      ++stats_.chain_criterion;
      continue;
    }
    out = std::move(p);
    return true;
  }
  return false;
}

}  // namespace implicitizer::detail
