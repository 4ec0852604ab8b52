#include "implicitizer/codec/scene_json.hpp"

#include <rapidjson/document.h>
#include <rapidjson/stringbuffer.h>
#include <rapidjson/writer.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "json_reader.hpp"
#include "scene_value.hpp"

namespace implicitizer {
namespace {

InputError invalid_scene(const std::string& message, const std::string& field) {
  return InputError("invalid_scene", message).in_field(field);
}

InputError invalid_value(const std::string& message, const std::string& field) {
  return InputError("invalid_value", message).in_field(field);
}

std::string read_string(const rapidjson::Value& v, const std::string& field, const char* code = "invalid_value") {
  if (!v.IsString()) throw InputError(code, "'" + field + "' must be a string").in_field(field);
  return std::string(v.GetString(), v.GetStringLength());
}

double read_number(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsNumber()) throw invalid_value("a number is expected", field);
  return v.GetDouble();
}

// An exact number: a JSON number (its shortest round-trip decimal, so 0.1 means 1/10)
// or a string holding a constant expression ("1/3", "2^-10", "1e-30").
Rational read_exact(const rapidjson::Value& v, const std::string& field) {
  std::string text;
  if (v.IsNumber()) {
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v.GetDouble());
    if (error != std::errc()) throw invalid_value("unprintable number", field);
    text.assign(buffer, end);
  } else if (v.IsString()) {
    text.assign(v.GetString(), v.GetStringLength());
  } else {
    throw invalid_value("a number (or an exact number as a string, e.g. \"1/3\") is expected", field);
  }
  Polynomial c(space_ring());
  try {
    c = parse_polynomial(text, space_ring());
  } catch (const InputError&) {
    throw invalid_value("'" + text + "' is not a number", field);
  }
  if (!c.is_constant()) throw invalid_value("'" + text + "' is not a number", field);
  return c.is_zero() ? Rational(0) : c.coefficient(0);
}

std::vector<std::string> read_strings(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsArray()) throw invalid_value("an array of strings is expected", field);
  std::vector<std::string> out;
  for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
    out.push_back(read_string(v[i], field + "[" + std::to_string(i) + "]"));
  }
  return out;
}

SceneBox read_box(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsArray() || v.Size() != 6) throw invalid_value("a box is six numbers [x0, y0, z0, x1, y1, z1]", field);
  SceneBox box;
  for (rapidjson::SizeType i = 0; i < 3; ++i) {
    box.lo[i] = read_exact(v[i], field + "[" + std::to_string(i) + "]");
    box.hi[i] = read_exact(v[i + 3], field + "[" + std::to_string(i + 3) + "]");
  }
  return box;
}

InputError invalid_domain(const std::string& message, const std::string& field) {
  return InputError("invalid_domain", message).in_field(field);
}

// A leaf's domain: one [lo, hi] pair of exact numbers per parameter, lo < hi (the
// count is the leaf's to check: it knows the parameters). Every mistake is
// `invalid_domain` at its path, as for a request's own "domain".
std::vector<std::pair<Rational, Rational>> read_domain(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsArray()) throw invalid_domain("a domain is an array of [lo, hi] pairs, one per parameter", field);
  std::vector<std::pair<Rational, Rational>> out;
  for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
    const std::string item = field + "[" + std::to_string(i) + "]";
    if (!v[i].IsArray() || v[i].Size() != 2) throw invalid_domain("an interval is a pair [lo, hi]", item);
    Rational lo, hi;
    try {
      lo = read_exact(v[i][0], item + "[0]");
      hi = read_exact(v[i][1], item + "[1]");
    } catch (const InputError& e) {
      throw invalid_domain(std::string(e.what()) + " (a domain's bounds are finite numbers)", e.field());
    }
    if (!(lo < hi)) throw invalid_domain("an interval needs lo < hi", item);
    out.emplace_back(lo, hi);
  }
  return out;
}

