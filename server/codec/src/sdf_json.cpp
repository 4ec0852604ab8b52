#include "implicitizer/codec/sdf_json.hpp"

#include <optional>

#include "implicitizer/codec/scene_json.hpp"
#include "json_reader.hpp"
#include "json_writer.hpp"
#include "scene_request_json.hpp"

namespace implicitizer {
namespace {

void write_trimming(json::Writer& w, const TrimmingSummary& t) {
  w.Key("trimming");
  w.StartObject();
  w.Key("method");
  json::write_string(w, t.method);
  w.Key("leaves");
  w.Uint64(t.leaves);
  w.Key("box_leaves");
  w.Uint64(t.box_leaves);
  w.Key("blunt_edge_leaves");
  w.Uint64(t.blunt_edge_leaves);
  w.EndObject();
}

void write_leaves(json::Writer& w, const std::vector<SdfLeafSummary>& leaves) {
  w.StartArray();
  for (const SdfLeafSummary& leaf : leaves) {
    w.StartObject();
    w.Key("implicit");
    json::write_string(w, leaf.implicit);
    w.Key("degree");
    w.Int(leaf.degree);
    w.Key("trimmed");
    w.Bool(leaf.trimmed);
    w.Key("shape");
    json::write_string(w, to_string(leaf.shape));
    if (leaf.trimming) write_trimming(w, *leaf.trimming);
    if (leaf.approximation) json::write_approximation(w, *leaf.approximation);
    w.EndObject();
  }
  w.EndArray();
}

}  // namespace

SdfRequest decode_sdf_request(std::string_view body, const JsonParams& limits) {
  const rapidjson::Document document = json::parse_object(body, json::with_room_for_a_scene(limits));
  json::ObjectReader reader(document);
  SdfRequest request;
  const json::SceneRequestChoices choices = json::read_scene_request(reader, request);
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = json::read_timeout_seconds(*v);
  reader.finish((std::string(json::kSceneRequestFields) + ", timeout_ms").c_str());
  choices.apply(request);
  return request;
}

std::string encode_sdf_response(const SdfAnswer& answer) {
  return json::write_json([&](json::Writer& w) {
    w.StartObject();
    w.Key("glsl");
    json::write_string(w, answer.glsl);
    w.Key("function");
    json::write_string(w, answer.function);
    w.Key("mode");
    json::write_string(w, to_string(answer.mode));
    if (answer.shape) {
      w.Key("shape");
      json::write_string(w, to_string(*answer.shape));
    }
    w.Key("dimension");
    w.Int(answer.dimension);
    w.Key("box");
    // Full precision here (a box may be 1e-6 wide), not the 3 decimals of times.
    w.SetMaxDecimalPlaces(json::Writer::kDefaultMaxDecimalPlaces);
    w.StartArray();
    // A curve's box is its plane box x0, y0, x1, y1 (its frame's z side is internal).
    if (answer.dimension == 2) {
      for (std::size_t i : {0, 1, 3, 4}) w.Double(answer.box[i]);
    } else {
      for (double b : answer.box) w.Double(b);
    }
    w.EndArray();
    json::configure(w);
    w.Key("degree");
    w.Int(answer.degree);
    if (answer.nodes > 0) {
      w.Key("nodes");
      w.Uint64(answer.nodes);
      w.Key("leaves");
      write_leaves(w, answer.leaves);
    }
    if (answer.trimming) write_trimming(w, *answer.trimming);
    if (!answer.side_function.empty()) {
      w.Key("side");
      w.StartObject();
      w.Key("glsl");
      json::write_string(w, answer.side_glsl);
      w.Key("function");
      json::write_string(w, answer.side_function);
      w.EndObject();
    }
    if (answer.approximation) json::write_approximation(w, *answer.approximation);
    w.Key("uniforms");
    const std::string uniforms = encode_scene_uniforms(answer.uniforms);
    w.RawValue(uniforms.data(), uniforms.size(), rapidjson::kArrayType);
    w.EndObject();
  });
}

}  // namespace implicitizer
