#include "session.hpp"

#include <sys/socket.h>

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/write.hpp>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string_view>

namespace implicitizer::server {

namespace beast = boost::beast;
namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

// After an answer that ends the connection, read and discard what the client still
// sends for this long (or this much), so that closing does not reset the connection
// before the client has read the answer (the classic lingering close).
constexpr std::chrono::milliseconds kLingerTime{1000};
constexpr std::size_t kLingerBytes = 4 << 20;

bool is_http_error(const beast::error_code& ec) { return std::strcmp(ec.category().name(), "beast.http") == 0; }

// RFC 9110 section 10.1.1: a client that sends `Expect: 100-continue` may wait for
// this interim answer before it sends the body; an HTTP/1.0 request's expectation
// is ignored. The value is case-insensitive.
bool expects_continue(const Request& header) {
  if (header.version() < 11) return false;
  const auto it = header.find(http::field::expect);
  return it != header.end() && beast::iequals(it->value(), "100-continue");
}

constexpr std::string_view kContinue = "HTTP/1.1 100 Continue\r\n\r\n";

}  // namespace

Session::Session(tcp::socket&& socket, const SessionContext& context) : stream_(std::move(socket)), context_(context) {
  beast::error_code ec;
  const tcp::endpoint remote = stream_.socket().remote_endpoint(ec);
  if (!ec) peer_ = remote.address().to_string();
  context_.metrics.record_open();
}

Session::~Session() {
  // Reached only when no handler holds the session: nothing computes for it any more,
  // but a computation it started may still be queued; make sure it stops early.
  if (computing_) budget_.cancel();
  context_.metrics.record_close();
}

void Session::run() {
  // Start on the connection's strand: every handler of this session runs there.
  net::dispatch(stream_.get_executor(), beast::bind_front_handler(&Session::do_read, shared_from_this()));
}

void Session::do_read() {
  parser_.emplace();
  parser_->header_limit(static_cast<std::uint32_t>(context_.config.max_header_bytes));
  parser_->body_limit(context_.config.max_body_bytes);
  stream_.expires_after(context_.config.read_timeout);
  http::async_read_header(stream_, buffer_, *parser_,
                          beast::bind_front_handler(&Session::on_read_header, shared_from_this()));
}

void Session::on_read_header(beast::error_code ec, std::size_t bytes) {
  // Errors (a declared Content-Length above the body limit among them) are
  // answered as for a whole request, before any 100 Continue.
  if (ec) return on_read(ec, bytes);
  if (parser_->is_done() || !expects_continue(parser_->get())) return do_read_body();
  // The raw bytes, not a Beast response: an interim answer is not a message of the
  // session (no log line, no metrics, no keep-alive accounting).
  stream_.expires_after(context_.config.write_timeout);
  net::async_write(stream_, net::buffer(kContinue),
                   beast::bind_front_handler(&Session::on_continue_written, shared_from_this()));
}

void Session::on_continue_written(beast::error_code ec, std::size_t) {
  if (ec) return;  // the stream is closed or broken; the session ends with this handler
  // The client starts sending only now: its body gets a whole read timeout.
  stream_.expires_after(context_.config.read_timeout);
  do_read_body();
}

void Session::do_read_body() {
  // Completes at once (posted) when the parser is already done.
  http::async_read(stream_, buffer_, *parser_, beast::bind_front_handler(&Session::on_read, shared_from_this()));
}

void Session::on_read(beast::error_code ec, std::size_t) {
  since_read_.restart();
  if (ec == http::error::body_limit) {
    return reject(http::status::payload_too_large, "body_too_large",
                  "the request body exceeds " + std::to_string(context_.config.max_body_bytes) + " bytes");
  }
  if (ec == http::error::header_limit) {
    return reject(http::status::request_header_fields_too_large, "headers_too_large",
                  "the request header exceeds " + std::to_string(context_.config.max_header_bytes) + " bytes");
  }
  if (ec && is_http_error(ec) && ec != http::error::end_of_stream && ec != http::error::partial_message) {
    return reject(http::status::bad_request, "bad_request", "malformed HTTP request: " + ec.message());
  }
  if (ec) {
    // The client closed between requests or mid-request, the connection broke, or
    // the client was too slow (the stream has closed itself then).
    if (ec != beast::error::timeout) do_close();
    return;
  }
  handle(parser_->release());
}