ParameterValue read_parameter(const rapidjson::Value& v, const ParameterSpec& spec, const std::string& field) {
  if (spec.type != ParameterType::vec3) {
    const double x = read_number(v, field);
    if (spec.type == ParameterType::count && !v.IsInt()) throw invalid_value("an integer is expected", field);
    return ParameterValue(x);
  }
  if (!v.IsArray() || v.Size() != 3) throw invalid_value("a vec3 is an array of three numbers", field);
  return ParameterValue(Vec3<double>{read_number(v[0], field + "[0]"), read_number(v[1], field + "[1]"),
                                     read_number(v[2], field + "[2]")});
}

// "type, name, uniforms, ..." : the keys a node of `info`'s kind may have.
std::string allowed_keys(const NodeKindInfo& info) {
  std::string allowed = "type, name, uniforms";
  if (info.arity == NodeArity::nary) allowed += ", children";
  if (info.arity == NodeArity::unary) allowed += ", child";
  if (info.kind == NodeKind::implicit) allowed += ", equation, shape, box";
  if (info.kind == NodeKind::parametric) allowed += ", x, y, z, parameters, domain, tolerance, shape, box";
  for (const ParameterSpec& p : info.parameters) allowed += ", " + std::string(p.name);
  return allowed;
}

// The kind named by the node's "type", after its keys were found distinct.
const NodeKindInfo& kind_of(const rapidjson::Value& value, const std::string& path) {
  if (!value.IsObject()) throw invalid_scene("a scene node is a JSON object with a \"type\"", path);
  std::set<std::string> keys;
  for (auto m = value.MemberBegin(); m != value.MemberEnd(); ++m) {
    const std::string key(m->name.GetString(), m->name.GetStringLength());
    if (!keys.insert(key).second) throw invalid_scene("key '" + key + "' is given twice", path + "." + key);
  }
  const auto type = value.FindMember("type");
  if (type == value.MemberEnd()) throw invalid_scene("a scene node needs a \"type\"", path + ".type");
  const std::string type_name = read_string(type->value, path + ".type", "invalid_scene");
  const NodeKindInfo* info = find_node_kind(type_name);
  if (info == nullptr) {
    std::string known;
    for (const NodeKindInfo& k : node_kinds()) known += (known.empty() ? "" : ", ") + std::string(k.type_name);
    throw InputError("unknown_node_type", "unknown node type '" + type_name + "' (known: " + known + ")")
        .in_field(path + ".type");
  }
  return *info;
}

// Required members the kind table does not list.
void check_required_members(const rapidjson::Value& value, const NodeKindInfo& info, const std::string& path) {
  const std::string type_name(info.type_name);
  if (info.arity == NodeArity::nary && !value.HasMember("children")) {
    throw InputError("missing_parameter", "a " + type_name + " needs \"children\"").in_field(path + ".children");
  }
  if (info.arity == NodeArity::unary && !value.HasMember("child")) {
    throw InputError("missing_parameter", "a " + type_name + " needs \"child\"").in_field(path + ".child");
  }
  if (info.kind == NodeKind::implicit && !value.HasMember("equation")) {
    throw InputError("missing_parameter", "an implicit leaf needs \"equation\"").in_field(path + ".equation");
  }
  if (info.kind == NodeKind::parametric) {
    for (const char* axis : {"x", "y", "z"}) {
      if (!value.HasMember(axis)) {
        throw InputError("missing_parameter", std::string("a parametric leaf needs \"") + axis + "\"")
            .in_field(path + "." + axis);
      }
    }
  }
}

class SceneDecoder {
 public:
  SceneNode decode(const rapidjson::Value& value, const std::string& path, std::size_t depth);

 private:
  // Reads the member `key` (not "type") of a node of kind `info` into `node`.
  void read_member(const std::string& key, const rapidjson::Value& v, const NodeKindInfo& info,
                   const std::string& field, std::size_t depth, SceneNode& node);

  std::size_t nodes_ = 0;
};

