#pragma once
/// \file
/// The server's own JSON lines, outside the endpoints' contract of requests and
/// answers: the health check's body and the access log.

#include <cstddef>
#include <string>
#include <string_view>

namespace implicitizer {

/// `{"status": status}`: the body of the server's GET /healthz.
std::string encode_health_status(std::string_view status);

/// One line of the server's access log (JSON lines on stderr):
/// `{"method", "path", "status", "ms", "bytes"}`; `path` without the query string.
std::string encode_access_log_entry(std::string_view method, std::string_view path, unsigned status, double ms,
                                    std::size_t bytes);

}  // namespace implicitizer
