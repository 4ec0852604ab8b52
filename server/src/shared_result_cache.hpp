#pragma once
/// \file
/// The second tier of the result cache, shared by replicas: a body computed on one
/// replica answers the same request on every other. Looked up by the worker that
/// would compute (never on a network thread: it is a round trip), after the replica's
/// own LRU missed; filled after every successful computation. A cache only: a tier
/// that cannot answer is a miss, never an error, and never holds a request past its
/// deadline: its round trips run on threads of the tier's own, and a lookup that has
/// not answered when the request's time is up is abandoned.

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "implicitizer/core/budget.hpp"
#include "redis_connection.hpp"
#include "worker_pool.hpp"

namespace implicitizer::server {

/// A result cache shared by several servers.
class SharedResultCache {
 public:
  virtual ~SharedResultCache() = default;
  /// The body stored under `key`, or nullopt (also when the tier cannot answer, or
  /// not soon: a slow tier must not cost a request more than computing might).
  /// Throws LimitExceeded (time, naming the shared result cache lookup) when
  /// `budget`'s deadline passes while it waits, or (cancelled) when the budget is.
  virtual std::optional<std::string> find(const std::string& key, const Budget& budget) = 0;
  /// Stores `body` under `key` later, on the tier's own thread: returns at once
  /// (silently skipped when the tier cannot answer or has too many stores pending).
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
  std::optional<std::string> find(const std::string& key, const Budget& budget) override;
  void insert(const std::string& key, const std::string& body) override;

  /// Threads that talk to Redis, and how many calls may wait for them: a Redis that
  /// stops answering fills the queue, and later lookups are misses at once.
  static constexpr unsigned kCallThreads = 2;
  /// How long a lookup waits for Redis before it counts as a miss: far above a round
  /// trip to a Redis in the same network, and short enough that a Redis that stalls
  /// (DEBUG SLEEP, a failover) adds next to nothing to a request.
  static constexpr std::chrono::milliseconds kLookupWait{30};
  static constexpr std::size_t kPendingCalls = 64;

 private:
  const std::chrono::seconds ttl_;
  // Shared with the calls in flight: one abandoned by its lookup may outlive this.
  std::shared_ptr<RedisConnection> redis_;
  WorkerPool calls_;
};

}  // namespace implicitizer::server
