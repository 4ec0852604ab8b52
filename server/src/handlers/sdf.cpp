#include "handlers/sdf.hpp"

#include <cstdio>

#include "implicitizer/codec/scene_json.hpp"
#include "implicitizer/codec/sdf_json.hpp"

namespace implicitizer::server {

std::string canonical_key(const SdfRequest& request) {
  std::string key = "sdf|";
  if (request.scene) {
    append_key_field(key, encode_scene(*request.scene));
    append_key_field(key, "scene");
  } else if (request.parametric) {
    for (const std::string& coordinate : *request.parametric) append_key_field(key, coordinate);
    append_key_field(key, "parametric");
    append_key_list(key, request.parameters);
  } else {
    append_key_field(key, request.implicit);
    append_key_field(key, "implicit");
  }
  append_key_field(key, to_string(request.shape));
  append_key_list(key, std::optional(request.domain));
  // The shortest round-trip text: two tolerances share a key iff they are one double.
  char tolerance[32] = "exact";
  if (request.tolerance) std::snprintf(tolerance, sizeof tolerance, "%.17g", *request.tolerance);
  append_key_field(key, tolerance);
  append_key_field(key, to_string(request.mode));
  append_key_list(key, std::optional(request.box));
  append_key_field(key, request.name);
  return key;
}

HandlerResult handle_sdf(const Request& request, const HandlerContext& context) {
  return handle_decoded(request, context, decode_sdf_request, [&](SdfRequest decoded) {
    std::string key = canonical_key(decoded);  // before decoded is moved from
    return cached_computation(
        std::move(decoded), std::move(key), context,
        [](const SdfRequest& r, const Budget& budget) { return encode_sdf_response(answer_sdf_request(r, budget)); });
  });
}

}  // namespace implicitizer::server
