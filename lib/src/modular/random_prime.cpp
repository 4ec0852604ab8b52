#include "implicitizer/modular/random_prime.hpp"

#include <flint/ulong_extras.h>

namespace implicitizer {

RandomPrimes::RandomPrimes() {
  std::random_device device;
  std::seed_seq seed{device(), device(), device(), device()};
  engine_.seed(seed);
}

std::uint64_t RandomPrimes::next() {
  constexpr std::uint64_t kLow = std::uint64_t{1} << 61;
  for (;;) {
    // 60 random bits, the top bit of the range and the low bit set: a uniform odd
    // number of [2^61, 2^62).
    const std::uint64_t candidate = kLow | ((engine_() >> 4) << 1) | 1;
    if (n_is_prime(candidate)) return candidate;
  }
}

}  // namespace implicitizer
