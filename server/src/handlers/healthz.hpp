#pragma once
/// \file
/// GET /healthz: the process is up and its network loop answers.

#include "http_message.hpp"

namespace implicitizer::server {

/// `{"status":"ok"}` with 200. Runs on the network thread, so it also shows that
/// thread is not blocked.
Response handle_healthz(const Request& request);

}  // namespace implicitizer::server