SceneNode SceneDecoder::decode(const rapidjson::Value& value, const std::string& path, std::size_t depth) {
  // Counted before reading the children, so neither count nor depth can grow past
  // the limits however the text is shaped.
  if (++nodes_ > kMaxSceneNodes) {
    throw InputError("scene_too_large", "a scene has at most " + std::to_string(kMaxSceneNodes) + " nodes")
        .in_field(path);
  }
  if (depth > kMaxSceneDepth) {
    throw InputError("scene_too_large", "a scene is at most " + std::to_string(kMaxSceneDepth) + " levels deep")
        .in_field(path);
  }
  const NodeKindInfo& info = kind_of(value, path);
  SceneNode node;
  node.kind = info.kind;
  for (auto m = value.MemberBegin(); m != value.MemberEnd(); ++m) {
    const std::string key(m->name.GetString(), m->name.GetStringLength());
    if (key != "type") read_member(key, m->value, info, path + "." + key, depth, node);
  }
  check_required_members(value, info, path);
  return node;
}

void SceneDecoder::read_member(const std::string& key, const rapidjson::Value& v, const NodeKindInfo& info,
                               const std::string& field, std::size_t depth, SceneNode& node) {
  const bool implicit = info.kind == NodeKind::implicit, parametric = info.kind == NodeKind::parametric;
  if (key == "name") {
    node.name = read_string(v, field, "invalid_name");
  } else if (key == "uniforms") {
    node.uniforms = read_strings(v, field);
  } else if (key == "children" && info.arity == NodeArity::nary) {
    if (!v.IsArray()) throw invalid_scene("\"children\" is an array of nodes", field);
    for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
      node.children.push_back(decode(v[i], field + "[" + std::to_string(i) + "]", depth + 1));
    }
  } else if (key == "child" && info.arity == NodeArity::unary) {
    node.children.push_back(decode(v, field, depth + 1));
  } else if (implicit && key == "equation") {
    node.leaf.equation = read_string(v, field);
  } else if (parametric && (key == "x" || key == "y" || key == "z")) {
    node.leaf.coordinates[static_cast<std::size_t>(key[0] - 'x')] = read_string(v, field);
  } else if (parametric && key == "parameters") {
    node.leaf.parameter_names = read_strings(v, field);
  } else if (parametric && key == "domain") {
    node.leaf.domain = read_domain(v, field);
  } else if ((implicit || parametric) && key == "shape") {
    try {
      node.leaf.shape = parse_sdf_shape(read_string(v, field));
    } catch (const InputError& e) {
      throw e.in_field(field);
    }
  } else if ((implicit || parametric) && key == "tolerance") {
    // An implicit leaf's is read too, so that the leaf refuses it by name
    // (`invalid_tolerance`: only parametric inputs are approximated).
    node.leaf.tolerance = json::read_tolerance(v, field);
  } else if ((implicit || parametric) && key == "box") {
    node.leaf.box = read_box(v, field);
  } else {
    const ParameterSpec* spec = nullptr;
    for (const ParameterSpec& p : info.parameters) {
      if (p.name == key) spec = &p;
    }
    if (spec == nullptr) {
      throw invalid_scene(
          "a " + std::string(info.type_name) + " has no key '" + key + "' (allowed: " + allowed_keys(info) + ")",
          field);
    }
    node.parameters.emplace_back(key, read_parameter(v, *spec, field));
  }
}

}  // namespace

SceneNode decode_scene(const rapidjson::Value& value, const std::string& path) {
  return SceneDecoder().decode(value, path, 1);
}

SceneNode parse_scene_json(std::string_view text, const std::string& path) {
  return decode_scene(json::parse_json(text, kMaxSceneJsonDepth), path);
}

