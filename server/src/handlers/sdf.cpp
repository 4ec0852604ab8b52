#include "handlers/sdf.hpp"

#include "implicitizer/codec/json_codec.hpp"
#include "implicitizer/codec/scene_json.hpp"

namespace implicitizer::server {

std::string canonical_key(const SdfRequest& request) {
  std::string key = "sdf|";
  append_key_field(key, request.scene ? encode_scene(*request.scene) : request.implicit);
  append_key_field(key, request.scene ? "scene" : "implicit");
  append_key_field(key, request.mode);
  append_key_list(key, std::optional(request.box));
  append_key_field(key, request.name);
  return key;
}

HandlerResult handle_sdf(const Request& request, const HandlerContext& context) {
  SdfRequest decoded;
  try {
    decoded = decode_sdf_request(request.body(), JsonParams{context.config.json_max_depth});
  } catch (const InputError& e) {
    return make_json_response(http::status::bad_request, encode_error(e));
  }
  std::string key = canonical_key(decoded);  // before decoded is moved from
  return cached_computation(std::move(decoded), std::move(key), context,
                            [](const auto& decoded_request, const BuchbergerParams& params) {
                              return encode_sdf_response(answer_sdf_request(decoded_request, params.budget));
                            });
}

}  // namespace implicitizer::server
