#pragma once
/// \file
/// A bounded LRU map from a canonical request to the body of its successful answer,
/// so that a repeated request costs a lookup instead of an elimination.

#include <atomic>
#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

namespace implicitizer::server {

/// Thread-safe LRU cache of response bodies. Capacity 0 disables it (every lookup
/// misses, nothing is stored). Hits and misses are counted for /metrics.
class ResultCache {
 public:
  /// A cache holding at most `capacity` entries.
  explicit ResultCache(std::size_t capacity);

  /// The body stored under `key` (and marks it most recently used), or nullptr.
  /// Counts a hit or a miss.
  std::shared_ptr<const std::string> find(const std::string& key);
  /// Stores `body` under `key` as most recently used, evicting the least recently
  /// used entry when full.
  void insert(const std::string& key, std::string body);

  std::size_t size() const;                                      ///< entries held now
  std::size_t capacity() const { return capacity_; }             ///< most entries held
  std::uint64_t hits() const { return hits_.load(); }            ///< lookups that found an entry
  std::uint64_t misses() const { return misses_.load(); }        ///< lookups that did not
  std::uint64_t evictions() const { return evictions_.load(); }  ///< entries dropped for room

 private:
  using Entry = std::pair<std::string, std::shared_ptr<const std::string>>;
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::list<Entry> order_;  // most recently used first
  std::unordered_map<std::string, std::list<Entry>::iterator> index_;
  std::atomic<std::uint64_t> hits_{0};
  std::atomic<std::uint64_t> misses_{0};
  std::atomic<std::uint64_t> evictions_{0};
};

}  // namespace implicitizer::server
