// Tests of MemoryAccount and its allocation hooks (lib/src/core/memory_account.cpp):
// what each allocator charges, to which account, and that freeing credits it back.

#include "implicitizer/core/memory_account.hpp"

#include <flint/flint.h>
#include <gmp.h>
#include <gtest/gtest.h>

#include <memory>
#include <thread>
#include <vector>

namespace implicitizer {
namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

class MemoryAccountTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!memory_accounting_enabled()) GTEST_SKIP() << "a sanitizer build counts no allocations";
  }
};

TEST_F(MemoryAccountTest, OperatorNewChargesAndDeleteCredits) {
  MemoryAccount account;
  {
    const MemoryScope scope(&account);
    auto block = std::make_unique<char[]>(3 * kMiB);
    EXPECT_GE(account.bytes(), 3 * kMiB);
    EXPECT_LT(account.bytes(), 3 * kMiB + 64 * 1024);
  }
  EXPECT_LT(account.bytes(), 64u * 1024);
  EXPECT_GE(account.peak_bytes(), 3 * kMiB);
  EXPECT_FALSE(account.exceeded());  // no limit: counting only
}

TEST_F(MemoryAccountTest, GmpAndFlintAllocationsAreCharged) {
  MemoryAccount account;
  const MemoryScope scope(&account);
  mpz_t big;
  mpz_init(big);
  mpz_ui_pow_ui(big, 10, 2'000'000);  // about 830 KB of limbs
  EXPECT_GE(account.bytes(), 800u * 1024);
  mpz_clear(big);
  EXPECT_LT(account.bytes(), 64u * 1024);

  void* block = flint_malloc(2 * kMiB);
  EXPECT_GE(account.bytes(), 2 * kMiB);
  block = flint_realloc(block, 4 * kMiB);
  EXPECT_GE(account.bytes(), 4 * kMiB);
  EXPECT_LT(account.bytes(), 5 * kMiB);
  flint_free(block);
  EXPECT_LT(account.bytes(), 64u * 1024);
}

TEST_F(MemoryAccountTest, ScopesNestAndRestore) {
  MemoryAccount outer, inner;
  const MemoryScope a(&outer);
  EXPECT_EQ(current_memory_account(), &outer);
  {
    const MemoryScope b(&inner);
    EXPECT_EQ(current_memory_account(), &inner);
    std::vector<char> block(2 * kMiB);
    EXPECT_GE(inner.bytes(), 2 * kMiB);
    EXPECT_LT(outer.bytes(), kMiB);
  }
  EXPECT_EQ(current_memory_account(), &outer);
  {
    const MemoryScope none(nullptr);
    std::vector<char> block(2 * kMiB);
    EXPECT_LT(outer.bytes(), kMiB);
  }
}

TEST_F(MemoryAccountTest, TheLimitMarksTheAccountExceeded) {
  MemoryAccount account(2 * kMiB);
  const MemoryScope scope(&account);
  std::vector<std::vector<char>> blocks;
  for (int i = 0; i < 16; ++i) blocks.emplace_back(100 * 1024);
  EXPECT_FALSE(account.exceeded());
  for (int i = 0; i < 16; ++i) blocks.emplace_back(100 * 1024);
  EXPECT_TRUE(account.exceeded());
  blocks.clear();
  EXPECT_TRUE(account.exceeded());  // sticky: the computation stops at its next check
}

TEST_F(MemoryAccountTest, AnotherThreadChargesOnlyWhenAttached) {
  MemoryAccount account;
  std::thread unattached([] { std::vector<char> block(4 * kMiB); });
  unattached.join();
  EXPECT_EQ(account.bytes(), 0u);
  std::size_t seen = 0;
  std::thread attached([&] {
    const MemoryScope scope(&account);
    std::vector<char> block(4 * kMiB);
    seen = account.bytes();
  });
  attached.join();
  EXPECT_GE(seen, 4 * kMiB);
  EXPECT_GE(account.peak_bytes(), 4 * kMiB);
}

TEST(ReleaseFreeMemory, OnlyAfterALargePeak) {
  EXPECT_FALSE(release_free_memory(kMiB, 64 * kMiB));
  EXPECT_TRUE(release_free_memory(128 * kMiB, 64 * kMiB));
}

}  // namespace
}  // namespace implicitizer
