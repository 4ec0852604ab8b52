#include "implicitizer/groebner/reduced_basis.hpp"

#include <algorithm>

#include "implicitizer/modular/one_per_thread.hpp"
#include "int_polynomial.hpp"

namespace implicitizer {

namespace {

std::vector<detail::Reducer> reducers_of(const Ring& ring, const std::vector<detail::IntPolynomial>& ps,
                                         std::size_t skip) {
  std::vector<detail::Reducer> out;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (i != skip && !ps[i].empty())
      out.push_back(detail::Reducer{&ps[i], ring.divisor_mask(ps[i].monomials.data()), 0});
  }
  return out;
}

}  // namespace

std::vector<Polynomial> reduce_basis(std::span<const Polynomial> groebner_basis, const Budget& budget,
                                     std::size_t threads) {
  if (groebner_basis.empty()) return {};
  const RingPtr ring = groebner_basis.front().ring();
  std::vector<const Polynomial*> sorted;
  for (const auto& g : groebner_basis) {
    if (!g.is_zero()) sorted.push_back(&g);
  }
  std::sort(sorted.begin(), sorted.end(), [&](const Polynomial* a, const Polynomial* b) {
    return ring->compare(a->leading_monomial(), b->leading_monomial()) < 0;
  });
  // Minimal basis: in increasing order, keep an element only if no kept leading
  // monomial divides its own (equal ones included, so one of each survives).
  std::vector<detail::IntPolynomial> minimal;
  for (const Polynomial* g : sorted) {
    const bool divisible = std::any_of(minimal.begin(), minimal.end(), [&](const detail::IntPolynomial& m) {
      return ring->divides(m.monomials.data(), g->leading_monomial());
    });
    if (!divisible) minimal.push_back(detail::to_int_polynomial(*g));
  }
  // Interreduce: each element's tail reduced by the others. Its leading term cannot
  // be reduced (the basis is minimal), and the result is the unique reduced element
  // with that leading monomial, whatever the order of the work.
  std::vector<Polynomial> reduced(minimal.size(), Polynomial(ring));
  threads = std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(minimal.size(), 1));
  run_one_per_thread(threads, [&](std::size_t t) {
    detail::ReductionCounters counters;
    for (std::size_t i = t; i < minimal.size(); i += threads) {
      const auto reducers = reducers_of(*ring, minimal, i);
      detail::IntPolynomial r = detail::reduce(*ring, minimal[i], reducers, true, budget, counters);
      reduced[i] = detail::to_monic_polynomial(ring, r);
    }
  });
  return reduced;
}

bool is_groebner(std::span<const Polynomial> basis, const Budget& budget) {
  if (basis.empty()) return true;
  const RingPtr ring = basis.front().ring();
  std::vector<detail::IntPolynomial> ps;
  for (const auto& g : basis) {
    if (!g.is_zero()) ps.push_back(detail::to_int_polynomial(g));
  }
  const auto reducers = reducers_of(*ring, ps, ps.size());
  detail::ReductionCounters counters;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    for (std::size_t j = i + 1; j < ps.size(); ++j) {
      detail::IntPolynomial s = detail::s_polynomial(*ring, ps[i], ps[j]);
      if (!detail::reduce(*ring, std::move(s), reducers, false, budget, counters).empty()) return false;
    }
  }
  return true;
}

bool is_reduced(std::span<const Polynomial> basis) {
  for (std::size_t i = 0; i < basis.size(); ++i) {
    const Polynomial& g = basis[i];
    if (g.is_zero() || g.leading_coefficient() != 1) return false;
    const Ring& ring = *g.ring();
    for (std::size_t j = 0; j < basis.size(); ++j) {
      // A zero element has no leading monomial; it fails the check on its own turn.
      if (i == j || basis[j].is_zero()) continue;
      const std::int32_t* lead = basis[j].leading_monomial();
      for (std::size_t t = 0; t < g.num_terms(); ++t) {
        if (ring.divides(lead, g.monomial(t))) return false;
      }
    }
  }
  return true;
}

}  // namespace implicitizer
