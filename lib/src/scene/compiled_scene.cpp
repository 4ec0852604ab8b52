#include "implicitizer/scene/compiled_scene.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/sdf/glsl_name.hpp"
#include "implicitizer/sdf/polynomial_program.hpp"
#include "node_operations.hpp"

// Compiling (validation, slots, uniforms, leaves), the evaluator's entry and the GLSL
// writer's frame. What each node kind does at each stage lives beside its concept
// (node_operations.hpp): here every stage calls the node's operations.

namespace implicitizer {

using Node = CompiledScene::Node;
using Slot = CompiledScene::Slot;

// ---------------------------------------------------------------------------------
// Compilation: validation, slots, uniforms, leaves, classes.

class SceneCompiler {
 public:
  SceneCompiler(const SceneParams& options, const Budget& budget) : options_(options), budget_(budget) {
    scene_.name_ = options.name;
    scene_.mode_ = options.mode;
    scene_.dimension_ = options.dimension;
  }

  CompiledScene run(const SceneNode& root);

 private:
  std::uint32_t compile(const SceneNode& node, const std::string& path, std::size_t depth);
  // Reads the node's parameters into out.slots (the table's order), registering
  // the uniforms it exposes.
  void read_parameters(const SceneNode& node, const NodeKindInfo& info, const std::string& path, Node& out);
  // Which parameters the node's "uniforms" list exposes (each checked: known, uniformable, once).
  static std::vector<bool> exposed_parameters(const SceneNode& node, const NodeKindInfo& info, const std::string& path);
  // The value of parameter `spec` (given, else its default), checked against its type and range.
  static Vec3<double> parameter_value(const SceneNode& node, const NodeKindInfo& info, const ParameterSpec& spec,
                                      const std::string& field);
  static void check_range(const ParameterSpec& spec, const Vec3<double>& v, const std::string& field);
  // Registers uniform `name` at its default `value`; returns its index.
  std::int32_t add_uniform(const std::string& name, ParameterType type, const Vec3<double>& value,
                           const std::string& field, const std::string& path);
  static void store_box(const NodeBox& box, Node& out);

