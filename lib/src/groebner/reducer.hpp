#pragma once
// Private to the groebner module: what a reduction needs to know of a basis element,
// for any coefficient domain (the fraction-free integers of int_polynomial.hpp, the
// integers modulo a prime of mod_polynomial.hpp).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace implicitizer::detail {

// One reducer: a basis element with its leading-monomial divisor mask and sugar.
template <class P>
struct BasicReducer {
  const P* polynomial;
  std::uint64_t mask;
  std::int32_t sugar;
};

// Counters updated by the reductions.
// Budget::charge_work's units, chosen so that a unit costs about the same time
// whatever the coefficients (docs/algorithms.md, "Head starts in units of work",
// measures the spread): a term written costs its monomial's arithmetic and an
// allocation, far more than one limb of its coefficient; a reduction step costs the
// search for its reducer; a pair examined by a criterion, a few monomial comparisons.
inline constexpr std::uint64_t kWorkPerTerm = 32;
inline constexpr std::uint64_t kWorkPerLimb = 1;
inline constexpr std::uint64_t kWorkPerStep = 64;
inline constexpr std::uint64_t kWorkPerModularTerm = 4;
inline constexpr std::uint64_t kWorkPerPairExamined = 2;

struct ReductionCounters {
  std::size_t steps = 0;
  std::uint64_t work = 0;  // Budget::charge_work units: terms and coefficient limbs written
};

// The reducer used for monomial m: among those whose leading monomial divides m, the
// shortest (fewest terms: the cheapest step, and the one that grows the remainder
// least). nullptr when none divides.
template <class P, class Ring>
const BasicReducer<P>* find_reducer(const Ring& ring, const std::int32_t* m,
                                    const std::vector<BasicReducer<P>>& reducers) {
  const std::uint64_t not_mask = ~ring.divisor_mask(m);
  const BasicReducer<P>* best = nullptr;
  for (const auto& r : reducers) {
    if ((r.mask & not_mask) != 0) continue;
    if (!ring.divides(r.polynomial->monomials.data(), m)) continue;
    if (best == nullptr || r.polynomial->size() < best->polynomial->size()) best = &r;
  }
  return best;
}

}  // namespace implicitizer::detail
