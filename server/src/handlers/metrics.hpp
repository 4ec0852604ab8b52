#pragma once
/// \file
/// GET /metrics: Prometheus text exposition of MetricsRegistry and the pool/cache gauges.

#include "handlers/handler.hpp"

namespace implicitizer::server {

/// 200 with `text/plain; version=0.0.4` and the current metrics.
Response handle_metrics(const Request& request, const HandlerContext& context);

}  // namespace implicitizer::server
