#include "implicitizer/codec/json_codec.hpp"

#include <rapidjson/document.h>
#include <rapidjson/error/en.h>
#include <rapidjson/stringbuffer.h>
#include <rapidjson/writer.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "implicitizer/codec/json_depth.hpp"
#include "implicitizer/codec/scene_json.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {
namespace {

using Writer = rapidjson::Writer<rapidjson::StringBuffer>;

// ---- decoding -------------------------------------------------------------

rapidjson::Document parse_object(std::string_view body, const JsonParams& limits) {
  check_json_depth(body, limits.max_depth);
  rapidjson::Document document;
  // Iterative parsing: no recursion whatever the input; invalid UTF-8 is a syntax
  // error. No kParseFullPrecisionFlag: Debian's RapidJSON 1.1.0 reads out of bounds
  // in StrtodDiyFp on long decimals with it (found by fuzz/request_fuzzer), and the
  // only number of a request, timeout_ms, needs no more than double's usual rounding.
  document.Parse<rapidjson::kParseIterativeFlag | rapidjson::kParseValidateEncodingFlag>(body.data(), body.size());
  if (document.HasParseError()) {
    throw InputError("invalid_json",
                     std::string("invalid JSON: ") + rapidjson::GetParseError_En(document.GetParseError()),
                     document.GetErrorOffset());
  }
  if (!document.IsObject()) throw InputError("wrong_type", "the request body must be a JSON object");
  return document;
}

// Walks the members of the request object: each field is taken at most once, and
// whatever was not taken at the end is an unknown field.
class ObjectReader {
 public:
  explicit ObjectReader(const rapidjson::Value& object) : object_(object) {
    for (auto m = object_.MemberBegin(); m != object_.MemberEnd(); ++m) {
      const std::string name(m->name.GetString(), m->name.GetStringLength());
      for (const std::string& seen : names_) {
        if (seen == name) throw InputError("duplicate_field", "field '" + name + "' is given twice").in_field(name);
      }
      names_.push_back(name);
    }
    taken_.assign(names_.size(), false);
  }

  /// The member `name`, or nullptr when absent.
  const rapidjson::Value* take(const char* name) {
    for (std::size_t i = 0; i < names_.size(); ++i) {
      if (names_[i] == name) {
        taken_[i] = true;
        return &(object_.MemberBegin() + static_cast<rapidjson::SizeType>(i))->value;
      }
    }
    return nullptr;
  }

  const rapidjson::Value& require(const char* name) {
    const rapidjson::Value* v = take(name);
    if (v == nullptr) throw InputError("missing_field", std::string("field '") + name + "' is required").in_field(name);
    return *v;
  }

  /// Throws `unknown_field` for the first member never taken.
  void finish(const char* allowed) const {
    for (std::size_t i = 0; i < names_.size(); ++i) {
      if (!taken_[i]) {
        throw InputError("unknown_field", "unknown field '" + names_[i] + "' (allowed: " + allowed + ")")
            .in_field(names_[i]);
      }
    }
  }

 private:
  const rapidjson::Value& object_;
  std::vector<std::string> names_;
  std::vector<bool> taken_;
};

InputError wrong_type(const std::string& field, const char* expected) {
  return InputError("wrong_type", "'" + field + "' must be " + expected).in_field(field);
}

std::string read_string(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsString()) throw wrong_type(field, "a string");
  return std::string(v.GetString(), v.GetStringLength());
}

std::vector<std::string> read_strings(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsArray()) throw wrong_type(field, "an array of strings");
  std::vector<std::string> out;
  out.reserve(v.Size());
  for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
    out.push_back(read_string(v[i], field + "[" + std::to_string(i) + "]"));
  }
  return out;
}

std::vector<int> read_ints(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsArray()) throw wrong_type(field, "an array of integers");
  std::vector<int> out;
  out.reserve(v.Size());
  for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
    if (!v[i].IsInt()) throw wrong_type(field + "[" + std::to_string(i) + "]", "an integer");
    out.push_back(v[i].GetInt());
  }
  return out;
}

