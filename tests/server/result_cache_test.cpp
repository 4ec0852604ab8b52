#include "result_cache.hpp"

#include <gtest/gtest.h>

namespace implicitizer::server {
namespace {

TEST(ResultCache, FindsWhatWasInsertedAndCountsHitsAndMisses) {
  ResultCache cache(2);
  EXPECT_EQ(cache.find("a"), nullptr);
  cache.insert("a", "body a");
  const auto found = cache.find("a");
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(*found, "body a");
  EXPECT_EQ(cache.hits(), 1u);
  EXPECT_EQ(cache.misses(), 1u);
  EXPECT_EQ(cache.size(), 1u);
}

TEST(ResultCache, EvictsTheLeastRecentlyUsed) {
  ResultCache cache(2);
  cache.insert("a", "A");
  cache.insert("b", "B");
  ASSERT_NE(cache.find("a"), nullptr);  // a is now more recent than b
  cache.insert("c", "C");
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.find("b"), nullptr);
  EXPECT_NE(cache.find("a"), nullptr);
  EXPECT_NE(cache.find("c"), nullptr);
  EXPECT_EQ(cache.evictions(), 1u);
}

TEST(ResultCache, ReinsertingReplacesWithoutGrowing) {
  ResultCache cache(2);
  cache.insert("a", "old");
  cache.insert("a", "new");
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(*cache.find("a"), "new");
}

TEST(ResultCache, CapacityZeroStoresNothing) {
  ResultCache cache(0);
  cache.insert("a", "A");
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(cache.find("a"), nullptr);
}

TEST(ResultCache, AnEntryHandedOutSurvivesEviction) {
  ResultCache cache(1);
  cache.insert("a", "A");
  const auto held = cache.find("a");
  cache.insert("b", "B");
  ASSERT_NE(held, nullptr);
  EXPECT_EQ(*held, "A");
}

}  // namespace
}  // namespace implicitizer::server
