#include "handlers/resultant.hpp"

#include "implicitizer/codec/json_codec.hpp"

namespace implicitizer::server {

std::string canonical_key(const ResultantRequest& request) {
  std::string key = "resultant|";
  append_key_list(key, std::optional(request.polynomials));
  append_key_field(key, request.variable);
  return key;
}

HandlerResult handle_resultant(const Request& request, const HandlerContext& context) {
  ResultantRequest decoded;
  try {
    decoded = decode_resultant_request(request.body(), JsonParams{context.config.json_max_depth});
  } catch (const InputError& e) {
    return make_json_response(http::status::bad_request, encode_error(e));
  }
  std::string key = canonical_key(decoded);  // before decoded is moved from
  return cached_computation(
      std::move(decoded), std::move(key), context, [](const auto& decoded_request, const BuchbergerParams& params) {
        return encode_resultant_response(answer_resultant_request(decoded_request, params.budget));
      });
}

}  // namespace implicitizer::server
