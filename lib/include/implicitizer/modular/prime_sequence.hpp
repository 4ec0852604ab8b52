#pragma once
/// \file
/// The word-size primes that modular algorithms work with, in a fixed order so that
/// runs are reproducible, and helpers for arithmetic modulo one of them.

#include <cstddef>
#include <cstdint>

namespace implicitizer {

/// Primes just above 2^62, increasing. 62-bit primes leave FLINT's nmod arithmetic
/// its fast paths and make an accidental zero (an unlucky prime or evaluation point)
/// about as likely as a hardware fault: the chance that a fixed non-zero value
/// vanishes modulo a random such prime is below 2^-55.
class PrimeSequence {
 public:
  /// Starts above 2^62 + `skip`·2^40; different `skip` values give disjoint,
  /// still reproducible sequences (tests force other primes this way).
  explicit PrimeSequence(std::uint64_t skip = 0);
  /// Starts just above `start` (any value ≥ 2); lets tests use small primes.
  static PrimeSequence from(std::uint64_t start);
  /// The next prime of the sequence. The primes of each start are found once per
  /// process (n_nextprime with a proof costs a few microseconds each, as much as a
  /// whole modular image of a small surface) and shared by every sequence with that
  /// start, from any thread.
  std::uint64_t next();

 private:
  std::uint64_t start_;
  std::size_t taken_ = 0;
};

/// A reproducible stream of pseudo-random residues (splitmix64), for evaluation
/// points. Not for cryptography: only the independence from the input matters.
class ResidueStream {
 public:
  /// A stream determined by `seed`.
  explicit ResidueStream(std::uint64_t seed) : state_(seed) {}
  /// The next value modulo `modulus` (> 0).
  std::uint64_t next(std::uint64_t modulus);

 private:
  std::uint64_t state_;
};

}  // namespace implicitizer