// timeout_ms: a non-negative finite number of milliseconds; 0 means no limit.
double read_timeout_seconds(const rapidjson::Value& v) {
  if (!v.IsNumber()) throw wrong_type("timeout_ms", "a number of milliseconds");
  const double ms = v.GetDouble();
  if (!std::isfinite(ms) || ms < 0) {
    throw InputError("invalid_value", "'timeout_ms' must be a non-negative number").in_field("timeout_ms");
  }
  return ms / 1000.0;
}

// ---- encoding -------------------------------------------------------------

Writer& configure(Writer& w) {
  w.SetMaxDecimalPlaces(3);
  return w;
}

void write_string(Writer& w, std::string_view s) { w.String(s.data(), static_cast<rapidjson::SizeType>(s.size())); }

void write_key(Writer& w, const char* key) { w.Key(key); }

void write_milliseconds(Writer& w, double ms) { w.Double(std::isfinite(ms) && ms > 0 ? ms : 0.0); }

void write_polynomials(Writer& w, const std::vector<Polynomial>& polynomials) {
  w.StartArray();
  for (const Polynomial& p : polynomials) write_string(w, to_string(p));
  w.EndArray();
}

void write_stats_members(Writer& w, const BuchbergerStats& s) {
  write_key(w, "pairs");
  w.Uint64(s.pairs_created);
  write_key(w, "product_criterion");
  w.Uint64(s.product_criterion);
  write_key(w, "chain_criterion");
  w.Uint64(s.chain_criterion);
  write_key(w, "reductions");
  w.Uint64(s.reductions);
  write_key(w, "zero_reductions");
  w.Uint64(s.zero_reductions);
  write_key(w, "reduction_steps");
  w.Uint64(s.reduction_steps);
  write_key(w, "work");
  w.Uint64(s.work);
  write_key(w, "max_degree");
  w.Int(s.max_degree);
  write_key(w, "basis_size");
  w.Uint64(s.basis_size);
  write_key(w, "groebner_ms");
  write_milliseconds(w, s.elapsed_ms);
}

// What the modular Gröbner computation did (modular_groebner.hpp).
void write_modular_stats(Writer& w, const ModularGroebnerStats& s) {
  w.StartObject();
  write_key(w, "primes");
  w.Uint64(s.primes);
  write_key(w, "lifted_primes");
  w.Uint64(s.lifted_primes);
  write_key(w, "unlucky_primes");
  w.Uint64(s.unlucky_primes);
  write_key(w, "bad_primes");
  w.Uint64(s.bad_primes);
  write_key(w, "reconstructions");
  w.Uint64(s.reconstructions);
  write_key(w, "checking_primes");
  w.Uint64(s.checking_primes);
  write_key(w, "rejected_candidates");
  w.Uint64(s.rejected_candidates);
  write_key(w, "homogenized");
  w.Bool(s.homogenized);
  write_key(w, "proven");
  w.Bool(s.proven);
  write_key(w, "verification_pairs");
  w.Uint64(s.verification_pairs);
  write_key(w, "threads");
  w.Uint64(s.threads);
  write_key(w, "modular_ms");
  write_milliseconds(w, s.modular_ms);
  write_key(w, "lift_ms");
  write_milliseconds(w, s.lift_ms);
  write_key(w, "verify_ms");
  write_milliseconds(w, s.verify_ms);
  write_key(w, "dehomogenize_ms");
  write_milliseconds(w, s.dehomogenize_ms);
  w.EndObject();
}

