#include "shared_result_cache.hpp"

#include <algorithm>
#include <future>
#include <iostream>

namespace implicitizer::server {

namespace {

std::string cache_key(const std::string& key) { return "implicitizer:cache:" + key; }

void report(const std::string& address, const std::string& what) {
  std::cerr << "implicitizer-server: shared result cache " + address + ": " + what + "\n" << std::flush;
}

}  // namespace

RedisResultCache::RedisResultCache(std::string host, int port, std::chrono::seconds ttl)
    : ttl_(ttl),
      redis_(std::make_shared<RedisConnection>(std::move(host), port)),
      calls_(kCallThreads, kPendingCalls) {}

std::optional<std::string> RedisResultCache::find(const std::string& key, const Budget& budget) {
  auto answer = std::make_shared<std::promise<std::optional<std::string>>>();
  std::future<std::optional<std::string>> future = answer->get_future();
  WorkerPool::Job call{[redis = redis_, answer, redis_key = cache_key(key)] {
                         try {
                           const RedisConnection::Reply reply = redis->command({"GET", redis_key});
                           if (reply->type != REDIS_REPLY_STRING) return answer->set_value(std::nullopt);
                           answer->set_value(std::string(reply->str, reply->len));
                         } catch (const std::exception& e) {
                           report(redis->address(), std::string(e.what()) + " (treated as a miss)");
                           answer->set_value(std::nullopt);
                         }
                       },
                       Budget()};
  if (!calls_.try_submit(call)) {
    report(redis_->address(), "too many calls waiting for an answer (treated as a miss)");
    return std::nullopt;
  }
  // An unanswered call keeps its thread until Redis answers or times out; nobody
  // waits for it.
  const auto give_up = std::chrono::steady_clock::now() + kLookupWait;
  for (;;) {
    const std::chrono::duration<double> wait = give_up - std::chrono::steady_clock::now();
    if (wait.count() <= 0) {
      report(redis_->address(), "no answer within " + std::to_string(kLookupWait.count()) + " ms (treated as a miss)");
      return std::nullopt;
    }
    const std::chrono::duration<double> left(budget.seconds_left());
    if (future.wait_for(std::min(wait, left)) == std::future_status::ready) return future.get();
    budget.check("the shared result cache lookup");
  }
}

void RedisResultCache::insert(const std::string& key, const std::string& body) {
  WorkerPool::Job call{[redis = redis_, redis_key = cache_key(key), body, ttl = ttl_] {
                         try {
                           redis->command({"SET", redis_key, body, "EX", std::to_string(ttl.count())});
                         } catch (const std::exception& e) {
                           report(redis->address(), std::string(e.what()) + " (not stored)");
                         }
                       },
                       Budget()};
  (void)calls_.try_submit(call);
}

}  // namespace implicitizer::server
