#include "implicitizer/codec/groebner_json.hpp"

#include <optional>

#include "json_reader.hpp"
#include "json_writer.hpp"

namespace implicitizer {

GroebnerRequest decode_groebner_request(std::string_view body, const JsonParams& limits) {
  const rapidjson::Document document = json::parse_object(body, limits);
  json::ObjectReader reader(document);
  GroebnerRequest request;
  request.polynomials = json::read_strings(reader.require("polynomials"), "polynomials");
  if (const auto* v = reader.take("variables")) request.variables = json::read_strings(*v, "variables");
  std::optional<std::string> order;
  if (const auto* v = reader.take("order")) order = json::read_string(*v, "order");
  if (const auto* v = reader.take("weights")) request.weights = json::read_ints(*v, "weights");
  if (const auto* v = reader.take("eliminate")) request.eliminate = json::read_strings(*v, "eliminate");
  std::optional<std::string> method;
  if (const auto* v = reader.take("method")) method = json::read_string(*v, "method");
  std::optional<std::string> proof;
  if (const auto* v = reader.take("proof")) proof = json::read_string(*v, "proof");
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = json::read_timeout_seconds(*v);
  reader.finish("polynomials, variables, order, weights, eliminate, method, proof, timeout_ms");
  if (order) request.order = json::parse_choice(*order, "order", &MonomialOrder::from_name);
  if (method) request.method = json::parse_choice(*method, "method", parse_groebner_method);
  if (proof) request.proof = json::parse_choice(*proof, "proof", parse_groebner_proof);
  return request;
}

std::string encode_groebner_response(const GroebnerAnswer& answer) {
  return json::write_json([&](json::Writer& w) {
    w.StartObject();
    w.Key("basis");
    json::write_polynomials(w, answer.basis);
    w.Key("order");
    json::write_string(w, answer.order);
    w.Key("method");
    json::write_string(w, to_string(answer.route.method));
    w.Key("proven");
    w.Bool(answer.route.proven());
    w.Key("stats");
    w.StartObject();
    json::write_buchberger_stats_members(w, answer.stats);
    if (answer.route.modular) {
      w.Key("modular");
      json::write_modular_stats(w, *answer.route.modular);
    }
    w.EndObject();
    w.Key("elapsed_ms");
    json::write_milliseconds(w, answer.elapsed_ms);
    if (answer.elimination_ideal) {
      w.Key("elimination_ideal");
      json::write_polynomials(w, *answer.elimination_ideal);
    }
    w.EndObject();
  });
}

}  // namespace implicitizer
