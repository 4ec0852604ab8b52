#include "implicitizer/codec/render_json.hpp"

#include <array>
#include <optional>

#include "json_reader.hpp"
#include "json_writer.hpp"
#include "scene_request_json.hpp"

namespace implicitizer {
namespace {

// A positive integer member (width, height, aa), left as it is when absent.
template <typename Count>
void read_count(json::ObjectReader& reader, const char* field, Count& out) {
  if (const auto* v = reader.take(field)) {
    if (!v->IsUint()) throw json::wrong_type(field, "a positive integer");
    out = v->GetUint();
  }
}

std::optional<std::array<double, 3>> read_point(json::ObjectReader& reader, const char* field) {
  const auto* v = reader.take(field);
  if (!v) return std::nullopt;
  if (!v->IsArray() || v->Size() != 3) throw json::wrong_type(field, "an array of three numbers");
  std::array<double, 3> p{};
  for (rapidjson::SizeType i = 0; i < 3; ++i) {
    if (!(*v)[i].IsNumber()) throw json::wrong_type(std::string(field) + "[" + std::to_string(i) + "]", "a number");
    p[i] = (*v)[i].GetDouble();
  }
  return p;
}

std::optional<std::string> read_optional_string(json::ObjectReader& reader, const char* field) {
  if (const auto* v = reader.take(field)) return json::read_string(*v, field);
  return std::nullopt;
}

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

RenderRequest decode_render_request(std::string_view body, const JsonParams& limits) {
  const rapidjson::Document document = json::parse_object(body, json::with_room_for_a_scene(limits));
  json::ObjectReader reader(document);
  RenderRequest request;
  const json::SceneRequestChoices choices = json::read_scene_request(reader, request);
  read_count(reader, "width", request.width);
  read_count(reader, "height", request.height);
  read_count(reader, "aa", request.antialiasing);
  const std::optional<std::string> method = read_optional_string(reader, "method");
  request.eye = read_point(reader, "eye");
  request.target = read_point(reader, "target");
  const std::optional<std::string> precision = read_optional_string(reader, "precision");
  const std::optional<std::string> format = read_optional_string(reader, "format");
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = json::read_timeout_seconds(*v);
  reader.finish((std::string(json::kSceneRequestFields) +
                 ", width, height, method, aa, eye, target, precision, format, timeout_ms")
                    .c_str());
  choices.apply(request);
  if (method) request.method = json::parse_choice(*method, "method", parse_march_method);
  if (precision) request.precision = json::parse_choice(*precision, "precision", parse_evaluation_precision);
  if (format) request.format = json::parse_choice(*format, "format", parse_render_format);
  return request;
}

std::string encode_render_response(const RenderAnswer& answer, bool with_png) {
  const RenderStats& s = answer.stats;
  return json::write_json([&](json::Writer& w) {
    w.StartObject();
    w.Key("width");
    w.Uint64(s.width);
    w.Key("height");
    w.Uint64(s.height);
    w.Key("method");
    json::write_string(w, to_string(s.method));
    w.Key("mode");
    json::write_string(w, to_string(s.mode));
    w.Key("precision");
    json::write_string(w, to_string(answer.precision));
    w.Key("rays");
    w.Uint64(s.rays);
    w.Key("mean_evaluations");
    w.Double(s.mean_evaluations());
    w.Key("max_evaluations");
    w.Uint(s.max_evaluations);
    w.Key("out_of_steps");
    w.Uint64(s.out_of_steps);
    w.Key("hits");
    w.Uint64(s.hits);
    w.Key("shading_evaluations");
    w.Uint64(s.shading_evaluations);
    w.Key("threads");
    w.Uint64(s.threads);
    w.Key("elapsed_ms");
    json::write_milliseconds(w, s.elapsed_ms);
    if (answer.shape) {
      w.Key("shape");
      json::write_string(w, to_string(*answer.shape));
    }
    w.Key("dimension");
    w.Int(answer.dimension);
    if (answer.approximation) json::write_approximation(w, *answer.approximation);
    if (with_png) {
      w.Key("png_base64");
      json::write_string(w, encode_base64(answer.png));
    }
    w.EndObject();
  });
}

}  // namespace implicitizer
