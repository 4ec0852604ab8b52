#include "implicitizer/codec/sdf_json.hpp"

#include <optional>

#include "implicitizer/codec/scene_json.hpp"
#include "json_reader.hpp"
#include "json_writer.hpp"
#include "scene_value.hpp"

namespace implicitizer {
namespace {

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
    w.EndObject();
  }
  w.EndArray();
}

}  // namespace

SdfRequest decode_sdf_request(std::string_view body, const JsonParams& limits) {
  const rapidjson::Document document = json::parse_object(body, json::with_room_for_a_scene(limits));
  json::ObjectReader reader(document);
  SdfRequest request;
  const rapidjson::Value* scene = reader.take("scene");
  const rapidjson::Value* implicit = reader.take("implicit");
  if (scene && implicit) {
    throw InputError("invalid_value", "send either implicit or scene, not both").in_field("scene");
  }
  if (scene) {
    request.scene = decode_scene(*scene, "scene");
  } else {
    request.implicit = json::read_string(implicit ? *implicit : reader.require("implicit"), "implicit");
  }
  std::optional<std::string> mode;
  if (const auto* v = reader.take("mode")) mode = json::read_string(*v, "mode");
  if (const auto* v = reader.take("name")) request.name = json::read_string(*v, "name");
  if (const auto* v = reader.take("box")) request.box = json::read_box_texts(*v);
  if (const auto* v = reader.take("timeout_ms")) request.timeout_seconds = json::read_timeout_seconds(*v);
  reader.finish("implicit, scene, mode, box, name, timeout_ms");
  if (mode) request.mode = json::parse_choice(*mode, "mode", parse_sdf_mode);
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
    w.Key("box");
    // Full precision here (a box may be 1e-6 wide), not the 3 decimals of times.
    w.SetMaxDecimalPlaces(json::Writer::kDefaultMaxDecimalPlaces);
    w.StartArray();
    for (double b : answer.box) w.Double(b);
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
    w.Key("uniforms");
    const std::string uniforms = encode_scene_uniforms(answer.uniforms);
    w.RawValue(uniforms.data(), uniforms.size(), rapidjson::kArrayType);
    w.EndObject();
  });
}

}  // namespace implicitizer
