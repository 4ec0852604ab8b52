#include "implicitizer/groebner/elimination.hpp"

#include <algorithm>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {

namespace {

MonomialOrder elimination_order(std::size_t k, std::size_t n, const MonomialOrder& remaining_order) {
  // A degree order on the remaining variables is refined by the elimination weight
  // vector (1 on the eliminated variables, 0 elsewhere) followed by grevlex on all
  // variables, as Singular's `eliminate` does: ties in the eliminated degree go to
  // the smaller total degree, which keeps the intermediate bases small. On
  // biquadratic_patch this is 17x faster than the block order (grevlex | grevlex).
  // Any weight vector positive exactly on the eliminated variables gives an
  // elimination order (CLO §3.1, exercise 5). For other remaining orders (lex, a
  // weighted order), the block order restricts to them exactly.
  if (remaining_order == MonomialOrder::grevlex() && k > 0) {
    std::vector<int> weights(n, 0);
    std::fill(weights.begin(), weights.begin() + static_cast<std::ptrdiff_t>(k), 1);
    return MonomialOrder::weighted(std::move(weights), MonomialOrder::grevlex());
  }
  return MonomialOrder::block(k, MonomialOrder::grevlex(), remaining_order);
}

// The block ring of `eliminate` and the generators in it; `compute` finds the basis.
template <class Compute>
EliminationResult eliminate_with(std::span<const Polynomial> generators, std::span<const std::string> eliminate,
                                 const MonomialOrder& remaining_order, Compute compute) {
  if (generators.empty()) throw std::invalid_argument("eliminate needs at least one generator");
  const Ring& ring = *generators.front().ring();
  const std::size_t n = ring.num_variables();
  std::vector<bool> is_eliminated(n, false);
  for (const auto& name : eliminate) {
    const auto index = ring.index_of(name);
    if (!index) throw InputError("unknown_variable", "cannot eliminate '" + name + "': not a variable of the ring");
    is_eliminated[*index] = true;
  }
  // Block ring: eliminated variables first (in the ring's order), then the others.
  std::vector<std::string> block_names, remaining_names;
  std::vector<std::size_t> to_block(n), to_remaining(n, 0);
  const std::size_t k = static_cast<std::size_t>(std::count(is_eliminated.begin(), is_eliminated.end(), true));
  std::size_t next_eliminated = 0, next_remaining = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (is_eliminated[i]) {
      to_block[i] = next_eliminated++;
    } else {
      to_block[i] = k + next_remaining;
      to_remaining[i] = next_remaining++;
      remaining_names.push_back(ring.variables()[i]);
    }
  }
  block_names.resize(n);
  for (std::size_t i = 0; i < n; ++i) block_names[to_block[i]] = ring.variables()[i];

  EliminationResult result;
  result.block_ring = Ring::make(block_names, elimination_order(k, n, remaining_order));
  result.remaining_ring = Ring::make(remaining_names, remaining_order);
  std::vector<Polynomial> mapped;
  mapped.reserve(generators.size());
  for (const auto& g : generators) mapped.push_back(g.map_to(result.block_ring, to_block));
  result.groebner = compute(mapped);
  // Theorem 1.7: the basis elements free of the first block generate the elimination
  // ideal, and form its reduced basis for the restricted order.
  std::vector<std::size_t> back(n);
  for (std::size_t i = 0; i < n; ++i) {
    back[to_block[i]] = is_eliminated[i] ? 0 : to_remaining[i];
  }
  for (const auto& g : result.groebner.basis) {
    bool free = true;
    for (std::size_t v = 0; v < k && free; ++v) free = !g.involves(v);
    if (free) result.elimination.push_back(g.map_to(result.remaining_ring, back));
  }
  return result;
}

}  // namespace

EliminationResult eliminate(std::span<const Polynomial> generators, std::span<const std::string> eliminate,
                            const BuchbergerParams& params, const MonomialOrder& remaining_order) {
  return eliminate_with(generators, eliminate, remaining_order,
                        [&](const std::vector<Polynomial>& mapped) { return compute_groebner_basis(mapped, params); });
}

EliminationResult eliminate_modular(std::span<const Polynomial> generators, std::span<const std::string> eliminate,
                                    const ModularGroebnerParams& params, const MonomialOrder& remaining_order,
                                    ModularGroebnerStats* stats) {
  return eliminate_with(generators, eliminate, remaining_order, [&](const std::vector<Polynomial>& mapped) {
    return compute_groebner_basis_modular(mapped, params, stats);
  });
}

}  // namespace implicitizer