namespace {

using SceneWriter = rapidjson::Writer<rapidjson::StringBuffer>;

void write_text(SceneWriter& w, const std::string& text) {
  w.String(text.c_str(), static_cast<rapidjson::SizeType>(text.size()));
}

// A number, or [x, y, z] for a vec3.
void write_parameter(SceneWriter& w, const Vec3<double>& value, bool is_vector) {
  if (!is_vector) {
    w.Double(value.x);
    return;
  }
  w.StartArray();
  w.Double(value.x);
  w.Double(value.y);
  w.Double(value.z);
  w.EndArray();
}

// Exact numbers as exact strings ("1/3"): read_exact() reads them back unchanged.
void write_exact(SceneWriter& w, const Rational& q) { write_text(w, to_string(q)); }

// The members of a leaf: the equation, or x, y, z, parameters and domain; its box.
void write_leaf_members(SceneWriter& w, const SceneNode& node) {
  if (node.kind == NodeKind::implicit) {
    w.Key("equation");
    write_text(w, node.leaf.equation);
  }
  if (node.kind == NodeKind::parametric) {
    const char* const keys[3] = {"x", "y", "z"};
    for (std::size_t i = 0; i < 3; ++i) {
      w.Key(keys[i]);
      write_text(w, node.leaf.coordinates[i]);
    }
    if (node.leaf.parameter_names) {
      w.Key("parameters");
      w.StartArray();
      for (const std::string& name : *node.leaf.parameter_names) write_text(w, name);
      w.EndArray();
    }
    if (!node.leaf.domain.empty()) {
      w.Key("domain");
      w.StartArray();
      for (const auto& [lo, hi] : node.leaf.domain) {
        w.StartArray();
        write_exact(w, lo);
        write_exact(w, hi);
        w.EndArray();
      }
      w.EndArray();
    }
  }
  // Part of the canonical form (the cache key): auto is the default and is left out.
  if ((node.kind == NodeKind::implicit || node.kind == NodeKind::parametric) &&
      node.leaf.shape != SdfShape::automatic) {
    w.Key("shape");
    w.String(to_string(node.leaf.shape));
  }
  if (node.leaf.tolerance) {
    w.Key("tolerance");
    w.Double(*node.leaf.tolerance);  // shortest round-trip: the cache key keeps it exact
  }
  if (node.leaf.box) {
    w.Key("box");
    w.StartArray();
    for (const Rational& q : node.leaf.box->lo) write_exact(w, q);
    for (const Rational& q : node.leaf.box->hi) write_exact(w, q);
    w.EndArray();
  }
}

void write_node(SceneWriter& w, const SceneNode& node) {
  w.StartObject();
  w.Key("type");
  const std::string_view type = node_kind_info(node.kind).type_name;
  w.String(type.data(), static_cast<rapidjson::SizeType>(type.size()));
  auto parameters = node.parameters;
  std::sort(parameters.begin(), parameters.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [key, value] : parameters) {
    write_text(w, key);
    write_parameter(w, value.value, value.is_vector);
  }
  if (!node.name.empty()) {
    w.Key("name");
    write_text(w, node.name);
  }
  if (!node.uniforms.empty()) {
    w.Key("uniforms");
    w.StartArray();
    for (const std::string& u : node.uniforms) write_text(w, u);
    w.EndArray();
  }
  write_leaf_members(w, node);
  const NodeArity arity = node_kind_info(node.kind).arity;
  if (arity == NodeArity::unary && node.children.size() == 1) {
    w.Key("child");
    write_node(w, node.children[0]);
  } else if (arity != NodeArity::leaf || !node.children.empty()) {
    w.Key("children");
    w.StartArray();
    for (const SceneNode& child : node.children) write_node(w, child);
    w.EndArray();
  }
  w.EndObject();
}

}  // namespace

std::string encode_scene(const SceneNode& root) {
  rapidjson::StringBuffer buffer;
  SceneWriter w(buffer);
  write_node(w, root);
  return buffer.GetString();
}

std::string encode_scene_uniforms(const std::vector<SceneUniform>& uniforms) {
  rapidjson::StringBuffer buffer;
  rapidjson::Writer<rapidjson::StringBuffer> w(buffer);
  w.StartArray();
  for (const SceneUniform& u : uniforms) {
    w.StartObject();
    w.Key("name");
    w.String(u.name.c_str(), static_cast<rapidjson::SizeType>(u.name.size()));
    w.Key("type");
    w.String(u.type == ParameterType::vec3 ? "vec3" : "float");
    w.Key("default");
    write_parameter(w, u.default_value, u.type == ParameterType::vec3);
    w.EndObject();
  }
  w.EndArray();
  return buffer.GetString();
}

}  // namespace implicitizer
