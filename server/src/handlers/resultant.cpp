#include "handlers/resultant.hpp"

#include "implicitizer/codec/resultant_json.hpp"

namespace implicitizer::server {

std::string canonical_key(const ResultantRequest& request) {
  std::string key = "resultant|";
  append_key_list(key, std::optional(request.polynomials));
  append_key_field(key, request.variable);
  return key;
}

HandlerResult handle_resultant(const Request& request, const HandlerContext& context) {
  return handle_decoded(request, context, decode_resultant_request, [&](ResultantRequest decoded) {
    std::string key = canonical_key(decoded);  // before decoded is moved from
    return cached_computation(std::move(decoded), std::move(key), context,
                              [](const ResultantRequest& r, const Budget& budget) {
                                return encode_resultant_response(answer_resultant_request(r, budget));
                              });
  });
}

}  // namespace implicitizer::server
