// implicitizer-server: the contract's HTTP service. Parses the flags, starts the
// Server, and waits for SIGINT/SIGTERM to shut it down gracefully (exit 0, or
// kExitComputationsDidNotStop when Server::stop() had to leave computations behind).

#include <csignal>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "config.hpp"
#include "server.hpp"

namespace {

constexpr int kExitUsage = 2;
constexpr int kExitStartFailed = 1;

}  // namespace

int main(int argc, char** argv) {
  using namespace implicitizer::server;
  std::optional<ServerConfig> config;
  try {
    config = parse_server_flags(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const UsageError& e) {
    std::cerr << "implicitizer-server: " << e.what() << '\n' << kServerUsage;
    return kExitUsage;
  }
  if (!config) {
    std::cout << kServerUsage;
    return 0;
  }

  // Block the stop signals in every thread (the server's threads inherit the mask)
  // and take them synchronously here, so no handler runs at an arbitrary point.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  try {
    Server server(*config);
    // Tests and scripts read this line to learn the port (with --port 0).
    std::cout << "implicitizer-server listening on http://" << config->host << ':' << server.port() << std::endl;
    int signal_number = 0;
    sigwait(&stop_signals, &signal_number);
    std::cerr << "implicitizer-server: " << (signal_number == SIGINT ? "SIGINT" : "SIGTERM") << ", shutting down\n";
    server.stop();
  } catch (const UsageError& e) {
    std::cerr << "implicitizer-server: " << e.what() << '\n';
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "implicitizer-server: cannot start: " << e.what() << '\n';
    return kExitStartFailed;
  }
  return 0;
}
