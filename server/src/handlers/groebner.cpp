#include "handlers/groebner.hpp"

#include "implicitizer/codec/json_codec.hpp"

namespace implicitizer::server {

std::string canonical_key(const GroebnerRequest& request) {
  std::string key = "groebner|";
  append_key_list(key, std::optional(request.polynomials));
  append_key_list(key, request.variables);
  append_key_field(key, request.order);
  append_key_list(key, request.weights);
  append_key_list(key, request.eliminate);
  append_key_field(key, request.method);
  return key;
}

HandlerResult handle_groebner(const Request& request, const HandlerContext& context) {
  GroebnerRequest decoded;
  try {
    decoded = decode_groebner_request(request.body(), JsonParams{context.config.json_max_depth});
  } catch (const InputError& e) {
    return make_json_response(http::status::bad_request, encode_error(e));
  }
  std::string key = canonical_key(decoded);  // before decoded is moved from
  return cached_computation(std::move(decoded), std::move(key), context,
                            [](const auto& decoded_request, const BuchbergerParams& params) {
                              return encode_groebner_response(answer_groebner_request(decoded_request, params));
                            });
}

}  // namespace implicitizer::server