void Session::handle(Request request) {
  ++requests_;
  method_ = std::string(request.method_string());
  path_ = std::string(request.target());
  Routed routed = context_.router.route(request, peer_);
  endpoint_ = std::move(routed.endpoint);
  if (auto* response = std::get_if<Response>(&routed.result)) return send(std::move(*response));
  if (auto* stream = std::get_if<EventStream>(&routed.result)) return stream_events(std::move(*stream));
  if (auto* call = std::get_if<StoreCall>(&routed.result)) return call_store(request, std::move(*call));
  compute(request, std::get<Computation>(std::move(routed.result)));
}

void Session::compute(const Request& request, Computation computation) {
  budget_ = computation.budget;
  // The worker hands the finished response back to this session's strand.
  WorkerPool::Job job{[self = shared_from_this(), run = std::move(computation.run)]() {
                        Response response = run();
                        net::post(self->stream_.get_executor(), [self, response = std::move(response)]() mutable {
                          self->on_computed(std::move(response));
                        });
                      },
                      computation.budget};
  const std::optional<WorkerPool::Ticket> ticket = context_.pool.try_submit(job);
  if (!ticket) return send(context_.router.make_overloaded_response(request, "computation"));
  ticket_ = *ticket;
  computing_ = true;
  client_gone_ = false;
  // No read timeout while the client waits for its answer; the budget bounds the wait.
  stream_.expires_never();
  watch_for_disconnect();
  wait_for_worker_deadline();
}

void Session::wait_for_worker_deadline() {
  const double left = budget_.seconds_left();
  if (!std::isfinite(left)) return;  // no deadline: the queue's bound is the wait's
  if (!deadline_timer_) deadline_timer_.emplace(stream_.get_executor());
  // Just past the deadline, so that the budget's own check finds it spent.
  deadline_timer_->expires_after(
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(left)) +
      std::chrono::milliseconds(1));
  deadline_timer_->async_wait(beast::bind_front_handler(&Session::on_worker_deadline, shared_from_this()));
}

void Session::on_worker_deadline(beast::error_code ec) {
  // Cancelled (the answer came first), or nothing computes any more.
  if (ec || !computing_) return;
  if (budget_.seconds_left() > 0) return wait_for_worker_deadline();  // woke early
  std::optional<WorkerPool::Job> job = context_.pool.withdraw(ticket_);
  if (!job) return;  // a worker has it: the budget stops it at its next check
  // Its first step is the budget check that names the wait for a worker: it answers
  // the 504 at once (and counts it in the metrics) without computing anything.
  job->run();
}

void Session::call_store(const Request& request, StoreCall call) {
  WorkerPool::Job job{[self = shared_from_this(), run = std::move(call.run)]() {
                        StoreAnswer answer = run();
                        net::post(self->stream_.get_executor(), [self, answer = std::move(answer)]() mutable {
                          self->on_store_answered(std::move(answer));
                        });
                      },
                      Budget()};
  if (!context_.store_pool.try_submit(job)) return send(context_.router.make_overloaded_response(request, "job store"));
  // The store's own timeouts bound the wait (the client may not time out meanwhile).
  stream_.expires_never();
}

void Session::on_store_answered(StoreAnswer answer) {
  if (auto* response = std::get_if<Response>(&answer)) return send(std::move(*response));
  stream_events(std::get<EventStream>(std::move(answer)));
}

void Session::watch_for_disconnect() {
  stream_.socket().async_wait(tcp::socket::wait_read,
                              beast::bind_front_handler(&Session::on_readable, shared_from_this()));
}

void Session::on_readable(beast::error_code ec) {
  if (!computing_ || ec == net::error::operation_aborted) return;  // the answer came first
  if (!ec) {
    char byte = 0;
    const ssize_t n = ::recv(stream_.socket().native_handle(), &byte, 1, MSG_PEEK | MSG_DONTWAIT);
    if (n > 0) return;  // a pipelined request: the client is still there; stop watching
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return watch_for_disconnect();
  }
  // End of stream or a socket error: nobody is waiting for this answer any more.
  client_gone_ = true;
  budget_.cancel();
}

void Session::on_computed(Response response) {
  computing_ = false;
  if (client_gone_) {
    // 499 is nginx's "client closed request": logged, never sent.
    context_.metrics.record_request(endpoint_, 499, since_read_.elapsed_seconds());
    log_request(499, 0);
    return do_close();
  }
  if (deadline_timer_) deadline_timer_->cancel();
  beast::error_code ignored;
  stream_.socket().cancel(ignored);  // ends the disconnect watch
  send(std::move(response));
}

