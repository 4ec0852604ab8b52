#include "implicitizer/modular/prime_sequence.hpp"

#include <flint/ulong_extras.h>

namespace implicitizer {

PrimeSequence::PrimeSequence(std::uint64_t skip) : current_((std::uint64_t{1} << 62) + (skip << 40)) {}

PrimeSequence PrimeSequence::from(std::uint64_t start) {
  PrimeSequence sequence;
  sequence.current_ = start;
  return sequence;
}

std::uint64_t PrimeSequence::next() {
  current_ = n_nextprime(current_, /*proved=*/1);
  return current_;
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
