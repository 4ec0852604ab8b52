#pragma once
/// \file
/// The second tier of the result cache, shared by replicas: a body computed on one
/// replica answers the same request on every other. Looked up by the worker that
/// would compute (never on a network thread: it is a round trip), after the replica's
/// own LRU missed; filled after every successful computation. A cache only: a tier
/// that cannot answer is a miss, never an error.

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "redis_connection.hpp"

namespace implicitizer::server {

/// A result cache shared by several servers.
class SharedResultCache {
 public:
  virtual ~SharedResultCache() = default;
  /// The body stored under `key`, or nullopt (also when the tier cannot answer).
  virtual std::optional<std::string> find(const std::string& key) = 0;
  /// Stores `body` under `key` (silently skipped when the tier cannot answer).
  virtual void insert(const std::string& key, const std::string& body) = 0;
};

/// Bodies in Redis under `implicitizer:cache:KEY` (the canonical request, whole: no
/// hash, so no two requests can share an entry), each expiring `ttl` after it was
/// stored; Redis's own memory policy bounds the rest.
class RedisResultCache : public SharedResultCache {
 public:
  /// A tier in the Redis at `host`:`port`. Throws std::runtime_error when it cannot
  /// be reached at start.
  RedisResultCache(std::string host, int port, std::chrono::seconds ttl);
  std::optional<std::string> find(const std::string& key) override;
  void insert(const std::string& key, const std::string& body) override;

 private:
  const std::chrono::seconds ttl_;
  RedisConnection redis_;
};

}  // namespace implicitizer::server
