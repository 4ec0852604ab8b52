#pragma once
/// \file
/// Accepts connections and gives each one a Session on its own strand. Nothing else.

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <memory>

#include "session.hpp"

namespace implicitizer::server {

/// The accepting socket. Owned by its pending accept (shared_from_this).
class Listener : public std::enable_shared_from_this<Listener> {
 public:
  /// Binds and listens on `endpoint`; throws boost::system::system_error when it
  /// cannot (address in use, no permission).
  Listener(boost::asio::io_context& io, const boost::asio::ip::tcp::endpoint& endpoint, const SessionContext& context);

  /// Starts accepting.
  void run();
  /// Stops accepting (for shutdown); established sessions carry on.
  void stop();
  /// The bound address, with the port the system chose when 0 was asked for.
  boost::asio::ip::tcp::endpoint local_endpoint() const { return acceptor_.local_endpoint(); }

 private:
  void do_accept();
  void on_accept(boost::beast::error_code ec, boost::asio::ip::tcp::socket socket);

  boost::asio::io_context& io_;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer backoff_;  // after an accept error such as EMFILE
  const SessionContext& context_;
};

}  // namespace implicitizer::server
