// Tests of lib/include/implicitizer/modular/one_per_thread.hpp: every job runs once,
// the lowest-numbered error is rethrown, and workers that do FLINT big-integer
// arithmetic (whose per-thread caches they free as they end) leave FLINT usable: a
// second batch, on new threads and on the calling one, computes the same. The leak
// the freeing prevents is LeakSanitizer's to see (scripts/fuzz.sh).

#include "implicitizer/modular/one_per_thread.hpp"

#include <flint/fmpz.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace implicitizer {
namespace {

// (i + 2)^400 mod 1000003, through a 400-digit fmpz and fmpz's freed-integer cache.
unsigned long big_power_residue(std::size_t i) {
  fmpz_t a, b;
  fmpz_init_set_ui(a, i + 2);
  fmpz_init(b);
  fmpz_pow_ui(b, a, 400);
  const unsigned long r = fmpz_fdiv_ui(b, 1000003);
  fmpz_clear(a);
  fmpz_clear(b);
  return r;
}

TEST(RunOnePerThread, WorkersUsingFlintIntegersTwiceGiveTheSameResults) {
  std::vector<unsigned long> first(4), second(4);
  run_one_per_thread(4, [&](std::size_t i) { first[i] = big_power_residue(i); });
  run_one_per_thread(4, [&](std::size_t i) { second[i] = big_power_residue(i); });
  for (std::size_t i = 0; i < 4; ++i) {
    fmpz_t a;
    fmpz_init_set_ui(a, i + 2);
    fmpz_pow_ui(a, a, 400);
    EXPECT_EQ(first[i], fmpz_fdiv_ui(a, 1000003)) << i;
    fmpz_clear(a);
  }
  EXPECT_EQ(first, second);
}

TEST(RunOnePerThread, TheLowestNumberedErrorIsRethrown) {
  std::vector<int> ran(3, 0);
  try {
    run_one_per_thread(3, [&](std::size_t i) {
      ran[i] = 1;
      if (i > 0) throw std::runtime_error("job " + std::to_string(i));
    });
    FAIL() << "no error rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "job 1");
  }
  EXPECT_EQ(ran, (std::vector<int>{1, 1, 1}));
}

}  // namespace
}  // namespace implicitizer
