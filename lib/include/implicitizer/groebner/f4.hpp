#pragma once
/// \file
/// Reduced Gröbner bases modulo one word-size prime, by F4 (Faugère 1999: the pairs of
/// one degree reduced together as the rows of a sparse Macaulay matrix) or by the
/// Buchberger engine the rational driver uses. The multi-modular route
/// (modular_groebner.hpp) runs one of them for each prime; this entry point exposes
/// one run so that the two can be compared on the same prime.

#include <cstdint>
#include <span>
#include <vector>

#include "implicitizer/groebner/buchberger.hpp"

namespace implicitizer {

/// Which algorithm computes a reduced basis modulo a prime.
enum class ModularAlgorithm {
  buchberger,  ///< one S-polynomial at a time (buchberger.hpp's engine, modulo p)
  f4,          ///< all pairs of the lowest degree (sugar) at once, in one sparse matrix
};

/// The reduced Gröbner basis of ⟨generators mod p⟩ in their ring's order, each element
/// monic with coefficients the integers in [0, p) (printed as such: the answer lives
/// in (ℤ/p)[vars], written with ℚ's polynomials). The ideal is that of the generators'
/// primitive integer parts reduced modulo p (a term whose coefficient p divides
/// vanishes). Precondition: `prime` is a prime below 2^63. The unit ideal gives {1},
/// the zero ideal {}. `stats`, if given, receives the run's counters (elapsed_ms and
/// basis_size included). Throws LimitExceeded from params.budget.
std::vector<Polynomial> compute_groebner_basis_modulo(std::span<const Polynomial> generators, std::uint64_t prime,
                                                      ModularAlgorithm algorithm,
                                                      const BuchbergerParams& params = BuchbergerParams(),
                                                      BuchbergerStats* stats = nullptr);

}  // namespace implicitizer
