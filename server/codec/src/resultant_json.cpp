#include "implicitizer/codec/resultant_json.hpp"

#include "implicitizer/polynomial/printer.hpp"
#include "json_reader.hpp"
#include "json_writer.hpp"

namespace implicitizer {

ResultantRequest decode_resultant_request(std::string_view body, const JsonParams& limits) {
  const rapidjson::Document document = json::parse_object(body, limits);
  json::ObjectReader reader(document);
  ResultantRequest request;
  request.polynomials = json::read_strings(reader.require("polynomials"), "polynomials");
  if (request.polynomials.size() != 2) {
    throw InputError("wrong_number_of_polynomials", "'polynomials' must hold exactly two polynomials, F and G (got " +
                                                        std::to_string(request.polynomials.size()) + ")")
        .in_field("polynomials");
  }
  request.variable = json::read_string(reader.require("variable"), "variable");
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = json::read_timeout_seconds(*v);
  reader.finish("polynomials, variable, timeout_ms");
  return request;
}

std::string encode_resultant_response(const ResultantAnswer& answer) {
  return json::write_json([&](json::Writer& w) {
    w.StartObject();
    w.Key("resultant");
    json::write_string(w, to_string(answer.resultant));
    w.Key("variables");
    json::write_strings(w, answer.variables);
    w.Key("degree");
    w.Int(answer.degree);
    w.Key("method");
    json::write_string(w, answer.method);
    w.Key("elapsed_ms");
    json::write_milliseconds(w, answer.elapsed_ms);
    w.EndObject();
  });
}

}  // namespace implicitizer
