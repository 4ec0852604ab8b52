#include "handlers/groebner.hpp"

#include "implicitizer/codec/json_codec.hpp"

namespace implicitizer::server {
namespace {

void append_field(std::string& key, const std::string& value) {
  key += std::to_string(value.size());
  key += ':';
  key += value;
}

template <typename T>
void append_list(std::string& key, const std::optional<std::vector<T>>& list) {
  if (!list) {
    key += '-';
    return;
  }
  key += 'L';
  key += std::to_string(list->size());
  for (const T& item : *list) {
    if constexpr (std::is_same_v<T, std::string>) {
      append_field(key, item);
    } else {
      append_field(key, std::to_string(item));
    }
  }
}

}  // namespace

std::string canonical_key(const GroebnerRequest& request) {
  std::string key = "groebner|";
  append_list(key, std::optional(request.polynomials));
  append_list(key, request.variables);
  append_field(key, request.order);
  append_list(key, request.weights);
  append_list(key, request.eliminate);
  return key;
}

HandlerResult handle_groebner(const Request& request, const HandlerContext& context) {
  GroebnerRequest decoded;
  try {
    decoded = decode_groebner_request(request.body(), JsonLimits{context.config.json_max_depth});
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