  const SceneParams& options_;
  const Budget& budget_;
  CompiledScene scene_;
  std::set<std::string> node_names_;
  std::size_t visited_ = 0;
};

CompiledScene compile_scene(const SceneNode& root, const SceneParams& options, const Budget& budget) {
  return SceneCompiler(options, budget).run(root);
}

void SceneCompiler::read_parameters(const SceneNode& node, const NodeKindInfo& info, const std::string& path,
                                    Node& out) {
  for (const auto& parameter : node.parameters) {
    // Named, not a structured binding: lambdas may not capture those before C++20's
    // P1091 (clang 14, which builds the fuzzers, refuses it).
    const std::string& key = parameter.first;
    const auto spec = std::find_if(info.parameters.begin(), info.parameters.end(),
                                   [&](const ParameterSpec& p) { return p.name == key; });
    if (spec == info.parameters.end()) {
      throw InputError("invalid_scene", "a " + std::string(info.type_name) + " has no parameter '" + key + "'")
          .in_field(path + "." + key);
    }
  }
  const std::vector<bool> exposed = exposed_parameters(node, info, path);
  for (std::size_t i = 0; i < info.parameters.size(); ++i) {
    const ParameterSpec& spec = info.parameters[i];
    const std::string field = path + "." + std::string(spec.name);
    const Vec3<double> v = parameter_value(node, info, spec, field);
    if (spec.type == ParameterType::count) out.count = static_cast<std::int32_t>(v.x);
    Slot slot = baked_slot(v);
    if (exposed[i]) slot.uniform = add_uniform(node.name + "_" + std::string(spec.name), spec.type, v, field, path);
    out.slots.push_back(slot);
  }
}

std::vector<bool> SceneCompiler::exposed_parameters(const SceneNode& node, const NodeKindInfo& info,
                                                    const std::string& path) {
  std::vector<bool> exposed(info.parameters.size(), false);
  if (!node.uniforms.empty() && node.name.empty()) {
    throw InputError("invalid_scene", "uniforms are named after their node: give the node a \"name\"")
        .in_field(path + ".uniforms");
  }
  for (std::size_t u = 0; u < node.uniforms.size(); ++u) {
    const std::string field = path + ".uniforms[" + std::to_string(u) + "]";
    const std::string& parameter = node.uniforms[u];
    std::size_t index = info.parameters.size();
    for (std::size_t i = 0; i < info.parameters.size(); ++i) {
      if (info.parameters[i].name == parameter) index = i;
    }
    if (index == info.parameters.size()) {
      throw InputError("invalid_value", "a " + std::string(info.type_name) + " has no parameter '" + parameter + "'")
          .in_field(field);
    }
    if (!info.parameters[index].uniformable) {
      throw InputError("invalid_value",
                       "parameter '" + parameter + "' of a " + std::string(info.type_name) +
                           " is fixed at compile time (it shapes the code or is normalised) and cannot be a uniform")
          .in_field(field);
    }
    if (exposed[index]) throw InputError("name_collision", "uniform '" + parameter + "' listed twice").in_field(field);
    exposed[index] = true;
  }
  return exposed;
}

Vec3<double> SceneCompiler::parameter_value(const SceneNode& node, const NodeKindInfo& info, const ParameterSpec& spec,
                                            const std::string& field) {
  const auto given =
      std::find_if(node.parameters.begin(), node.parameters.end(), [&](const auto& p) { return p.first == spec.name; });
  ParameterValue value;
  if (given != node.parameters.end()) {
    value = given->second;
  } else if (spec.default_value) {
    value = ParameterValue(*spec.default_value);
  } else {
    throw InputError("missing_parameter",
                     "a " + std::string(info.type_name) + " needs '" + std::string(spec.name) + "'")
        .in_field(field);
  }
  const bool wants_vector = spec.type == ParameterType::vec3;
  if (value.is_vector != wants_vector) {
    throw InputError("invalid_value", std::string(spec.name) + " is " + (wants_vector ? "a vec3" : "a number"))
        .in_field(field);
  }
  const Vec3<double>& v = value.value;
  for (double c : {v.x, v.y, v.z}) {
    if (!std::isfinite(c) || std::fabs(c) > kMaxParameterMagnitude) {
      throw InputError("invalid_value", std::string(spec.name) + " must be finite and at most 1e18 in magnitude")
          .in_field(field);
    }
  }
  check_range(spec, v, field);
  return v;
}

void SceneCompiler::check_range(const ParameterSpec& spec, const Vec3<double>& v, const std::string& field) {
  const auto fail = [&](const std::string& what) {
    return InputError("invalid_value", std::string(spec.name) + " must be " + what).in_field(field);
  };
  switch (spec.range) {
    case ParameterRange::any:
      break;
    case ParameterRange::positive:
      if (!(v.x > 0)) throw fail("positive");
      break;
    case ParameterRange::non_negative:
      if (!(v.x >= 0)) throw fail("at least 0");
      break;
    case ParameterRange::nonzero_vector:
      if (v.x == 0 && v.y == 0 && v.z == 0) throw fail("a non-zero vector");
      break;
    case ParameterRange::positive_components:
      if (!(v.x > 0 && v.y > 0 && v.z > 0)) throw fail("positive on every axis");
      break;
    case ParameterRange::acute_angle:
      if (!(v.x > 0 && v.x < std::acos(0.0))) throw fail("an angle in (0, pi/2) radians");
      break;
  }
  if (spec.type == ParameterType::count && (v.x != std::floor(v.x) || v.x < 1 || v.x > kMaxCount)) {
    throw fail("an integer from 1 to " + std::to_string(kMaxCount));
  }
}

std::int32_t SceneCompiler::add_uniform(const std::string& name, ParameterType type, const Vec3<double>& value,
                                        const std::string& field, const std::string& path) {
  SceneUniform uniform;
  uniform.name = name;
  const std::string uniform_field = path + ".uniforms";
  try {
    check_glsl_name(uniform.name);
  } catch (const InputError& e) {
    throw InputError(e.code(), "uniform '" + uniform.name + "': " + e.what()).in_field(uniform_field);
  }
  if (scene_.find_uniform(uniform.name)) {
    throw InputError("name_collision", "two uniforms are named '" + uniform.name + "'").in_field(uniform_field);
  }
  uniform.type = type;
  uniform.default_value = value;
  uniform.field = field;
  scene_.uniforms_.push_back(uniform);
  scene_.defaults_.push_back(value);
  return static_cast<std::int32_t>(scene_.uniforms_.size() - 1);
}

// The node's box, and its float copy rounded outwards: ±inf (and beyond the float
// range) become ∓/± the largest float, which GLSL can state and which stays outside
// every scene.
void SceneCompiler::store_box(const NodeBox& box, Node& out) {
  out.box_lo = box.lo;
  out.box_hi = box.hi;
  out.box_grows = box.grows;
  const Vec3<double>& lo = box.lo;
  const Vec3<double>& hi = box.hi;
  const auto down = [](double x) {
    const float f = static_cast<float>(x);
    if (!(f > -std::numeric_limits<float>::max())) return -std::numeric_limits<float>::max();
    return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
  };
  const auto up = [](double x) {
    const float f = static_cast<float>(x);
    if (!(f < std::numeric_limits<float>::max())) return std::numeric_limits<float>::max();
    return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
  };
  out.box_lo_float = {down(lo.x), down(lo.y), down(lo.z)};
  out.box_hi_float = {up(hi.x), up(hi.y), up(hi.z)};
}

std::uint32_t SceneCompiler::compile(const SceneNode& node, const std::string& path, std::size_t depth) {
  budget_.check("compile_scene");
  if (++visited_ > kMaxSceneNodes) {
    throw InputError("scene_too_large", "a scene has at most " + std::to_string(kMaxSceneNodes) + " nodes")
        .in_field(path);
  }
  if (depth > kMaxSceneDepth) {
    throw InputError("scene_too_large", "a scene is at most " + std::to_string(kMaxSceneDepth) + " levels deep")
        .in_field(path);
  }
  const NodeKindInfo& info = node_kind_info(node.kind);
  const std::size_t n = node.children.size();
  if (info.arity == NodeArity::leaf && n != 0) {
    throw InputError("invalid_scene", "a " + std::string(info.type_name) + " has no children").in_field(path);
  }
  if (info.arity == NodeArity::unary && n != 1) {
    throw InputError("invalid_scene", "a " + std::string(info.type_name) + " has exactly one child")
        .in_field(path + ".child");
  }
  if (info.arity == NodeArity::nary && n < 2) {
    throw InputError("invalid_scene", "a " + std::string(info.type_name) + " has at least two children")
        .in_field(path + ".children");
  }
  if (!node.name.empty()) {
    try {
      check_glsl_name(node.name);
    } catch (const InputError& e) {
      throw e.in_field(path + ".name");
    }
    if (!node_names_.insert(node.name).second) {
      throw InputError("name_collision", "two nodes are named '" + node.name + "'").in_field(path + ".name");
    }
  }

  Node out;
  out.kind = node.kind;
  out.operations = info.operations;
  read_parameters(node, info, path, out);
  for (std::size_t i = 0; i < n; ++i) {
    out.children.push_back(compile(node.children[i], child_field(path, info.arity, i), depth + 1));
  }
  if (node.kind == NodeKind::implicit || node.kind == NodeKind::parametric) {
    out.leaf = static_cast<std::int32_t>(scene_.leaves_.size());
    scene_.leaves_.push_back(
        PolynomialLeaf::build(node.kind, node.leaf, options_.box, options_.mode, budget_, path, options_.dimension));
  }
  NodeCompilation compilation{out, path, options_.mode, scene_.nodes_, scene_.leaves_};
  info.operations->classify(compilation);
  store_box(info.operations->bound(compilation), out);
  scene_.nodes_.push_back(std::move(out));
  return static_cast<std::uint32_t>(scene_.nodes_.size() - 1);
}

// ---------------------------------------------------------------------------------
// The C++ evaluator.

template <typename T>
T CompiledScene::evaluate(const Vec3<T>& p) const {
  return SceneEvaluator<T>(nodes_, leaves_, defaults_, mode_).node(root_, p);
}

template <typename T>
T CompiledScene::evaluate(const Vec3<T>& p, const UniformValues& values) const {
  if (values.size() != uniforms_.size()) {
    throw std::invalid_argument("evaluate: " + std::to_string(values.size()) + " uniform values for " +
                                std::to_string(uniforms_.size()) + " uniforms");
  }
  return SceneEvaluator<T>(nodes_, leaves_, values, mode_).node(root_, p);
}

template float CompiledScene::evaluate(const Vec3<float>&) const;
template double CompiledScene::evaluate(const Vec3<double>&) const;
template float CompiledScene::evaluate(const Vec3<float>&, const UniformValues&) const;
template double CompiledScene::evaluate(const Vec3<double>&, const UniformValues&) const;

UniformValues CompiledScene::default_uniform_values() const { return defaults_; }

std::optional<std::size_t> CompiledScene::find_uniform(const std::string& name) const {
  for (std::size_t i = 0; i < uniforms_.size(); ++i) {
    if (uniforms_[i].name == name) return i;
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------------
// The GLSL.

std::string SceneGlslWriter::node(std::uint32_t index, const std::string& p) {
  const Node& n = scene_.nodes_[index];
  return n.operations->emit(*this, n, p);
}

void SceneGlslWriter::require_helper(const std::string& id, const std::string& text,
                                     const std::vector<std::string>& suffixes) {
  if (helper_ids_.insert(id).second) {
    helpers_ += text;
    globals_.insert(prefix_ + "_" + id);
    for (const std::string& suffix : suffixes) globals_.insert(prefix_ + "_" + id + suffix);
  }
}

std::string SceneGlslWriter::point(const std::string& expression, const std::string& comment) {
  const std::string name = "p" + std::to_string(++variables_);
  body_ += "  vec3 " + name + " = " + expression + ";  // " + comment + "\n";
  return name;
}

std::string SceneGlslWriter::value(const std::string& expression, const std::string& comment) {
  const std::string name = "d" + std::to_string(++variables_);
  body_ += "  float " + name + " = " + expression + ";  // " + comment + "\n";
  return name;
}

std::string SceneGlslWriter::scalar(const Node& n, std::size_t i) const {
  const Slot& s = n.slots[i];
  if (s.uniform >= 0) return scene_.uniforms_[static_cast<std::size_t>(s.uniform)].name;
  return format_glsl_float(s.value_float.x);
}

std::string SceneGlslWriter::vector(const Node& n, std::size_t i) const {
  const Slot& s = n.slots[i];
  if (s.uniform >= 0) return scene_.uniforms_[static_cast<std::size_t>(s.uniform)].name;
  return glsl_vec3(s.value_float);
}

std::string glsl_vec3(const Vec3<float>& v) {
  return "vec3(" + format_glsl_float(v.x) + ", " + format_glsl_float(v.y) + ", " + format_glsl_float(v.z) + ")";
}

std::string SceneGlslWriter::write(std::set<std::string>& globals) {
  const std::string result = node(scene_.root_, "p");
  const std::string function = scene_.function_name();
  globals_.insert(function);
  std::string out;
  out += "// " + function + ": a scene of " + std::to_string(scene_.nodes_.size()) + " nodes, mode " +
         (scene_.mode_ == SdfMode::safe ? "safe (a lower bound of the distance)" : "fast (a distance estimate)") +
         ", negative inside.\n// Generated by implicitizer; see docs/sdf.md, \"Scenes\".\n";
  for (const SceneUniform& u : scene_.uniforms_) {
    out += std::string("uniform ") + (u.type == ParameterType::vec3 ? "vec3 " : "float ") + u.name + ";\n";
  }
  out += helpers_;
  if (scene_.dimension_ == 2) {
    // A plane curve: the slice z = 0 of the scene in space.
    const std::string space = scene_.name_ + "_space";
    globals_.insert(space);
    out += "float " + space + "(vec3 p) {\n" + body_ + "  return " + result + ";\n}\n";
    out += "float " + function + "(vec2 p) {\n  return " + space + "(vec3(p, 0.0));\n}\n";
  } else {
    out += "float " + function + "(vec3 p) {\n" + body_ + "  return " + result + ";\n}\n";
  }
  globals = globals_;
  return out;
}

CompiledScene SceneCompiler::run(const SceneNode& root) {
  try {
    check_glsl_name(options_.name);
  } catch (const InputError& e) {
    throw e.in_field("name");
  }
  if (options_.dimension != 2 && options_.dimension != 3) {
    throw InputError("invalid_value", "dimension is 2 (a plane curve) or 3 (space)").in_field("dimension");
  }
  scene_.root_ = compile(root, options_.root_field, 1);
  std::set<std::string> globals;
  scene_.glsl_ = SceneGlslWriter(scene_).write(globals);
  // A uniform named like a helper or NAME_sdf would redefine it: refuse.
  for (const SceneUniform& u : scene_.uniforms_) {
    if (globals.count(u.name) != 0) {
      throw InputError("name_collision", "uniform '" + u.name + "' has the name of a function of the scene's GLSL")
          .in_field(u.field);
    }
  }
  return std::move(scene_);
}

}  // namespace implicitizer
