#pragma once
/// \file
/// The JSON-lines access log on stderr: one line per answered request.

#include <cstddef>
#include <mutex>
#include <string_view>

namespace implicitizer::server {

/// Writes one JSON object per request to stderr, whole lines under a lock so that
/// lines of concurrent sessions never interleave. Disabled by `--quiet`.
class AccessLog {
 public:
  /// A log that writes when `enabled`.
  explicit AccessLog(bool enabled) : enabled_(enabled) {}

  /// Logs one request. `path` is the target without its query string; bytes
  /// that are not printable ASCII are written as `?` so every line is valid JSON.
  void write(std::string_view method, std::string_view path, unsigned status, double ms, std::size_t bytes);

 private:
  bool enabled_;
  std::mutex mutex_;
};

}  // namespace implicitizer::server
