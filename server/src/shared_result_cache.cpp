#include "shared_result_cache.hpp"

#include <iostream>

namespace implicitizer::server {

namespace {

std::string cache_key(const std::string& key) { return "implicitizer:cache:" + key; }

void report(const std::exception& e) {
  std::cerr << std::string("implicitizer-server: shared result cache: ") + e.what() + " (treated as a miss)\n"
            << std::flush;
}

}  // namespace

RedisResultCache::RedisResultCache(std::string host, int port, std::chrono::seconds ttl)
    : ttl_(ttl), redis_(std::move(host), port) {}

std::optional<std::string> RedisResultCache::find(const std::string& key) {
  try {
    const RedisConnection::Reply reply = redis_.command({"GET", cache_key(key)});
    if (reply->type != REDIS_REPLY_STRING) return std::nullopt;
    return std::string(reply->str, reply->len);
  } catch (const std::exception& e) {
    report(e);
    return std::nullopt;
  }
}

void RedisResultCache::insert(const std::string& key, const std::string& body) {
  try {
    redis_.command({"SET", cache_key(key), body, "EX", std::to_string(ttl_.count())});
  } catch (const std::exception& e) {
    report(e);
  }
}

}  // namespace implicitizer::server
