#pragma once
/// \file
/// Primes drawn uniformly at random from [2^61, 2^62), for checks whose worth rests on
/// the prime being unknown in advance: a fixed nonzero integer N has at most
/// log2(N)/61 prime factors in that range, which holds about 5.4·10^16 primes, so a
/// prime drawn uniformly divides N with probability at most log2(N)/(3.3·10^18). The
/// reproducible PrimeSequence cannot say that: an input can be built against it.

#include <cstdint>
#include <random>

namespace implicitizer {

/// A source of independent uniformly random primes of exactly 62 bits, seeded from
/// the operating system's entropy (std::random_device).
class RandomPrimes {
 public:
  RandomPrimes();
  /// The next prime: odd numbers of the range drawn uniformly until one is prime
  /// (every prime equally likely; about 21 draws on average).
  std::uint64_t next();

 private:
  std::mt19937_64 engine_;
};

}  // namespace implicitizer
