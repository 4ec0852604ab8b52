#include "handlers/metrics.hpp"

namespace implicitizer::server {

Response handle_metrics(const Request&, const HandlerContext& context) {
  const MetricsGauges gauges = context.gauges ? context.gauges() : MetricsGauges{};
  return make_response(http::status::ok, context.metrics.render(gauges), "text/plain; version=0.0.4; charset=utf-8");
}

}  // namespace implicitizer::server