// The auxiliary resultant's statistics: what the resultant route did, or, when
// `auto` fell back to Gröbner, what its probe found.
void write_resultant_stats(Writer& w, const AuxiliaryResultantStats& s, std::int32_t map_degree) {
  w.StartObject();
  write_key(w, "dixon_vanishes");
  w.Bool(s.dixon_vanishes);
  write_key(w, "macaulay_vanishes");
  w.Bool(s.macaulay_vanishes);
  if (s.matrix_too_large) {
    write_key(w, "matrix_too_large");
    w.Bool(true);
  }
  if (s.matrix_size > 0) {
    write_key(w, "formulation");
    write_string(w, to_string(s.formulation));
    write_key(w, "matrix_size");
    w.Uint64(s.matrix_size);
    write_key(w, "extraneous_size");
    w.Uint64(s.extraneous_size);
    write_key(w, "degree_bound");
    w.Int(s.degree_bound);
  }
  // The determinant's figures only when it was computed (not when auto's head start
  // let Buchberger answer first).
  if (s.determinant.primes > 0) {
    write_key(w, "map_degree");
    w.Int(map_degree);
    write_key(w, "primes");
    w.Uint64(s.determinant.primes);
    write_key(w, "unlucky_primes");
    w.Uint64(s.determinant.unlucky_primes);
    write_key(w, "evaluations");
    w.Uint64(s.determinant.evaluations);
    write_key(w, "modulus_bits");
    w.Uint64(s.determinant.modulus_bits);
    write_key(w, "proven_bound");
    w.Bool(s.determinant.proven);
    write_key(w, "determinant_ms");
    write_milliseconds(w, s.determinant_ms);
  }
  write_key(w, "construction_ms");
  write_milliseconds(w, s.construction_ms);
  w.EndObject();
}

// The interpolation route's statistics (method interpolation).
void write_interpolation_stats(Writer& w, const InterpolationStats& s) {
  w.StartObject();
  write_key(w, "degree_bound");
  w.Int(s.degree_bound);
  write_key(w, "degree");
  w.Int(s.degree);
  write_key(w, "rows");
  w.Uint64(s.rows);
  write_key(w, "columns");
  w.Uint64(s.columns);
  write_key(w, "primes");
  w.Uint64(s.primes);
  write_key(w, "unlucky_primes");
  w.Uint64(s.unlucky_primes);
  write_key(w, "degree_probes");
  w.Uint64(s.degree_probes);
  write_key(w, "rejected_points");
  w.Uint64(s.rejected_points);
  write_key(w, "rejected_candidates");
  w.Uint64(s.rejected_candidates);
  write_key(w, "modulus_bits");
  w.Uint64(s.modulus_bits);
  write_key(w, "threads");
  w.Uint(s.threads);
  write_key(w, "search_ms");
  write_milliseconds(w, s.search_ms);
  write_key(w, "images_ms");
  write_milliseconds(w, s.images_ms);
  write_key(w, "reconstruction_ms");
  write_milliseconds(w, s.reconstruction_ms);
  w.EndObject();
}

std::string finish(const rapidjson::StringBuffer& buffer) { return std::string(buffer.GetString(), buffer.GetSize()); }

}  // namespace

ImplicitizeRequest decode_implicitize_request(std::string_view body, const JsonParams& limits) {
  const rapidjson::Document document = parse_object(body, limits);
  ObjectReader reader(document);
  ImplicitizeRequest request;
  request.x = read_string(reader.require("x"), "x");
  request.y = read_string(reader.require("y"), "y");
  if (const auto* v = reader.take("z")) request.z = read_string(*v, "z");
  if (const auto* v = reader.take("parameters")) request.parameters = read_strings(*v, "parameters");
  if (const auto* v = reader.take("method")) request.method = read_string(*v, "method");
  if (const auto* v = reader.take("modular")) {
    if (!v->IsBool()) throw wrong_type("modular", "true or false");
    request.modular = v->GetBool();
  }
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = read_timeout_seconds(*v);
  reader.finish("x, y, z, parameters, method, modular, timeout_ms");
  return request;
}

GroebnerRequest decode_groebner_request(std::string_view body, const JsonParams& limits) {
  const rapidjson::Document document = parse_object(body, limits);
  ObjectReader reader(document);
  GroebnerRequest request;
  request.polynomials = read_strings(reader.require("polynomials"), "polynomials");
  if (const auto* v = reader.take("variables")) request.variables = read_strings(*v, "variables");
  if (const auto* v = reader.take("order")) request.order = read_string(*v, "order");
  if (const auto* v = reader.take("weights")) request.weights = read_ints(*v, "weights");
  if (const auto* v = reader.take("eliminate")) request.eliminate = read_strings(*v, "eliminate");
  if (const auto* v = reader.take("method")) request.method = read_string(*v, "method");
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = read_timeout_seconds(*v);
  reader.finish("polynomials, variables, order, weights, eliminate, method, timeout_ms");
  return request;
}

