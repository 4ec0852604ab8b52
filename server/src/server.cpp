#include "server.hpp"

#include <boost/asio/ip/address.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace implicitizer::server {

namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

tcp::endpoint resolve_endpoint(net::io_context& io, const std::string& host, unsigned short port) {
  boost::system::error_code ec;
  const net::ip::address address = net::ip::make_address(host, ec);
  if (!ec) return {address, port};
  tcp::resolver resolver(io);
  const auto results = resolver.resolve(host, std::to_string(port), tcp::resolver::passive);
  return results.begin()->endpoint();
}

HandlerContext make_handler_context(const ServerConfig& config, ResultCache& cache, MetricsRegistry& metrics,
                                    const WorkerPool& pool, JobManager& jobs, SharedResultCache* shared_cache) {
  return HandlerContext{config,
                        cache,
                        metrics,
                        [&cache, &pool, &jobs] {
                          MetricsGauges g;
                          g.queue_depth = pool.queued();
                          g.queue_capacity = pool.queue_capacity();
                          g.workers_busy = pool.busy();
                          g.workers = pool.threads();
                          g.queue_rejections = pool.rejected();
                          g.cache_entries = cache.size();
                          g.cache_capacity = cache.capacity();
                          g.cache_hits = cache.hits();
                          g.cache_misses = cache.misses();
                          g.cache_evictions = cache.evictions();
                          g.jobs_unfinished = jobs.unfinished();
                          return g;
                        },
                        &jobs,
                        shared_cache};
}

// The part of Server::kStopAfterCancel kept for writing the last answers; the rest
// is the workers' time to stop.
constexpr std::chrono::milliseconds kLastWrites{200};

ServerConfig checked(ServerConfig config) {
  if (!config.static_dir.empty() && !std::filesystem::is_directory(config.static_dir)) {
    throw UsageError("--static: '" + config.static_dir + "' is not a directory");
  }
  return config;
}

}  // namespace

Server::Server(ServerConfig config)
    : config_(checked(std::move(config))),
      cache_(config_.cache_capacity),
      pool_(config_.effective_worker_threads(), config_.queue_capacity),
      shared_cache_(make_shared_result_cache(config_)),
      jobs_(config_, make_job_store(config_), cache_, metrics_, shared_cache_.get()),
      store_pool_(kStoreThreads, kStoreQueueCapacity),
      router_(make_handler_context(config_, cache_, metrics_, pool_, jobs_, shared_cache_.get())),
      log_(!config_.quiet),
      session_context_{config_, router_, pool_, store_pool_, metrics_, log_},
      io_(static_cast<int>(config_.io_threads)) {
  listener_ = std::make_shared<Listener>(io_, resolve_endpoint(io_, config_.host, config_.port), session_context_);
  port_ = listener_->local_endpoint().port();
  listener_->run();
  for (unsigned i = 0; i < config_.io_threads; ++i) io_threads_.emplace_back([this] { io_.run(); });
}

Server::~Server() { stop(); }

void Server::stop() {
  if (stopped_) return;
  stopped_ = true;
  listener_->stop();
  // Store calls are short unless the store hangs; one that has not answered by then
  // would use the job manager after it stopped, so it counts as unfinished.
  const std::size_t store_calls_left = store_pool_.shutdown(kLastWrites, kLastWrites);
  const std::size_t jobs_left = jobs_.stop(kStopAfterCancel - kLastWrites) + store_calls_left;
  // Workers finish or are cancelled; each posts its answer to its session's strand,
  // which the still-running network threads write.
  const std::size_t unfinished = pool_.shutdown(config_.shutdown_grace, kStopAfterCancel - kLastWrites) + jobs_left;
  // A short, bounded wait for those last writes; a client that does not read them
  // in this time loses them.
  std::this_thread::sleep_for(kLastWrites);
  if (unfinished > 0) {
    // One write, so that no access-log line of a network thread splits it.
    std::cerr << "implicitizer-server: " + std::to_string(unfinished) + " computation" + (unfinished == 1 ? "" : "s") +
                     " did not stop within " + std::to_string(kStopAfterCancel.count()) +
                     " ms of being cancelled; exiting without them\n"
              << std::flush;
    std::fflush(nullptr);
    std::_Exit(kExitComputationsDidNotStop);
  }
  io_.stop();
  for (std::thread& t : io_threads_) t.join();
}

}  // namespace implicitizer::server
