#pragma once
/// \file
/// One client connection: read → route → (compute on the pool) → write → read, in
/// Beast's do_x/on_x style. Transport only: what to answer is the router's business.
///
/// Limits enforced here: a read timeout armed before every read (slow or idle clients
/// are dropped), header and body limits on every parser (431 / 413), a request cap
/// per connection, a write timeout. The header is read first, so that a request with
/// `Expect: 100-continue` gets its interim `100 Continue` (or, when its declared body
/// is too large, the 413 at once) before the client sends the body. A computation whose deadline passes while it
/// waits for a worker is taken back from the pool and answered 504 at its deadline.
/// A StoreCall runs on the store executor; the session writes when its answer comes
/// back, as it does for a computation. While a computation runs the session waits for
/// the socket to become readable: end of stream means the client left, and the
/// computation's budget is cancelled. An event stream (GET /v1/jobs/{id}/events) is
/// written piece by piece, polled on a timer on this connection's strand (each poll
/// read on the store executor), and ends the connection.

#include <array>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <memory>
#include <optional>
#include <string>

#include "access_log.hpp"
#include "config.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "metrics_registry.hpp"
#include "router.hpp"
#include "worker_pool.hpp"

namespace implicitizer::server {

/// What every session shares; outlives all sessions.
struct SessionContext {
  const ServerConfig& config;
  const Router& router;
  WorkerPool& pool;
  WorkerPool& store_pool;  ///< runs StoreCalls (the jobs API's store work)
  MetricsRegistry& metrics;
  AccessLog& log;
};

/// An HTTP/1.1 connection. Owned by the handlers it has in flight (shared_from_this).
class Session : public std::enable_shared_from_this<Session> {
 public:
  /// Takes over `socket`, whose executor must be a strand (the listener makes one).
  Session(boost::asio::ip::tcp::socket&& socket, const SessionContext& context);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  /// Starts reading the first request.
  void run();

 private:
  void do_read();
  void on_read_header(boost::beast::error_code ec, std::size_t bytes);
  void on_continue_written(boost::beast::error_code ec, std::size_t bytes);
  void do_read_body();
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  void handle(Request request);
  void compute(const Request& request, Computation computation);
  void wait_for_worker_deadline();
  void on_worker_deadline(boost::beast::error_code ec);
  void call_store(const Request& request, StoreCall call);
  void on_store_answered(StoreAnswer answer);
  void watch_for_disconnect();
  void on_readable(boost::beast::error_code ec);
  void on_computed(Response response);
  void send(Response response);
  void on_write(boost::beast::error_code ec, std::size_t bytes);
  void stream_events(EventStream stream);
  void on_events_head_written(boost::beast::error_code ec, std::size_t bytes);
  void wait_for_event();
  void on_event_due(boost::beast::error_code ec);
  void on_event_read(std::string piece, bool last);
  void on_event_written(boost::beast::error_code ec, std::size_t bytes);
  void reject(http::status status, std::string_view code, std::string_view message);
  void do_close();
  void drain();
  void log_request(unsigned status, std::size_t bytes);

  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  const SessionContext& context_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::shared_ptr<Response> response_;  // alive until its write completes
  unsigned requests_ = 0;

  // The request being answered, for the log and metrics.
  std::string method_;
  std::string path_;
  std::string endpoint_ = "other";
  Stopwatch since_read_;  // restarted when a request has been read: its time for the log and metrics

  // The computation in flight, if any.
  bool computing_ = false;
  bool client_gone_ = false;
  Budget budget_;
  WorkerPool::Ticket ticket_ = 0;
  // Fires at the computation's deadline: if it is still queued then, it is withdrawn
  // and answered 504 at once instead of when a worker frees up.
  std::optional<boost::asio::steady_timer> deadline_timer_;

  // The event stream being written, if any.
  std::optional<EventStream> events_;
  std::optional<http::response_serializer<http::string_body>> events_head_;
  std::optional<boost::asio::steady_timer> events_timer_;
  std::string event_;  // the piece being written
  bool last_event_ = false;
  std::size_t event_bytes_ = 0;

  std::string peer_;  // the client's address, for per-client limits

  std::array<char, 4096> drain_buffer_{};
  std::size_t drained_ = 0;
};

}  // namespace implicitizer::server