ResultantRequest decode_resultant_request(std::string_view body, const JsonParams& limits) {
  const rapidjson::Document document = parse_object(body, limits);
  ObjectReader reader(document);
  ResultantRequest request;
  request.polynomials = read_strings(reader.require("polynomials"), "polynomials");
  if (request.polynomials.size() != 2) {
    throw InputError("wrong_number_of_polynomials", "'polynomials' must hold exactly two polynomials, F and G (got " +
                                                        std::to_string(request.polynomials.size()) + ")")
        .in_field("polynomials");
  }
  request.variable = read_string(reader.require("variable"), "variable");
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = read_timeout_seconds(*v);
  reader.finish("polynomials, variable, timeout_ms");
  return request;
}

namespace {

// A scene box: six JSON numbers, passed on as the exact decimal value of each double
// (17 significant digits round-trip; the SDF frame then reads it as an exact rational).
std::vector<std::string> read_box_texts(const rapidjson::Value& v) {
  if (!v.IsArray()) throw wrong_type("box", "an array of six numbers");
  std::vector<std::string> box;
  for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
    const rapidjson::Value& x = v[i];
    if (!x.IsNumber()) throw wrong_type("box[" + std::to_string(i) + "]", "a number");
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x.GetDouble());
    box.emplace_back(text);
  }
  return box;
}

}  // namespace

SdfRequest decode_sdf_request(std::string_view body, const JsonParams& limits) {
  // A scene nests an object and a children array per level: allow the deepest
  // scene the scene decoder accepts (kMaxSceneJsonDepth, a few hundred bytes of
  // stack per level in RapidJSON's recursive destructor), whatever the caller's limit.
  JsonParams scene_limits = limits;
  scene_limits.max_depth = std::max(limits.max_depth, kMaxSceneJsonDepth + 1);
  const rapidjson::Document document = parse_object(body, scene_limits);
  ObjectReader reader(document);
  SdfRequest request;
  const rapidjson::Value* scene = reader.take("scene");
  const rapidjson::Value* implicit = reader.take("implicit");
  if (scene && implicit) {
    throw InputError("invalid_value", "send either implicit or scene, not both").in_field("scene");
  }
  if (scene) {
    request.scene = decode_scene(*scene, "scene");
  } else {
    request.implicit = read_string(implicit ? *implicit : reader.require("implicit"), "implicit");
  }
  if (const auto* v = reader.take("mode")) request.mode = read_string(*v, "mode");
  if (const auto* v = reader.take("name")) request.name = read_string(*v, "name");
  if (const auto* v = reader.take("box")) request.box = read_box_texts(*v);
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = read_timeout_seconds(*v);
  reader.finish("implicit, scene, mode, box, name, timeout_ms");
  return request;
}

