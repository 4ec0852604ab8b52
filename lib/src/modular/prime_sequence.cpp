#include "implicitizer/modular/prime_sequence.hpp"

#include <flint/ulong_extras.h>

#include <map>
#include <mutex>
#include <vector>

namespace implicitizer {

namespace {

// The primes found so far after each start. A handful of starts occur (the skips of
// the routes, and the small starts of tests), each with at most a few thousand primes.
std::mutex cache_mutex;
std::map<std::uint64_t, std::vector<std::uint64_t>> cache;

}  // namespace

PrimeSequence::PrimeSequence(std::uint64_t skip) : start_((std::uint64_t{1} << 62) + (skip << 40)) {}

PrimeSequence PrimeSequence::from(std::uint64_t start) {
  PrimeSequence sequence;
  sequence.start_ = start;
  return sequence;
}

std::uint64_t PrimeSequence::next() {
  const std::lock_guard<std::mutex> lock(cache_mutex);
  std::vector<std::uint64_t>& primes = cache[start_];
  while (primes.size() <= taken_) primes.push_back(n_nextprime(primes.empty() ? start_ : primes.back(), /*proved=*/1));
  return primes[taken_++];
}

std::uint64_t ResidueStream::next(std::uint64_t modulus) {
  // splitmix64: a full-period 64-bit generator with good mixing.
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return z % modulus;
}

}  // namespace implicitizer
