#include "http_message.hpp"

#include "implicitizer/codec/error_json.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer::server {

Response make_response(http::status status, std::string body, std::string_view content_type) {
  Response response(status, 11);
  response.set(http::field::content_type, content_type);
  response.set(http::field::server, "implicitizer");
  response.body() = std::move(body);
  response.prepare_payload();
  return response;
}

Response make_json_response(http::status status, std::string body) {
  return make_response(status, std::move(body), "application/json");
}

Response make_error_response(http::status status, std::string_view code, std::string_view message) {
  return make_json_response(status, encode_error(code, message));
}

Response make_exception_response(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const InputError& e) {
    return make_json_response(http::status::bad_request, encode_error(e));
  } catch (const NoSingleEquation& e) {
    return make_json_response(http::status::unprocessable_entity, encode_error(e));
  } catch (const ToleranceNotMet& e) {
    // Like no_single_equation: a well-formed request the computation cannot answer
    // as asked (never a worse answer in its place).
    return make_json_response(http::status::unprocessable_entity, encode_error(e));
  } catch (const LimitExceeded& e) {
    // A size or memory limit is the request being too large for this server, as a
    // body is; a cancelled computation only answers a client that has gone (or a
    // shutdown).
    const http::status status = e.limit() == Limit::time        ? http::status::gateway_timeout
                                : e.limit() == Limit::cancelled ? http::status::service_unavailable
                                                                : http::status::payload_too_large;
    return make_json_response(status, encode_error(e));
  } catch (const std::bad_alloc&) {
    // The machine's memory exhausted (an allocation past a computation's own limit
    // arrives here as LimitExceeded: Budget::rethrow_bad_alloc).
    return make_json_response(http::status::payload_too_large,
                              encode_error(LimitExceeded(Limit::memory,
                                                         "out of memory: the machine has no memory "
                                                         "left for this computation")));
  } catch (...) {
    return make_error_response(http::status::internal_server_error, "internal_error", "internal error");
  }
}

}  // namespace implicitizer::server
