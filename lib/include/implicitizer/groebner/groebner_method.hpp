#pragma once
/// \file
/// Which algorithm computes a Gröbner basis or an elimination, and the one policy
/// that chooses between them (`auto`): Buchberger's algorithm over ℚ first, within a
/// head start measured in work, then the proven modular computation with F4 modulo
/// each prime (modular_groebner.hpp, f4.hpp). Buchberger answers the small ideals a
/// user types at once; the modular route wins on the ones whose coefficients swell,
/// and F4 beats Buchberger modulo p on every ideal measured past the head start
/// (docs/algorithms.md).

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/groebner/elimination.hpp"
#include "implicitizer/groebner/modular_groebner.hpp"
#include "implicitizer/polynomial/monomial_order.hpp"

namespace implicitizer {

/// The algorithms a caller may ask for.
enum class GroebnerMethod {
  automatic,   ///< buchberger within kBuchbergerHeadStartMs of work, then f4
  buchberger,  ///< Buchberger's algorithm over ℚ (buchberger.hpp)
  modular,     ///< modulo primes by Buchberger's algorithm, lifted and proven over ℚ (modular_groebner.hpp)
  f4,          ///< modulo primes by F4 (f4.hpp), lifted and proven over ℚ the same way
};

/// How long `auto` lets Buchberger's algorithm over ℚ run before it switches to the
/// modular computation, in milliseconds of Buchberger's work
/// (buchberger_work_of_milliseconds: the same allowance on every run, loaded or not).
/// Short since F4 has a trace and the proof is by matrices: every ideal measured that
/// needed more work than this was answered sooner by F4 (docs/algorithms.md, "F4
/// modulo primes", `auto`'s rule).
inline constexpr double kBuchbergerHeadStartMs = 5;

/// Whether the modular routes prove their answer. Buchberger's algorithm over ℚ is
/// exact either way.
enum class GroebnerProof {
  exact,          ///< proven over ℚ (modular_groebner.hpp): the default
  random_primes,  ///< not proven: checked modulo kUnprovenRandomChecks random primes, and labelled so
};

/// The random primes an unproven modular answer must agree with: a wrong answer
/// passes all of them with probability at most (b/3.3·10^18)^2, b the bits of an
/// integer fixed by the ideal (modular_groebner.hpp; docs/algorithms.md, "The
/// unproven mode").
inline constexpr std::size_t kUnprovenRandomChecks = 2;

/// Parses `auto`, `buchberger`, `modular` and `f4`; throws InputError `unknown_method`
/// (field "method") otherwise.
GroebnerMethod parse_groebner_method(const std::string& name);

/// "auto", "buchberger", "modular" or "f4".
const char* to_string(GroebnerMethod method);

/// Parses `exact` and `random_primes`; throws InputError `unknown_proof` (field
/// "proof") otherwise.
GroebnerProof parse_groebner_proof(const std::string& name);

/// "exact" or "random_primes".
const char* to_string(GroebnerProof proof);

/// What answered a computation by method: `buchberger`, `modular` or `f4` (never
/// `automatic`), with the modular computation's counters when one of the modular
/// routes answered.
struct GroebnerRoute {
  GroebnerMethod method = GroebnerMethod::buchberger;
  std::optional<ModularGroebnerStats> modular;

  /// Whether the answer is exact: Buchberger's over ℚ always, a modular route's when
  /// it was proven.
  bool proven() const { return !modular || modular->proven; }
};

/// The reduced Gröbner basis of `generators` (compute_groebner_basis or
/// compute_groebner_basis_modular, proven unless `proof` says otherwise) by `method`.
/// With `automatic` only the head start's work allowance hands over to the modular
/// route (try_within): the caller's deadline, memory, term limit and cancellation
/// stop both and propagate. `route`, if given, says what answered (its modular stats
/// say whether the answer was proven). Throws what the chosen algorithms throw.
GroebnerResult compute_groebner_basis_by_method(std::span<const Polynomial> generators, GroebnerMethod method,
                                                const BuchbergerParams& params, GroebnerRoute* route = nullptr,
                                                GroebnerProof proof = GroebnerProof::exact);

/// eliminate() or eliminate_modular() by `method`, chosen as in
/// compute_groebner_basis_by_method().
EliminationResult eliminate_by_method(std::span<const Polynomial> generators, std::span<const std::string> eliminate,
                                      GroebnerMethod method, const BuchbergerParams& params,
                                      const MonomialOrder& remaining_order = MonomialOrder::grevlex(),
                                      GroebnerRoute* route = nullptr, GroebnerProof proof = GroebnerProof::exact);

}  // namespace implicitizer
