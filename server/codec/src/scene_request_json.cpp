#include "scene_request_json.hpp"

#include <array>
#include <charconv>

#include "implicitizer/sdf/sdf_shape.hpp"
#include "scene_value.hpp"

namespace implicitizer::json {
namespace {

// x and y (and z for a surface), or none of them.
std::optional<std::array<std::string, 3>> read_parametric(ObjectReader& reader) {
  static const char* const kNames[3] = {"x", "y", "z"};
  const rapidjson::Value* coordinates[3] = {reader.take("x"), reader.take("y"), reader.take("z")};
  if (!coordinates[0] && !coordinates[1] && !coordinates[2]) return std::nullopt;
  std::array<std::string, 3> xyz;
  for (int i = 0; i < 2; ++i) {
    if (!coordinates[i]) {
      throw InputError("missing_field", std::string("a parametric surface needs x, y and z, a curve x and y; '") +
                                            kNames[i] + "' is missing")
          .in_field(kNames[i]);
    }
    xyz[i] = read_string(*coordinates[i], kNames[i]);
  }
  if (coordinates[2]) {
    xyz[2] = read_string(*coordinates[2], "z");
    if (xyz[2].empty()) {
      throw InputError("invalid_value", "z is empty; leave it out for a plane curve (x, y)").in_field("z");
    }
  }
  return xyz;
}

// A domain: exact numbers as JSON numbers (their shortest round-trip decimal, so 0.1
// is 1/10, as in a scene leaf's domain) or strings ("1/3").
std::vector<std::string> read_domain_texts(const rapidjson::Value& v) {
  if (!v.IsArray()) {
    throw InputError("invalid_domain", "a domain is an array of numbers [s0, s1] or [s0, s1, t0, t1]")
        .in_field("domain");
  }
  std::vector<std::string> texts;
  for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
    const rapidjson::Value& x = v[i];
    if (x.IsString()) {
      texts.emplace_back(x.GetString(), x.GetStringLength());
    } else if (x.IsNumber()) {
      char text[40];
      const auto [end, error] = std::to_chars(text, text + sizeof text, x.GetDouble());
      texts.emplace_back(text, error == std::errc() ? end : text);
    } else {
      throw InputError("invalid_domain", "a domain's bounds are numbers (or exact numbers as strings, \"1/3\")")
          .in_field("domain[" + std::to_string(i) + "]");
    }
  }
  return texts;
}

void write_bound(Writer& w, const char* key, double bound, BoundMethod method, std::size_t samples) {
  w.Key(key);
  w.StartObject();
  w.Key("bound");
  w.Double(bound);
  w.Key("method");
  write_string(w, to_string(method));
  if (method == BoundMethod::measured) {
    w.Key("samples");
    w.Uint64(samples);
  }
  w.EndObject();
}

}  // namespace

void write_approximation(Writer& w, const ApproximationSummary& s) {
  w.Key("approximation");
  // Full precision (a bound of 1e-5 is not 0.000), then the writer's usual places.
  w.SetMaxDecimalPlaces(Writer::kDefaultMaxDecimalPlaces);
  w.StartObject();
  w.Key("tolerance");
  w.Double(s.tolerance);
  w.Key("exact");
  w.Bool(!s.kept_exact.empty());
  if (!s.kept_exact.empty()) {
    w.Key("reason");
    write_string(w, s.kept_exact);
  }
  w.Key("degree");
  w.Int(s.degree);
  w.Key("pieces");
  w.Uint64(s.pieces);
  w.Key("glsl_lines");
  w.Uint64(s.glsl_lines);
  write_bound(w, "patch_to_surface", s.patch_to_surface, s.patch_to_surface_method, 0);
  write_bound(w, "surface_to_patch", s.surface_to_patch, s.surface_to_patch_method, s.surface_to_patch_samples);
  w.EndObject();
  configure(w);
}

void SceneRequestChoices::apply(SceneRequest& request) const {
  if (mode) request.mode = parse_choice(*mode, "mode", parse_sdf_mode);
  if (shape) request.shape = parse_choice(*shape, "shape", parse_sdf_shape);
}

SceneRequestChoices read_scene_request(ObjectReader& reader, SceneRequest& request) {
  const rapidjson::Value* scene = reader.take("scene");
  const rapidjson::Value* implicit = reader.take("implicit");
  std::optional<std::array<std::string, 3>> parametric = read_parametric(reader);
  if ((scene ? 1 : 0) + (implicit ? 1 : 0) + (parametric ? 1 : 0) > 1) {
    throw InputError("invalid_value", "send one of implicit, x/y[/z] (parametric) or scene").in_field("scene");
  }
  if (scene) {
    request.scene = decode_scene(*scene, "scene");
  } else if (parametric) {
    request.parametric = std::move(parametric);
  } else {
    request.implicit = read_string(implicit ? *implicit : reader.require("implicit"), "implicit");
  }
  if (const auto* v = reader.take("parameters")) request.parameters = read_strings(*v, "parameters");
  if (const auto* v = reader.take("domain")) request.domain = read_domain_texts(*v);
  if (const auto* v = reader.take("tolerance")) request.tolerance = read_tolerance(*v, "tolerance");
  if (const auto* v = reader.take("box")) request.box = read_box_texts(*v);
  if (const auto* v = reader.take("name")) request.name = read_string(*v, "name");
  SceneRequestChoices choices;
  if (const auto* v = reader.take("mode")) choices.mode = read_string(*v, "mode");
  if (const auto* v = reader.take("shape")) choices.shape = read_string(*v, "shape");
  return choices;
}

}  // namespace implicitizer::json
