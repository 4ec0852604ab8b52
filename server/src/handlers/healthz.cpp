#include "handlers/healthz.hpp"

#include "implicitizer/codec/server_json.hpp"

namespace implicitizer::server {

Response handle_healthz(const Request&) { return make_json_response(http::status::ok, encode_health_status("ok")); }

}  // namespace implicitizer::server
