#include "handlers/implicitize.hpp"

#include "implicitizer/codec/json_codec.hpp"

namespace implicitizer::server {
namespace {

void append_field(std::string& key, const std::string& value) {
  key += std::to_string(value.size());
  key += ':';
  key += value;
}

}  // namespace

std::string canonical_key(const ImplicitizeRequest& request) {
  std::string key = "implicitize|";
  append_field(key, request.x);
  append_field(key, request.y);
  append_field(key, request.z);
  append_field(key, request.method);
  if (request.parameters) {
    key += 'P';
    key += std::to_string(request.parameters->size());
    for (const std::string& p : *request.parameters) append_field(key, p);
  } else {
    key += '-';
  }
  return key;
}

HandlerResult handle_implicitize(const Request& request, const HandlerContext& context) {
  ImplicitizeRequest decoded;
  try {
    decoded = decode_implicitize_request(request.body(), JsonLimits{context.config.json_max_depth});
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
