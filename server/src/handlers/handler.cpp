#include "handlers/handler.hpp"

#include "implicitizer/codec/error_json.hpp"

namespace implicitizer::server {

Response make_refusal_response(const InputError& error) {
  const http::status status =
      error.code() == "render_too_large" ? http::status::payload_too_large : http::status::bad_request;
  return make_json_response(status, encode_error(error));
}

Budget make_computation_budget(const std::optional<double>& requested_seconds, const ServerConfig& config) {
  const double cap = std::chrono::duration<double>(config.max_timeout).count();
  double seconds = std::chrono::duration<double>(config.default_timeout).count();
  if (requested_seconds) seconds = *requested_seconds <= 0 || *requested_seconds > cap ? cap : *requested_seconds;
  Budget budget = Budget::with_timeout(seconds);
  budget.set_max_terms(config.max_terms)
      .set_max_memory(config.effective_max_memory_bytes())
      .set_max_variables(config.max_variables)
      .set_max_polynomials(config.max_polynomials);
  return budget;
}

}  // namespace implicitizer::server
