#pragma once
/// \file
/// One connection to a Redis server (Debian's libhiredis), shared by threads: each
/// command is sent and answered under a mutex, and a lost connection is opened again
/// once per command. What the Redis job store and the shared result cache speak.

#include <hiredis/hiredis.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace implicitizer::server {

/// A thread-safe Redis connection.
class RedisConnection {
 public:
  struct ReplyDeleter {
    void operator()(redisReply* reply) const { freeReplyObject(reply); }
  };
  /// A reply, freed with it.
  using Reply = std::unique_ptr<redisReply, ReplyDeleter>;

  /// Connects to `host`:`port` and checks that it answers PING. Throws
  /// std::runtime_error when it cannot.
  RedisConnection(std::string host, int port);

  /// Sends `args` (binary-safe) and returns the reply. Throws std::runtime_error,
  /// whose message starts with address(), for a Redis error reply or when neither the
  /// connection nor a fresh one answers (so a blocked call lasts up to twice
  /// kCommandTimeout).
  Reply command(const std::vector<std::string>& args);

  /// EVAL of `script` with `keys` and `args`: the reply's integer (anything else: 0).
  long long eval_integer(const std::string& script, const std::vector<std::string>& keys,
                         const std::vector<std::string>& args);

  /// How long one command may wait for its answer before the connection is
  /// considered broken (and the command tried once more on a new one).
  static constexpr std::chrono::seconds kCommandTimeout{5};

  /// `redis://HOST:PORT`, for messages.
  std::string address() const { return "redis://" + host_ + ":" + std::to_string(port_); }

 private:
  struct ContextDeleter {
    void operator()(redisContext* context) const { redisFree(context); }
  };
  void connect();  // with mutex_ held
  // Why a command got no reply: "timeout (...)" or hiredis's error text.
  static std::string describe_failure(const redisContext& context);

  const std::string host_;
  const int port_;
  std::mutex mutex_;
  std::unique_ptr<redisContext, ContextDeleter> context_;
};

/// The host and port of `redis://HOST:PORT` (checked by parse_server_flags).
std::pair<std::string, int> parse_redis_address(const std::string& url);

}  // namespace implicitizer::server
