#include "redis_connection.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace implicitizer::server {

RedisConnection::RedisConnection(std::string host, int port) : host_(std::move(host)), port_(port) {
  std::lock_guard lock(mutex_);
  connect();
  // The first command proves the server answers (a closed port fails at connect).
  Reply reply(static_cast<redisReply*>(redisCommand(context_.get(), "PING")));
  if (!reply || reply->type == REDIS_REPLY_ERROR) throw std::runtime_error(address() + " does not answer PING");
}

void RedisConnection::connect() {
  const timeval timeout{2, 0};
  context_.reset(redisConnectWithTimeout(host_.c_str(), port_, timeout));
  if (!context_ || context_->err) {
    const std::string why = context_ ? context_->errstr : "out of memory";
    context_.reset();
    throw std::runtime_error("cannot connect to " + address() + ": " + why);
  }
  const timeval command_timeout{static_cast<time_t>(kCommandTimeout.count()), 0};
  redisSetTimeout(context_.get(), command_timeout);
}

RedisConnection::Reply RedisConnection::command(const std::vector<std::string>& args) {
  std::vector<const char*> argv;
  std::vector<std::size_t> lengths;
  for (const std::string& a : args) {
    argv.push_back(a.data());
    lengths.push_back(a.size());
  }
  std::lock_guard lock(mutex_);
  std::string why;
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (!context_) connect();
    Reply reply(static_cast<redisReply*>(
        redisCommandArgv(context_.get(), static_cast<int>(argv.size()), argv.data(), lengths.data())));
    if (!reply) {  // the connection broke: one fresh connection, one more try
      why = describe_failure(*context_);
      context_.reset();
      continue;
    }
    if (reply->type == REDIS_REPLY_ERROR) {
      throw std::runtime_error(address() + ": error reply: " + std::string(reply->str, reply->len));
    }
    return reply;
  }
  throw std::runtime_error(address() + ": " + why);
}

std::string RedisConnection::describe_failure(const redisContext& context) {
  // hiredis reports its command timeout as a read that would block.
  if (context.err == REDIS_ERR_IO && std::strcmp(context.errstr, std::strerror(EAGAIN)) == 0) {
    return "timeout (no answer within " + std::to_string(kCommandTimeout.count()) + " s, twice)";
  }
  return context.errstr;
}

long long RedisConnection::eval_integer(const std::string& script, const std::vector<std::string>& keys,
                                        const std::vector<std::string>& args) {
  std::vector<std::string> all{"EVAL", script, std::to_string(keys.size())};
  all.insert(all.end(), keys.begin(), keys.end());
  all.insert(all.end(), args.begin(), args.end());
  const Reply reply = command(all);
  return reply->type == REDIS_REPLY_INTEGER ? reply->integer : 0;
}

std::pair<std::string, int> parse_redis_address(const std::string& url) {
  const std::string address = url.substr(url.rfind("redis://", 0) == 0 ? 8 : 0);
  const std::size_t colon = address.rfind(':');
  if (colon == std::string::npos) throw std::runtime_error("not redis://HOST:PORT: " + url);
  return {address.substr(0, colon), std::stoi(address.substr(colon + 1))};
}

}  // namespace implicitizer::server
