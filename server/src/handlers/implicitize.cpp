#include "handlers/implicitize.hpp"

#include "implicitizer/codec/implicitize_json.hpp"

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
  append_key_field(key, std::to_string(static_cast<int>(request.method)));
  key += request.modular ? 'm' : '-';
  append_key_list(key, request.parameters);
  return key;
}

HandlerResult handle_implicitize(const Request& request, const HandlerContext& context) {
  return handle_decoded(request, context, decode_implicitize_request, [&](ImplicitizeRequest decoded) {
    std::string key = canonical_key(decoded);  // before decoded is moved from
    return cached_computation(std::move(decoded), std::move(key), context,
                              [](const ImplicitizeRequest& r, const Budget& budget) {
                                return encode_implicitize_response(answer_implicitize_request(r, budget));
                              });
  });
}

}  // namespace implicitizer::server