RenderRequest decode_render_request(std::string_view body, const JsonParams& limits) {
  JsonParams scene_limits = limits;  // as decode_sdf_request: room for the deepest scene
  scene_limits.max_depth = std::max(limits.max_depth, kMaxSceneJsonDepth + 1);
  const rapidjson::Document document = parse_object(body, scene_limits);
  ObjectReader reader(document);
  RenderRequest request;
  const rapidjson::Value* scene = reader.take("scene");
  const rapidjson::Value* implicit = reader.take("implicit");
  const rapidjson::Value* coordinates[3] = {reader.take("x"), reader.take("y"), reader.take("z")};
  const int parametric = (coordinates[0] ? 1 : 0) + (coordinates[1] ? 1 : 0) + (coordinates[2] ? 1 : 0);
  if ((scene ? 1 : 0) + (implicit ? 1 : 0) + (parametric > 0 ? 1 : 0) > 1) {
    throw InputError("invalid_value", "send one of implicit, x/y/z (parametric) or scene").in_field("scene");
  }
  if (scene) {
    request.scene = decode_scene(*scene, "scene");
  } else if (parametric > 0) {
    static const char* const kNames[3] = {"x", "y", "z"};
    std::array<std::string, 3> xyz;
    for (int i = 0; i < 3; ++i) {
      if (!coordinates[i]) {
        throw InputError("missing_field",
                         std::string("a parametric surface needs x, y and z; '") + kNames[i] + "' is missing")
            .in_field(kNames[i]);
      }
      xyz[i] = read_string(*coordinates[i], kNames[i]);
    }
    request.parametric = xyz;
  } else {
    request.implicit = read_string(implicit ? *implicit : reader.require("implicit"), "implicit");
  }
  if (const auto* v = reader.take("parameters")) request.parameters = read_strings(*v, "parameters");
  if (const auto* v = reader.take("mode")) request.mode = read_string(*v, "mode");
  if (const auto* v = reader.take("name")) request.name = read_string(*v, "name");
  if (const auto* v = reader.take("box")) request.box = read_box_texts(*v);
  auto read_size = [&](const char* field, std::size_t& out) {
    if (const auto* v = reader.take(field)) {
      if (!v->IsUint()) throw wrong_type(field, "a positive integer");
      out = v->GetUint();
    }
  };
  read_size("width", request.width);
  read_size("height", request.height);
  if (const auto* v = reader.take("aa")) {
    if (!v->IsUint()) throw wrong_type("aa", "a positive integer");
    request.antialiasing = v->GetUint();
  }
  if (const auto* v = reader.take("method")) request.method = read_string(*v, "method");
  auto read_point = [&](const char* field) -> std::optional<std::array<double, 3>> {
    const auto* v = reader.take(field);
    if (!v) return std::nullopt;
    if (!v->IsArray() || v->Size() != 3) throw wrong_type(field, "an array of three numbers");
    std::array<double, 3> p{};
    for (rapidjson::SizeType i = 0; i < 3; ++i) {
      if (!(*v)[i].IsNumber()) throw wrong_type(std::string(field) + "[" + std::to_string(i) + "]", "a number");
      p[i] = (*v)[i].GetDouble();
    }
    return p;
  };
  request.eye = read_point("eye");
  request.target = read_point("target");
  if (const auto* v = reader.take("precision")) request.precision = read_string(*v, "precision");
  if (const auto* v = reader.take("format")) request.format = read_string(*v, "format");
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = read_timeout_seconds(*v);
  reader.finish(
      "implicit, x, y, z, parameters, scene, mode, box, name, width, height, method, aa, eye, target, precision, "
      "format, timeout_ms");
  return request;
}

