#pragma once
// Private to lib/src/scene: what one node kind does at each stage of a scene. Each
// kind's concept file (primitives.cpp, boolean_operators.cpp, affine_transforms.cpp,
// domain_operators.cpp, polynomial_leaf.cpp) defines its NodeOperations beside the C++
// twin and the GLSL text they call, the kinds table of scene_node.cpp points the kind's
// row at them, and compiled_scene.cpp compiles, evaluates and prints a scene by calling
// them node by node. A kind's evaluate and emit run the same steps in the same order
// (compiled_scene.hpp: evaluate<float>() predicts the GPU).
//
// The evaluator dispatches through the operations pointer each compiled node carries:
// one indirect call per node where the switch it replaced made one indirect jump, and
// measured no slower (docs/benchmarks.md, "Issue 17: compiled scenes with per-kind
// operations"), so no switch over kinds remains in the per-point loop.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "implicitizer/scene/compiled_scene.hpp"
#include "implicitizer/scene/polynomial_leaf.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/scene/vec3.hpp"

namespace implicitizer {

using CompiledNode = CompiledScene::Node;

/// A baked (non-uniform) slot holding `v`, and its float rounding.
inline CompiledScene::Slot baked_slot(const Vec3<double>& v) {
  return CompiledScene::Slot{-1, v,
                             Vec3<float>{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)}};
}
/// A baked scalar slot.
inline CompiledScene::Slot baked_slot(double x) { return baked_slot(Vec3<double>{x, 0, 0}); }

/// The JSON path of child i of the node at `path`.
inline std::string child_field(const std::string& path, NodeArity arity, std::size_t i) {
  return arity == NodeArity::unary ? path + ".child" : path + ".children[" + std::to_string(i) + "]";
}

/// The compiler's view of the node being compiled: its slots read, its children
/// compiled (their classes and boxes known), the node itself not yet stored.
struct NodeCompilation {
  CompiledNode& out;
  const std::string& path;  ///< the node's JSON path, for error fields
  SdfMode mode;
  const std::vector<CompiledNode>& nodes;  ///< every node compiled so far, children included
  const std::vector<PolynomialLeaf>& leaves;

  bool safe() const { return mode == SdfMode::safe; }
  const CompiledNode& child(std::size_t i) const { return nodes[out.children[i]]; }
  /// The weakest class of the children (the enum's order): min, max and negation keep
  /// 1-Lipschitz functions 1-Lipschitz and bounds bounds, min and max keep outer
  /// bounds outer bounds (docs/sdf.md, "Scenes", safe mode).
  NodeClass children_class() const {
    NodeClass weakest = NodeClass::lipschitz;
    for (std::uint32_t c : out.children) weakest = std::max(weakest, nodes[c].node_class);
    return weakest;
  }
  /// Whether any of `slots` (that exist) is a uniform: a box that depends on it is unknown.
  bool uniform(std::initializer_list<std::size_t> slots) const {
    for (std::size_t i : slots) {
      if (i < out.slots.size() && out.slots[i].uniform >= 0) return true;
    }
    return false;
  }
  /// Slot i's baked value (a uniform's default).
  const Vec3<double>& value(std::size_t i) const { return out.slots[i].value; }
};

/// A box containing a node's solid {v ≤ 0}, and whether v ≥ the distance to the box
/// outside it ("grows"). The default, unknown (all ±inf, not growing), is always correct.
struct NodeBox {
  Vec3<double> lo{-CompiledScene::kUnbounded, -CompiledScene::kUnbounded, -CompiledScene::kUnbounded};
  Vec3<double> hi{CompiledScene::kUnbounded, CompiledScene::kUnbounded, CompiledScene::kUnbounded};
  bool grows = false;
};

