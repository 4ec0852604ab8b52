#include "handlers/groebner.hpp"

#include "implicitizer/codec/groebner_json.hpp"

namespace implicitizer::server {

std::string canonical_key(const GroebnerRequest& request) {
  std::string key = "groebner|";
  append_key_list(key, std::optional(request.polynomials));
  append_key_list(key, request.variables);
  append_key_field(key, request.order.name());
  append_key_list(key, request.weights);
  append_key_list(key, request.eliminate);
  append_key_field(key, to_string(request.method));
  // The default proof is left out, so that the keys of exact requests stay as they were.
  if (request.proof != GroebnerProof::exact) append_key_field(key, to_string(request.proof));
  return key;
}

HandlerResult handle_groebner(const Request& request, const HandlerContext& context) {
  return handle_decoded(request, context, decode_groebner_request, [&](GroebnerRequest decoded) {
    std::string key = canonical_key(decoded);  // before decoded is moved from
    return cached_computation(std::move(decoded), std::move(key), context,
                              [](const GroebnerRequest& r, const Budget& budget) {
                                return encode_groebner_response(answer_groebner_request(r, budget));
                              });
  });
}

}  // namespace implicitizer::server
