#pragma once
/// \file
/// The HTTP message types every part of the server speaks, and the builders of the
/// contract's responses (JSON bodies, the error shape). Builders are pure.

#include <boost/beast/http.hpp>
#include <exception>
#include <string>
#include <string_view>

namespace implicitizer::server {

namespace http = boost::beast::http;

/// A request as the session read it: the whole body in memory (bounded by the parser).
using Request = http::request<http::string_body>;
/// A response ready to be written.
using Response = http::response<http::string_body>;

/// A response with `status`, body `body` and Content-Type `content_type`, with
/// Content-Length set. Version and keep-alive are the router's to set (Router::finish).
Response make_response(http::status status, std::string body, std::string_view content_type);

/// A JSON response (`application/json`).
Response make_json_response(http::status status, std::string body);

/// The contract's error: `{"error": {"code": code, "message": message}}` with `status`.
Response make_error_response(http::status status, std::string_view code, std::string_view message);

/// Maps what a computation threw to the contract's status and error body:
/// InputError → 400, NoSingleEquation → 422, LimitExceeded time → 504, size → 413,
/// cancelled → 503; anything else → 500 `internal_error` (the message is not leaked).
Response make_exception_response(const std::exception_ptr& error);

}  // namespace implicitizer::server