/// The componentwise minimum of two corners.
inline Vec3<double> lower_corner(const Vec3<double>& a, const Vec3<double>& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
/// The componentwise maximum of two corners.
inline Vec3<double> upper_corner(const Vec3<double>& a, const Vec3<double>& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
/// (r, r, r).
inline Vec3<double> cube_corner(double r) { return {r, r, r}; }
/// The box [lo, hi] that grows where child 0 grows (what 1-Lipschitz warps and offsets keep).
inline NodeBox child_grows_box(const NodeCompilation& c, const Vec3<double>& lo, const Vec3<double>& hi) {
  return {lo, hi, c.child(0).box_grows};
}

/// The child's box grown by the baked scalar r of slot 0, growing, where the child
/// grows: an offset f − r (round, shell's |f| − r) is ≤ 0 only where f ≤ r, within r of
/// the box, and f − r ≥ dist(p, box) − r ≥ dist(p, box ± r). Unknown otherwise, or when
/// r is a uniform.
inline NodeBox offset_child_box(const NodeCompilation& c) {
  if (!c.child(0).box_grows || c.uniform({0})) return {};
  const double r = c.value(0).x;
  return {c.child(0).box_lo - cube_corner(r), c.child(0).box_hi + cube_corner(r), true};
}

/// Reads a node's slots as T: a uniform's current value, or the baked constant
/// (float runs: the float the GLSL states).
template <typename T>
struct SlotReader {
  const CompiledNode& node;
  const UniformValues& values;

  Vec3<T> vector(std::size_t i) const {
    const CompiledScene::Slot& s = node.slots[i];
    if (s.uniform >= 0) {
      const Vec3<double>& v = values[static_cast<std::size_t>(s.uniform)];
      return {static_cast<T>(v.x), static_cast<T>(v.y), static_cast<T>(v.z)};
    }
    if constexpr (sizeof(T) == sizeof(float)) {
      return s.value_float;
    } else {
      return {static_cast<T>(s.value.x), static_cast<T>(s.value.y), static_cast<T>(s.value.z)};
    }
  }
  T scalar(std::size_t i) const { return vector(i).x; }
  bool is_uniform(std::size_t i) const { return node.slots[i].uniform >= 0; }
};

template <typename T>
class SceneEvaluator;
class SceneGlslWriter;

/// A kind's value at p, in T = float or double.
template <typename T>
using EvaluateNode = T (*)(const SceneEvaluator<T>&, const CompiledNode&, const Vec3<T>&);

/// What one node kind does (see the file comment).
struct NodeOperations {
  /// Sets out.node_class (what the value guarantees in safe mode, from the children's
  /// classes), appends the constants the kind derives at compile time to out.slots, and
  /// checks what the table's ranges cannot say (InputError, e.g. `unsafe_operator`).
  void (*classify)(NodeCompilation&);
  /// The node's box (NodeBox), after classify.
  NodeBox (*bound)(const NodeCompilation&);
  EvaluateNode<float> evaluate_float;
  EvaluateNode<double> evaluate_double;
  /// The GLSL of the node at point expression p; returns the expression of its value.
  std::string (*emit)(SceneGlslWriter&, const CompiledNode&, const std::string& p);
};

/// Evaluates nodes of one scene at one set of uniform values.
template <typename T>
class SceneEvaluator {
 public:
  SceneEvaluator(const std::vector<CompiledNode>& nodes, const std::vector<PolynomialLeaf>& leaves,
                 const UniformValues& values, SdfMode mode)
      : nodes_(nodes), leaves_(leaves), values_(values), mode_(mode) {}

  /// The value of node `index` at p.
  T node(std::uint32_t index, const Vec3<T>& p) const {
    const CompiledNode& n = nodes_[index];
    if constexpr (std::is_same_v<T, float>) {
      return n.operations->evaluate_float(*this, n, p);
    } else {
      return n.operations->evaluate_double(*this, n, p);
    }
  }
  /// The value of n's child i at q.
  T child(const CompiledNode& n, std::size_t i, const Vec3<T>& q) const { return node(n.children[i], q); }
  SlotReader<T> slots(const CompiledNode& n) const { return {n, values_}; }
  const CompiledNode& child_node(const CompiledNode& n, std::size_t i) const { return nodes_[n.children[i]]; }
  const PolynomialLeaf& leaf(const CompiledNode& n) const { return leaves_[static_cast<std::size_t>(n.leaf)]; }
  bool safe() const { return mode_ == SdfMode::safe; }

 private:
  const std::vector<CompiledNode>& nodes_;
  const std::vector<PolynomialLeaf>& leaves_;
  const UniformValues& values_;
  SdfMode mode_;
};

/// Prints a scene's GLSL: helpers once each in order of first use, then NAME_sdf as
/// straight-line statements, one or two per node.
class SceneGlslWriter {
 public:
  explicit SceneGlslWriter(const CompiledScene& scene) : scene_(scene), prefix_(scene.name_) {}

  /// The whole text; `globals` receives every global identifier it defines.
  std::string write(std::set<std::string>& globals);

  /// Emits node `index` at point expression p; returns the expression of its value.
  std::string node(std::uint32_t index, const std::string& p);
  /// Emits n's child i at point expression p.
  std::string child(const CompiledNode& n, std::size_t i, const std::string& p) { return node(n.children[i], p); }
  /// Adds helper `id` (its text defines PREFIX_id, and PREFIX_id + each of
  /// `suffixes`) once, in order of first use.
  void require_helper(const std::string& id, const std::string& text, const std::vector<std::string>& suffixes = {});
  /// A new point variable `vec3 pK = expression;  // comment`; returns pK.
  std::string point(const std::string& expression, const std::string& comment);
  /// A new value variable `float dK = expression;  // comment`; returns dK.
  std::string value(const std::string& expression, const std::string& comment);
  /// A new loop counter name cK.
  std::string counter() { return "c" + std::to_string(++variables_); }
  /// Appends raw statements to NAME_sdf's body (a loop's braces).
  void statement(const std::string& text) { body_ += text; }
  /// Slot i of n as GLSL: the uniform's name or the float constant.
  std::string scalar(const CompiledNode& n, std::size_t i) const;
  /// See scalar(): a vec3.
  std::string vector(const CompiledNode& n, std::size_t i) const;
  /// PREFIX_id(arguments).
  std::string call(const std::string& id, const std::string& arguments) const {
    return prefix_ + "_" + id + "(" + arguments + ")";
  }
  /// require_helper(id, text), then a value variable holding PREFIX_id(p, arguments).
  std::string call_primitive(const CompiledNode& n, const std::string& p, const std::string& id,
                             const std::string& text, const std::string& arguments) {
    require_helper(id, text);
    return value(call(id, p + ", " + arguments), type(n));
  }
  /// The kind's JSON name, the comment of its statements.
  static std::string type(const CompiledNode& n) { return std::string(node_kind_info(n.kind).type_name); }
  const std::string& prefix() const { return prefix_; }
  bool safe() const { return scene_.mode_ == SdfMode::safe; }
  const CompiledNode& child_node(const CompiledNode& n, std::size_t i) const { return scene_.nodes_[n.children[i]]; }
  const PolynomialLeaf& leaf(const CompiledNode& n) const { return scene_.leaves_[static_cast<std::size_t>(n.leaf)]; }

 private:
  const CompiledScene& scene_;
  const std::string prefix_;
  std::set<std::string> helper_ids_;
  std::set<std::string> globals_;
  std::string helpers_, body_;
  std::size_t variables_ = 0;
};

/// vec3(x, y, z) of float constants.
std::string glsl_vec3(const Vec3<float>& v);

// The operations of every kind, defined in the kind's concept file.
extern const NodeOperations kSphereOperations, kBoxOperations, kRoundBoxOperations, kTorusOperations, kPlaneOperations,
    kCapsuleOperations, kConeOperations, kEllipsoidOperations, kCylinderOperations;  // primitives.cpp
extern const NodeOperations kPolynomialLeafOperations;  // polynomial_leaf.cpp: implicit and parametric
extern const NodeOperations kUnionOperations, kIntersectionOperations, kDifferenceOperations, kSmoothUnionOperations,
    kSmoothIntersectionOperations, kSmoothDifferenceOperations;                         // boolean_operators.cpp
extern const NodeOperations kTranslateOperations, kRotateOperations, kScaleOperations;  // affine_transforms.cpp
extern const NodeOperations kShellOperations;                                           // shell.cpp
extern const NodeOperations kTwistOperations, kBendOperations, kRoundOperations, kElongateOperations,
    kSymmetryOperations, kRepeatOperations, kRepeatFiniteOperations, kDisplaceOperations;  // domain_operators.cpp

/// The classify of exact Euclidean distances (primitives.hpp): 1-Lipschitz.
inline void classify_lipschitz(NodeCompilation& c) { c.out.node_class = NodeClass::lipschitz; }
/// A node that keeps its children's class (isometries, uniform scaling, sharp booleans, 1-Lipschitz warps).
inline void classify_as_children(NodeCompilation& c) { c.out.node_class = c.children_class(); }
/// Safe mode: a bound, or weaker when a child is (an outer bound stays one: the warps'
/// and the repetitions' proofs use the child's claim on the side of the point only).
/// Fast mode: an estimate.
inline NodeClass bound_or_weaker(const NodeCompilation& c) {
  return c.safe() ? std::max(NodeClass::bound, c.children_class()) : NodeClass::estimate;
}

}  // namespace implicitizer
