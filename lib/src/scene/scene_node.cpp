#include "implicitizer/scene/scene_node.hpp"

#include <algorithm>
#include <stdexcept>

#include "node_operations.hpp"

namespace implicitizer {
namespace {

using enum ParameterType;
using enum ParameterRange;

// One row per NodeKind, in enum order (node_kind_info indexes it). Parameters are
// in slot order: the kind's operations read slot i as the i-th parameter here. Longer
// than a screen because it is the table itself, one row per kind.
const std::vector<NodeKindInfo>& kinds_table() {
  static const std::vector<NodeKindInfo> kinds = {
      {NodeKind::sphere,
       "sphere",
       NodeArity::leaf,
       {{"radius", scalar, positive, true, std::nullopt}},
       &kSphereOperations},
      {NodeKind::box,
       "box",
       NodeArity::leaf,
       {{"size", vec3, positive_components, true, std::nullopt}},
       &kBoxOperations},
      {NodeKind::round_box,
       "round_box",
       NodeArity::leaf,
       {{"size", vec3, positive_components, true, std::nullopt}, {"radius", scalar, non_negative, true, std::nullopt}},
       &kRoundBoxOperations},
      {NodeKind::torus,
       "torus",
       NodeArity::leaf,
       {{"major", scalar, positive, true, std::nullopt}, {"minor", scalar, positive, true, std::nullopt}},
       &kTorusOperations},
      {NodeKind::plane,
       "plane",
       NodeArity::leaf,
       {{"normal", vec3, nonzero_vector, false, std::nullopt}, {"offset", scalar, any, true, 0.0}},
       &kPlaneOperations},
      {NodeKind::capsule,
       "capsule",
       NodeArity::leaf,
       {{"a", vec3, any, true, std::nullopt},
        {"b", vec3, any, true, std::nullopt},
        {"radius", scalar, positive, true, std::nullopt}},
       &kCapsuleOperations},
      {NodeKind::cone,
       "cone",
       NodeArity::leaf,
       {{"angle", scalar, acute_angle, true, std::nullopt}, {"height", scalar, positive, true, std::nullopt}},
       &kConeOperations},
      {NodeKind::ellipsoid,
       "ellipsoid",
       NodeArity::leaf,
       {{"radii", vec3, positive_components, true, std::nullopt}},
       &kEllipsoidOperations},
      {NodeKind::cylinder,
       "cylinder",
       NodeArity::leaf,
       {{"radius", scalar, positive, true, std::nullopt}},
       &kCylinderOperations},
      {NodeKind::implicit, "implicit", NodeArity::leaf, {}, &kPolynomialLeafOperations},
      {NodeKind::parametric, "parametric", NodeArity::leaf, {}, &kPolynomialLeafOperations},
      {NodeKind::csg_union, "union", NodeArity::nary, {}, &kUnionOperations},
      {NodeKind::csg_intersection, "intersection", NodeArity::nary, {}, &kIntersectionOperations},
      {NodeKind::csg_difference, "difference", NodeArity::nary, {}, &kDifferenceOperations},
      {NodeKind::smooth_union,
       "smooth_union",
       NodeArity::nary,
       {{"k", scalar, positive, true, std::nullopt}, {"n", count, positive, false, 2.0}},
       &kSmoothUnionOperations},
      {NodeKind::smooth_intersection,
       "smooth_intersection",
       NodeArity::nary,
       {{"k", scalar, positive, true, std::nullopt}, {"n", count, positive, false, 2.0}},
       &kSmoothIntersectionOperations},
      {NodeKind::smooth_difference,
       "smooth_difference",
       NodeArity::nary,
       {{"k", scalar, positive, true, std::nullopt}, {"n", count, positive, false, 2.0}},
       &kSmoothDifferenceOperations},
      {NodeKind::translate,
       "translate",
       NodeArity::unary,
       {{"offset", vec3, any, true, std::nullopt}},
       &kTranslateOperations},
      {NodeKind::rotate,
       "rotate",
       NodeArity::unary,
       {{"axis", vec3, nonzero_vector, false, std::nullopt}, {"angle", scalar, any, true, std::nullopt}},
       &kRotateOperations},
      {NodeKind::scale,
       "scale",
       NodeArity::unary,
       {{"factor", scalar, positive, true, std::nullopt}},
       &kScaleOperations},
      // |d| − thickness (shell.hpp): a sheet as a thin solid.
      {NodeKind::shell,
       "shell",
       NodeArity::unary,
       {{"thickness", scalar, positive, true, std::nullopt}},
       &kShellOperations},
      // Domain operators (domain_operators.hpp). Components a range cannot say (size
      // >= 0, axes 0 or 1, period >= 0, integer limits) are checked by the kind's classify (domain_operators.cpp).
      {NodeKind::twist, "twist", NodeArity::unary, {{"k", scalar, any, true, std::nullopt}}, &kTwistOperations},
      {NodeKind::bend, "bend", NodeArity::unary, {{"k", scalar, any, true, std::nullopt}}, &kBendOperations},
      {NodeKind::round,
       "round",
       NodeArity::unary,
       {{"radius", scalar, non_negative, true, std::nullopt}},
       &kRoundOperations},
      {NodeKind::elongate,
       "elongate",
       NodeArity::unary,
       {{"size", vec3, any, true, std::nullopt}},
       &kElongateOperations},
      {NodeKind::symmetry,
       "symmetry",
       NodeArity::unary,
       {{"axes", vec3, nonzero_vector, false, std::nullopt}},
       &kSymmetryOperations},
      {NodeKind::repeat,
       "repeat",
       NodeArity::unary,
       {{"period", vec3, nonzero_vector, true, std::nullopt}},
       &kRepeatOperations},
      {NodeKind::repeat_finite,
       "repeat_finite",
       NodeArity::unary,
       {{"period", vec3, nonzero_vector, true, std::nullopt}, {"limit", vec3, any, false, std::nullopt}},
       &kRepeatFiniteOperations},
      {NodeKind::displace,
       "displace",
       NodeArity::unary,
       {{"amplitude", scalar, any, true, std::nullopt}, {"frequency", scalar, any, true, std::nullopt}},
       &kDisplaceOperations},
  };
  return kinds;
}

}  // namespace

const std::vector<NodeKindInfo>& node_kinds() { return kinds_table(); }

const NodeKindInfo& node_kind_info(NodeKind kind) {
  const auto& kinds = kinds_table();
  const auto index = static_cast<std::size_t>(kind);
  if (index >= kinds.size() || kinds[index].kind != kind) {
    // The table is out of step with the enum: a programming error, caught by the tests.
    throw std::logic_error("node kind table out of order at " + std::to_string(index));
  }
  return kinds[index];
}

const NodeKindInfo* find_node_kind(std::string_view type_name) {
  const auto& kinds = kinds_table();
  const auto it =
      std::find_if(kinds.begin(), kinds.end(), [&](const NodeKindInfo& k) { return k.type_name == type_name; });
  return it == kinds.end() ? nullptr : &*it;
}

SceneNode& SceneNode::set(const std::string& key, ParameterValue value) {
  for (auto& [parameter, v] : parameters) {
    if (parameter == key) {
      v = value;
      return *this;
    }
  }
  parameters.emplace_back(key, value);
  return *this;
}

SceneNode make_node(NodeKind kind, std::vector<std::pair<std::string, ParameterValue>> parameters,
                    std::vector<SceneNode> children) {
  SceneNode node;
  node.kind = kind;
  node.parameters = std::move(parameters);
  node.children = std::move(children);
  return node;
}

}  // namespace implicitizer
