#include "handlers/healthz.hpp"

#include "implicitizer/codec/json_codec.hpp"

namespace implicitizer::server {

Response handle_healthz(const Request&) { return make_json_response(http::status::ok, encode_health_status("ok")); }

}  // namespace implicitizer::server