void Session::send(Response response) {
  if (requests_ >= context_.config.max_requests_per_connection) response.keep_alive(false);
  response_ = std::make_shared<Response>(std::move(response));
  stream_.expires_after(context_.config.write_timeout);
  http::async_write(stream_, *response_, beast::bind_front_handler(&Session::on_write, shared_from_this()));
}

void Session::on_write(beast::error_code ec, std::size_t bytes) {
  const unsigned status = response_->result_int();
  context_.metrics.record_request(endpoint_, status, since_read_.elapsed_seconds());
  log_request(status, bytes);
  if (ec) return;  // the stream is closed or broken; the session ends with this handler
  const bool keep_alive = response_->keep_alive();
  response_.reset();
  if (!keep_alive) return do_close();
  do_read();
}

void Session::stream_events(EventStream stream) {
  events_.emplace(std::move(stream));
  events_head_.emplace(events_->head);
  event_bytes_ = 0;
  stream_.expires_after(context_.config.write_timeout);
  http::async_write_header(stream_, *events_head_,
                           beast::bind_front_handler(&Session::on_events_head_written, shared_from_this()));
}

void Session::on_events_head_written(beast::error_code ec, std::size_t bytes) {
  event_bytes_ += bytes;
  if (ec) return log_request(events_->head.result_int(), event_bytes_);
  wait_for_event();
}

void Session::wait_for_event() {
  // No write is pending while the timer runs: the stream's timeout would close an
  // idle but healthy stream, so it is armed per write only.
  stream_.expires_never();
  if (!events_timer_) events_timer_.emplace(stream_.get_executor());
  events_timer_->expires_after(events_->interval);
  events_timer_->async_wait(beast::bind_front_handler(&Session::on_event_due, shared_from_this()));
}

void Session::on_event_due(beast::error_code ec) {
  if (ec) return;  // the timer was cancelled: the session is going away
  // The feed reads the job store: on the store executor, like every store call.
  WorkerPool::Job job{[self = shared_from_this(), next = events_->next]() {
                        std::pair<std::string, bool> event = next();
                        net::post(self->stream_.get_executor(), [self, event = std::move(event)]() mutable {
                          self->on_event_read(std::move(event.first), event.second);
                        });
                      },
                      Budget()};
  // A full store queue: this listener asks again at its next interval.
  if (!context_.store_pool.try_submit(job)) return wait_for_event();
}

void Session::on_event_read(std::string piece, bool last) {
  if (piece.empty() && !last) return wait_for_event();
  event_ = std::move(piece);
  last_event_ = last;
  stream_.expires_after(context_.config.write_timeout);
  net::async_write(stream_, net::buffer(event_),
                   beast::bind_front_handler(&Session::on_event_written, shared_from_this()));
}

void Session::on_event_written(beast::error_code ec, std::size_t bytes) {
  event_bytes_ += bytes;
  // A write error is the listener gone (or too slow to read): the stream ends.
  if (!ec && !last_event_) return wait_for_event();
  context_.metrics.record_request(endpoint_, events_->head.result_int(), since_read_.elapsed_seconds());
  log_request(events_->head.result_int(), event_bytes_);
  if (!ec) do_close();
}

void Session::reject(http::status status, std::string_view code, std::string_view message) {
  // The header may be incomplete: the router still sees method, target and Origin
  // when they were read, which is all it uses.
  const Request& partial = parser_->get();
  method_ = std::string(partial.method_string());
  path_ = std::string(partial.target());
  endpoint_ = "other";
  ++requests_;
  send(context_.router.make_transport_error_response(partial, status, code, message));
}

void Session::do_close() {
  beast::error_code ec;
  stream_.socket().shutdown(tcp::socket::shutdown_send, ec);
  if (ec) return;
  drained_ = 0;
  stream_.expires_after(kLingerTime);
  drain();
}

void Session::drain() {
  stream_.async_read_some(net::buffer(drain_buffer_), [self = shared_from_this()](beast::error_code ec, std::size_t n) {
    self->drained_ += n;
    if (ec || self->drained_ > kLingerBytes) {
      beast::error_code ignored;
      self->stream_.socket().close(ignored);
      return;
    }
    self->drain();
  });
}

void Session::log_request(unsigned status, std::size_t bytes) {
  const double ms = since_read_.elapsed_ms();
  context_.log.write(method_, path_, status, ms, bytes);
}

}  // namespace implicitizer::server