namespace {

// RFC 4648 base64 with padding.
std::string encode_base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[v >> 18];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v =
        static_cast<unsigned char>(bytes[i]) << 16 | (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
    out += kAlphabet[v >> 18];
    out += kAlphabet[(v >> 12) & 63];
    out += two ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

}  // namespace

std::string encode_render_response(const RenderAnswer& answer, bool with_png) {
  const RenderStats& s = answer.stats;
  rapidjson::StringBuffer buffer;
  Writer w(buffer);
  configure(w);
  w.StartObject();
  write_key(w, "width");
  w.Uint64(s.width);
  write_key(w, "height");
  w.Uint64(s.height);
  write_key(w, "method");
  write_string(w, to_string(s.method));
  write_key(w, "mode");
  write_string(w, s.mode == SdfMode::safe ? "safe" : "fast");
  write_key(w, "precision");
  write_string(w, answer.precision);
  write_key(w, "rays");
  w.Uint64(s.rays);
  write_key(w, "mean_evaluations");
  w.Double(s.mean_evaluations());
  write_key(w, "max_evaluations");
  w.Uint(s.max_evaluations);
  write_key(w, "out_of_steps");
  w.Uint64(s.out_of_steps);
  write_key(w, "hits");
  w.Uint64(s.hits);
  write_key(w, "shading_evaluations");
  w.Uint64(s.shading_evaluations);
  write_key(w, "threads");
  w.Uint64(s.threads);
  write_key(w, "elapsed_ms");
  write_milliseconds(w, s.elapsed_ms);
  if (with_png) {
    write_key(w, "png_base64");
    write_string(w, encode_base64(answer.png));
  }
  w.EndObject();
  return finish(buffer);
}

std::string encode_implicitize_response(const ImplicitizeAnswer& answer) {
  const ImplicitizeResult& result = answer.result;
  rapidjson::StringBuffer buffer;
  Writer w(buffer);
  configure(w);
  w.StartObject();
  write_key(w, "implicit");
  write_string(w, to_string(result.implicit));
  write_key(w, "degree");
  w.Int(result.degree);
  write_key(w, "variables");
  w.StartArray();
  for (const std::string& v : result.implicit.ring()->variables()) write_string(w, v);
  w.EndArray();
  write_key(w, "method");
  write_string(w, result.method);
  write_key(w, "verified");
  w.Bool(result.verified);
  write_key(w, "elapsed_ms");
  write_milliseconds(w, result.elapsed_ms);
  write_key(w, "stats");
  w.StartObject();
  write_stats_members(w, result.stats);
  write_key(w, "verify_ms");
  write_milliseconds(w, result.verify_ms);
  if (!result.route.empty()) {
    write_key(w, "route");
    write_string(w, result.route);
  }
  if (result.resultant_stats) {
    write_key(w, "resultant");
    write_resultant_stats(w, *result.resultant_stats, result.map_degree);
  }
  if (result.interpolation_stats) {
    write_key(w, "interpolation");
    write_interpolation_stats(w, *result.interpolation_stats);
  }
  if (result.modular_stats) {
    write_key(w, "modular");
    write_modular_stats(w, *result.modular_stats);
  }
  w.EndObject();
  write_key(w, "reproduce");
  w.StartObject();
  write_key(w, "singular");
  write_string(w, answer.reproduce.singular);
  write_key(w, "macaulay2");
  write_string(w, answer.reproduce.macaulay2);
  w.EndObject();
  w.EndObject();
  return finish(buffer);
}

std::string encode_groebner_response(const GroebnerAnswer& answer) {
  rapidjson::StringBuffer buffer;
  Writer w(buffer);
  configure(w);
  w.StartObject();
  write_key(w, "basis");
  write_polynomials(w, answer.basis);
  write_key(w, "order");
  write_string(w, answer.order);
  write_key(w, "method");
  write_string(w, answer.method);
  write_key(w, "stats");
  w.StartObject();
  write_stats_members(w, answer.stats);
  if (answer.modular) {
    write_key(w, "modular");
    write_modular_stats(w, *answer.modular);
  }
  w.EndObject();
  write_key(w, "elapsed_ms");
  write_milliseconds(w, answer.elapsed_ms);
  if (answer.elimination_ideal) {
    write_key(w, "elimination_ideal");
    write_polynomials(w, *answer.elimination_ideal);
  }
  w.EndObject();
  return finish(buffer);
}

std::string encode_resultant_response(const ResultantAnswer& answer) {
  rapidjson::StringBuffer buffer;
  Writer w(buffer);
  configure(w);
  w.StartObject();
  write_key(w, "resultant");
  write_string(w, to_string(answer.resultant));
  write_key(w, "variables");
  w.StartArray();
  for (const std::string& v : answer.variables) write_string(w, v);
  w.EndArray();
  write_key(w, "degree");
  w.Int(answer.degree);
  write_key(w, "method");
  write_string(w, answer.method);
  write_key(w, "elapsed_ms");
  write_milliseconds(w, answer.elapsed_ms);
  w.EndObject();
  return finish(buffer);
}

std::string encode_sdf_response(const SdfAnswer& answer) {
  rapidjson::StringBuffer buffer;
  Writer w(buffer);
  configure(w);
  w.StartObject();
  write_key(w, "glsl");
  write_string(w, answer.glsl);
  write_key(w, "function");
  write_string(w, answer.function);
  write_key(w, "mode");
  write_string(w, answer.mode);
  write_key(w, "box");
  // Full precision here (a box may be 1e-6 wide), not the 3 decimals of times.
  w.SetMaxDecimalPlaces(Writer::kDefaultMaxDecimalPlaces);
  w.StartArray();
  for (double b : answer.box) w.Double(b);
  w.EndArray();
  configure(w);
  write_key(w, "degree");
  w.Int(answer.degree);
  if (answer.nodes > 0) {
    write_key(w, "nodes");
    w.Uint64(answer.nodes);
    write_key(w, "leaves");
    w.StartArray();
    for (const SdfLeafSummary& leaf : answer.leaves) {
      w.StartObject();
      write_key(w, "implicit");
      write_string(w, leaf.implicit);
      write_key(w, "degree");
      w.Int(leaf.degree);
      write_key(w, "trimmed");
      w.Bool(leaf.trimmed);
      w.EndObject();
    }
    w.EndArray();
  }
  write_key(w, "uniforms");
  const std::string uniforms = encode_scene_uniforms(answer.uniforms);
  w.RawValue(uniforms.data(), uniforms.size(), rapidjson::kArrayType);
  w.EndObject();
  return finish(buffer);
}

namespace {

// The contract's error shape: {"error": {"code", "message", ...extra members}}.
// `extra` writes the members that only some errors carry.
template <typename WriteExtra>
std::string encode_error_object(std::string_view code, std::string_view message, WriteExtra&& extra) {
  rapidjson::StringBuffer buffer;
  Writer w(buffer);
  w.StartObject();
  write_key(w, "error");
  w.StartObject();
  write_key(w, "code");
  write_string(w, code);
  write_key(w, "message");
  write_string(w, message);
  extra(w);
  w.EndObject();
  w.EndObject();
  return finish(buffer);
}

}  // namespace

std::string encode_error(const InputError& error) {
  return encode_error_object(error.code(), error.what(), [&](Writer& w) {
    if (error.position()) {
      write_key(w, "position");
      w.Uint64(*error.position());
    }
    if (!error.field().empty()) {
      write_key(w, "field");
      write_string(w, error.field());
    }
  });
}

std::string encode_error(const NoSingleEquation& error) {
  return encode_error_object(error.code(), error.what(), [&](Writer& w) {
    write_key(w, "generators");
    w.StartArray();
    for (const std::string& g : error.generators()) write_string(w, g);
    w.EndArray();
  });
}

std::string encode_error(const LimitExceeded& error) {
  return encode_error_object(limit_error_code(error.limit()), error.what(), [&](Writer& w) {
    write_key(w, "limit");
    write_string(w, to_string(error.limit()));
  });
}

std::string encode_error(std::string_view code, std::string_view message) {
  return encode_error_object(code, message, [](Writer&) {});
}

std::string encode_health_status(std::string_view status) {
  rapidjson::StringBuffer buffer;
  Writer w(buffer);
  w.StartObject();
  write_key(w, "status");
  write_string(w, status);
  w.EndObject();
  return finish(buffer);
}

std::string encode_access_log_entry(std::string_view method, std::string_view path, unsigned status, double ms,
                                    std::size_t bytes) {
  rapidjson::StringBuffer buffer;
  Writer w(buffer);
  configure(w);
  w.StartObject();
  write_key(w, "method");
  write_string(w, method);
  write_key(w, "path");
  write_string(w, path);
  write_key(w, "status");
  w.Uint(status);
  write_key(w, "ms");
  write_milliseconds(w, ms);
  write_key(w, "bytes");
  w.Uint64(bytes);
  w.EndObject();
  return finish(buffer);
}

const char* limit_error_code(Limit limit) {
  switch (limit) {
    case Limit::time:
      return "time_limit_exceeded";
    case Limit::size:
      return "size_limit_exceeded";
    case Limit::memory:
      return "memory_limit_exceeded";
    case Limit::work:
      return "work_limit_exceeded";
    case Limit::cancelled:
      return "cancelled";
  }
  return "limit_exceeded";
}

}  // namespace implicitizer
