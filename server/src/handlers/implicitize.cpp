#include "handlers/implicitize.hpp"

#include "implicitizer/codec/json_codec.hpp"

namespace implicitizer::server {

std::string canonical_key(const ImplicitizeRequest& request) {
  std::string key = "implicitize|";
  append_key_field(key, request.x);
  append_key_field(key, request.y);
  if (request.z) {
    append_key_field(key, *request.z);
  } else {
    key += '-';  // a plane curve: no field, distinct from every length-prefixed one
  }
  append_key_field(key, request.method);
  key += request.modular ? 'm' : '-';
  append_key_list(key, request.parameters);
  return key;
}

HandlerResult handle_implicitize(const Request& request, const HandlerContext& context) {
  ImplicitizeRequest decoded;
  try {
    decoded = decode_implicitize_request(request.body(), JsonParams{context.config.json_max_depth});
  } catch (const InputError& e) {
    return make_json_response(http::status::bad_request, encode_error(e));
  }
  std::string key = canonical_key(decoded);  // before decoded is moved from
  return cached_computation(std::move(decoded), std::move(key), context,
                            [](const auto& decoded_request, const BuchbergerParams& params) {
                              return encode_implicitize_response(answer_implicitize_request(decoded_request, params));
                            });
}

}  // namespace implicitizer::server
