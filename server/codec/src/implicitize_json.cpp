#include "implicitizer/codec/implicitize_json.hpp"

#include <optional>

#include "implicitizer/polynomial/printer.hpp"
#include "json_reader.hpp"
#include "json_writer.hpp"

namespace implicitizer {
namespace {

using json::write_milliseconds;
using json::write_string;
using json::Writer;

// The auxiliary resultant's statistics: what the resultant route did, or, when
// `auto` fell back to Gröbner, what its probe found.
void write_resultant_stats(Writer& w, const AuxiliaryResultantStats& s, std::int32_t map_degree) {
  w.StartObject();
  w.Key("dixon_vanishes");
  w.Bool(s.dixon_vanishes);
  w.Key("macaulay_vanishes");
  w.Bool(s.macaulay_vanishes);
  if (s.matrix_too_large) {
    w.Key("matrix_too_large");
    w.Bool(true);
  }
  if (s.matrix_size > 0) {
    w.Key("formulation");
    write_string(w, to_string(s.formulation));
    w.Key("matrix_size");
    w.Uint64(s.matrix_size);
    w.Key("extraneous_size");
    w.Uint64(s.extraneous_size);
    w.Key("degree_bound");
    w.Int(s.degree_bound);
  }
  // The determinant's figures only when it was computed (not when auto's head start
  // let Buchberger answer first).
  if (s.determinant.primes > 0) {
    w.Key("map_degree");
    w.Int(map_degree);
    w.Key("primes");
    w.Uint64(s.determinant.primes);
    w.Key("unlucky_primes");
    w.Uint64(s.determinant.unlucky_primes);
    w.Key("evaluations");
    w.Uint64(s.determinant.evaluations);
    w.Key("modulus_bits");
    w.Uint64(s.determinant.modulus_bits);
    w.Key("proven_bound");
    w.Bool(s.determinant.proven);
    w.Key("determinant_ms");
    write_milliseconds(w, s.determinant_ms);
  }
  w.Key("construction_ms");
  write_milliseconds(w, s.construction_ms);
  w.EndObject();
}

// The interpolation route's statistics (method interpolation).
void write_interpolation_stats(Writer& w, const InterpolationStats& s) {
  w.StartObject();
  w.Key("degree_bound");
  w.Int(s.degree_bound);
  w.Key("degree");
  w.Int(s.degree);
  w.Key("rows");
  w.Uint64(s.rows);
  w.Key("columns");
  w.Uint64(s.columns);
  w.Key("primes");
  w.Uint64(s.primes);
  w.Key("unlucky_primes");
  w.Uint64(s.unlucky_primes);
  w.Key("degree_probes");
  w.Uint64(s.degree_probes);
  w.Key("rejected_points");
  w.Uint64(s.rejected_points);
  w.Key("rejected_candidates");
  w.Uint64(s.rejected_candidates);
  w.Key("modulus_bits");
  w.Uint64(s.modulus_bits);
  w.Key("threads");
  w.Uint(s.threads);
  w.Key("search_ms");
  write_milliseconds(w, s.search_ms);
  w.Key("images_ms");
  write_milliseconds(w, s.images_ms);
  w.Key("reconstruction_ms");
  write_milliseconds(w, s.reconstruction_ms);
  w.EndObject();
}

// "stats": Buchberger's counters, the verification time, and what each route adds.
void write_stats(Writer& w, const ImplicitizeResult& result) {
  w.StartObject();
  json::write_buchberger_stats_members(w, result.stats);
  w.Key("verify_ms");
  write_milliseconds(w, result.verify_ms);
  if (!result.route.empty()) {
    w.Key("route");
    write_string(w, result.route);
  }
  if (result.resultant_stats) {
    w.Key("resultant");
    write_resultant_stats(w, *result.resultant_stats, result.map_degree);
  }
  if (result.interpolation_stats) {
    w.Key("interpolation");
    write_interpolation_stats(w, *result.interpolation_stats);
  }
  if (result.modular_stats) {
    w.Key("modular");
    json::write_modular_stats(w, *result.modular_stats);
  }
  w.EndObject();
}

// "substitution" and "rational_parametrization": how the input was made rational and
// the form that was implicitized (only for an input with functions).
void write_substitution(Writer& w, const ImplicitizeAnswer& answer) {
  w.Key("substitution");
  w.StartArray();
  for (const auto& s : answer.substitutions) {
    w.StartObject();
    w.Key("parameter");
    write_string(w, s.parameter);
    w.Key("variable");
    write_string(w, s.variable);
    w.Key("kind");
    write_string(w, to_string(s.kind));
    w.Key("formula");
    write_string(w, to_string(s));
    w.EndObject();
  }
  w.EndArray();
  w.Key("rational_parametrization");
  w.StartObject();
  w.Key("parameters");
  json::write_strings(w, answer.rational_parameters);
  const std::vector<std::string> names = coordinate_names(answer.rational_coordinates.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    w.Key(names[i].c_str());
    write_string(w, answer.rational_coordinates[i]);
  }
  w.EndObject();
}

}  // namespace

ImplicitizeRequest decode_implicitize_request(std::string_view body, const JsonParams& limits) {
  const rapidjson::Document document = json::parse_object(body, limits);
  json::ObjectReader reader(document);
  ImplicitizeRequest request;
  request.x = json::read_string(reader.require("x"), "x");
  request.y = json::read_string(reader.require("y"), "y");
  if (const auto* v = reader.take("z")) request.z = json::read_string(*v, "z");
  if (const auto* v = reader.take("parameters")) request.parameters = json::read_strings(*v, "parameters");
  std::optional<std::string> method;
  if (const auto* v = reader.take("method")) method = json::read_string(*v, "method");
  if (const auto* v = reader.take("modular")) {
    if (!v->IsBool()) throw json::wrong_type("modular", "true or false");
    request.modular = v->GetBool();
  }
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = json::read_timeout_seconds(*v);
  reader.finish("x, y, z, parameters, method, modular, timeout_ms");
  if (method) request.method = json::parse_choice(*method, "method", parse_implicitization_method);
  return request;
}

std::string encode_implicitize_response(const ImplicitizeAnswer& answer) {
  const ImplicitizeResult& result = answer.result;
  return json::write_json([&](Writer& w) {
    w.StartObject();
    w.Key("implicit");
    write_string(w, to_string(result.implicit));
    w.Key("degree");
    w.Int(result.degree);
    w.Key("variables");
    json::write_strings(w, result.implicit.ring()->variables());
    w.Key("method");
    write_string(w, result.method);
    w.Key("verified");
    w.Bool(result.verified);
    w.Key("elapsed_ms");
    write_milliseconds(w, result.elapsed_ms);
    w.Key("stats");
    write_stats(w, result);
    if (!answer.substitutions.empty()) write_substitution(w, answer);
    w.Key("reproduce");
    w.StartObject();
    w.Key("singular");
    write_string(w, answer.reproduce.singular);
    w.Key("macaulay2");
    write_string(w, answer.reproduce.macaulay2);
    w.EndObject();
    w.EndObject();
  });
}

}  // namespace implicitizer
