#pragma once
/// \file
/// The whole service assembled: metrics, cache, worker pool, router, network threads
/// and listener, with the shutdown order that lets in-flight answers go out.

#include <boost/asio/io_context.hpp>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "access_log.hpp"
#include "config.hpp"
#include "jobs/job_manager.hpp"
#include "listener.hpp"
#include "metrics_registry.hpp"
#include "result_cache.hpp"
#include "router.hpp"
#include "worker_pool.hpp"

namespace implicitizer::server {

/// The exit status of a process that Server::stop() ended because computations
/// did not stop after their cancellation (docs/api.md, "Shutdown").
constexpr int kExitComputationsDidNotStop = 3;

/// A running implicitizer-server. Construction binds the port and starts the
/// workers and network threads; stop() (or destruction) shuts down.
class Server {
 public:
  /// Starts serving with `config`. Throws boost::system::system_error when the address
  /// cannot be bound or resolved, UsageError when the static directory does not exist.
  explicit Server(ServerConfig config);
  /// stop(), if not done yet.
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// The port bound (the system's choice when the config asked for 0).
  unsigned short port() const { return port_; }

  /// Graceful shutdown: stops accepting, cancels the running jobs at once (a
  /// persistent store queues them again at the next start: no grace would be long
  /// enough for an hour's job), lets in-flight computations finish for the
  /// configured grace and cancels the rest, gives their answers a moment to be
  /// written, then stops the network threads. Idempotent. Returns within the grace
  /// plus kStopAfterCancel (and the time to join the network threads).
  ///
  /// If a cancelled computation has not stopped within kStopAfterCancel (a loop
  /// that never checks its budget), stop() writes one line to stderr saying how many
  /// did not stop and ends the process with std::_Exit(kExitComputationsDidNotStop):
  /// their jobs refer to this Server's sessions, network loop and cache, so neither
  /// returning (the Server would be destroyed under them) nor waiting (perhaps
  /// forever) is safe.
  void stop();

  /// How long stop() waits, after cancelling, for the computations to stop and for
  /// their answers to be written.
  static constexpr std::chrono::milliseconds kStopAfterCancel{1000};

  /// Threads that answer the jobs API's store calls, and how many calls may wait
  /// for them (more: 503 `overloaded`). Two, so that one call stuck on a locked store
  /// does not make a call that could answer wait behind it at once; few, since the
  /// stores serialize their calls anyway.
  static constexpr unsigned kStoreThreads = 2;
  static constexpr std::size_t kStoreQueueCapacity = 64;

 private:
  ServerConfig config_;
  MetricsRegistry metrics_;
  ResultCache cache_;
  WorkerPool pool_;
  std::unique_ptr<SharedResultCache> shared_cache_;  // null unless --store redis://
  JobManager jobs_;
  // The jobs API's store calls (StoreCall): off the network threads, apart from the
  // computations. Declared after jobs_, which its calls use.
  WorkerPool store_pool_;
  Router router_;
  AccessLog log_;
  SessionContext session_context_;
  boost::asio::io_context io_;
  std::shared_ptr<Listener> listener_;
  std::vector<std::thread> io_threads_;
  unsigned short port_ = 0;
  bool stopped_ = false;
};

}  // namespace implicitizer::server
