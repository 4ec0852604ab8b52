#pragma once
/// \file
/// Chinese remaindering of a vector of numbers across word-size primes, with rational
/// reconstruction: the one lift behind the modular determinant (integers), the modular
/// Gröbner basis (an element's coefficients) and interpolation (a kernel vector).
///
/// What the callers keep, because only they know the structure of an image: which
/// primes are unlucky (a vanishing minor, other leading monomials, another lead
/// column; the caller drops the image or starts a new lift), and how a lifted answer
/// is confirmed (agreement on a prime not used, a proof, a substitution).

#include <cstddef>
#include <span>
#include <vector>

#include "implicitizer/core/rational.hpp"
#include "implicitizer/modular/flint_handles.hpp"

namespace implicitizer {

/// How CrtLift::reconstruct() accepts a rational.
struct CrtLiftParams {
  /// Bits to spare. A value n/d is taken from its residue a modulo M (the product of
  /// the primes) when it is the only rational with |n|, d ≤ √(M / 2^(margin_bits+1))
  /// congruent to a (Wang's reconstruction). With 0 this is Wang's bound √(M/2):
  /// the value is unique, but a residue that is not yet the image of a small rational
  /// reconstructs to some rational more often than not, so the caller must confirm
  /// the values on a prime not used. With m > 0 such a residue passes with
  /// probability about 2^-m; the next prime refutes it unless it happens to agree
  /// (probability 1/p).
  std::size_t margin_bits = 0;
  /// Whether the entries are one vector divided by one of its entries (a normalized
  /// kernel vector), so that every denominator divides one integer. Then a value is
  /// also taken from a when a·L has a symmetric residue margin_bits shorter than M,
  /// L the lcm of the denominators a later prime confirmed (a multiple of all of them
  /// once one is known); and when entries are still missing, a trial L (the lcm of
  /// every denominator found) is tried for all of them at once. This is what lifts a
  /// vector with a small leading coefficient and large other ones from fewer primes
  /// than the balanced bound needs. Requires margin_bits > 0: with none, every
  /// residue would pass.
  bool shared_denominator = false;
};

/// A vector of numbers known by their residues modulo a growing product M of
/// distinct primes. Each entry is kept as the integer in (−M/2, M/2] with those
/// residues, and, once reconstruct() found one, as a rational value that every
/// later prime checks: a value a prime refutes is dropped and reconstructed again.
/// A value that survives is what a reconstruction from scratch would give (the
/// rational below the bound is unique and the bound only grows), so keeping it
/// changes no answer and saves the work. Once a later prime confirmed a value, the
/// value stands for the integer: the next primes are not folded into it (most of
/// the work of a lift whose entries settle at different primes), and the integer is
/// computed from the value when asked for or when a prime refutes the value.
class CrtLift {
 public:
  /// `size` entries, no prime yet (M = 1). Throws std::invalid_argument when
  /// shared_denominator is asked without a margin.
  explicit CrtLift(std::size_t size, CrtLiftParams params = {});
  CrtLift(const CrtLift&) = delete;
  CrtLift& operator=(const CrtLift&) = delete;
  CrtLift(CrtLift&&) noexcept = default;
  CrtLift& operator=(CrtLift&&) noexcept = default;

  /// The number of entries.
  std::size_t size() const { return residues_.size(); }
  /// The number of primes added.
  std::size_t primes() const { return primes_; }
  /// The bits of M.
  std::size_t modulus_bits() const;

  /// Adds the image modulo `p`, a prime below 2^63 not added before (the update uses
  /// Shoup's multiplication, which needs the top bit clear): residues[i] ∈ [0, p) is
  /// entry i modulo p. Drops the rational values p refutes. Returns whether any
  /// entry's integer (integer()) changed: false means every integer agrees with p
  /// (an entry whose confirmed value is not an integer counts as changed).
  /// Throws std::invalid_argument when the sizes differ or p ≥ 2^63.
  bool add(std::span<const mp_limb_t> residues, mp_limb_t p);

  /// Grows to `new_size` entries: entry i moves to positions[i] (increasing, below
  /// new_size) with its value; the new entries are 0 modulo every prime so far (a
  /// coefficient that no image had) and have no value.
  void spread(std::span<const std::size_t> positions, std::size_t new_size);

  /// Entry i as the integer in (−M/2, M/2] congruent to its residues.
  Integer integer(std::size_t i) const;

  /// Gives every entry without a value one, by the rules of CrtLiftParams; returns
  /// whether every entry has one. Without shared_denominator it stops at the first
  /// entry that has none (nothing could use the later ones).
  bool reconstruct();

  /// The lcm L of the values' denominators. Precondition: reconstruct() returned true.
  Integer common_denominator() const;
  /// The values times common_denominator(): integers. Precondition: reconstruct()
  /// returned true.
  std::vector<Integer> integer_values() const;

 private:
  void check_values(std::span<const mp_limb_t> residues, mp_limb_t p);
  // The integer in (−M/2, M/2] congruent to entry i's confirmed value.
  void value_modulo(std::size_t i, fmpz_t out) const;
  bool reconstruct_entry(std::size_t i);
  bool reconstruct_with_trial_denominator();
  Fmpz lcm_of_denominators() const;

  CrtLiftParams params_;
  std::vector<Fmpz> residues_;  // symmetric, in (−M/2, M/2]
  std::vector<Fmpq> values_;
  std::vector<char> known_;      // values_[i] holds a value
  std::vector<char> confirmed_;  // ... that a later prime agreed with: it stands for residues_[i],
                                 // which no prime is folded into from then on
  std::size_t primes_ = 0;
  Fmpz modulus_;      // M
  Fmpz denominator_;  // L: the lcm of the confirmed values' denominators
  Fmpz bound_;        // √(M / 2^(margin_bits+1))
  Fmpz scratch_;
};

}  // namespace implicitizer
