#pragma once
/// \file
/// A validated scene (scene_node.hpp), ready to evaluate: one C++ evaluator in float
/// and double, and the GLSL of the same computation. Each node kind's C++ twin runs
/// the same operations in the same order as its GLSL text, with the same float
/// constants, so evaluate<float>() predicts what the GPU computes (up to the GPU's
/// own freedoms: fused multiply-adds, its sin/cos/tan for angles given as uniforms;
/// docs/sdf.md, "Scenes", lists the measured differences on llvmpipe).
///
/// The GLSL defines `float NAME_sdf(vec3 p)`, negative inside (a sheet leaf has no
/// inside: sdf_shape.hpp; `shell` gives it one); a plane curve's (SceneParams::
/// dimension 2) is `float NAME_sdf(vec2 p)`. Before it, the uniform declarations and
/// the helpers of the node kinds present in the scene, and only those, each prefixed
/// `NAME_` so that two scenes can be pasted into one shader.
///
/// Safe mode. Every node's value v then satisfies, at every point p,
///     v(p) > 0  ⇒  v(p) ≤ dist(p, {v ≤ 0})   and   v(p) < 0  ⇒  −v(p) ≤ dist(p, {v ≥ 0}),
/// i.e. |v| never exceeds the distance to the other side of the node's surface, so
/// sphere tracing with v never crosses it ("a bound"; proofs in docs/sdf.md and at
/// each kind's classify, beside its concept in lib/src/scene/). Smooth operators are only
/// bounds over 1-Lipschitz children, so compile_scene() tracks NodeClass and refuses
/// the others (InputError `unsafe_operator`). A shell over a mere bound keeps only the
/// first half (an outer bound: tracing from outside never enters it), so a difference
/// refuses one as its subtrahend. The claims are of exact arithmetic; fp32 rounding
/// adds a few ulps of the values involved.
///
/// Adding a node kind: see scene_node.hpp.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/scene/polynomial_leaf.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/scene/vec3.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/sdf/scene_frame.hpp"

namespace implicitizer {

/// Options of compile_scene().
struct SceneParams {
  SdfMode mode = SdfMode::fast;
  /// The frame box of implicit and parametric leaves that give none (a parametric
  /// leaf with a domain uses the box of its patch instead).
  SceneBox box = SceneBox::default_box();
  std::string name = "scene";  ///< the GLSL function is NAME_sdf; helpers are NAME_*
  /// The path of the root in error fields: errors name "scene.children[1].radius".
  std::string root_field = "scene";
  /// 3: a scene in space, `float NAME_sdf(vec3 p)`. 2: a plane curve (its leaves are
  /// polynomials in x and y, or parametrizations with x and y only), `float
  /// NAME_sdf(vec2 p)`, evaluated at z = 0 (docs/sdf.md, "Curves"): the scene is the
  /// slice z = 0 of the 3-D scene its nodes describe. Anything else is InputError
  /// `invalid_value` (field "dimension").
  int dimension = 3;
};

/// What a node's value guarantees (exact arithmetic), strongest first: a node is
/// at most as strong as its weakest child.
enum class NodeClass : std::uint8_t {
  lipschitz,    ///< 1-Lipschitz with the right sign: a bound, and smooth operators keep it
  bound,        ///< |v| ≤ distance to the other side (see the file comment), not 1-Lipschitz
  outer_bound,  ///< only v > 0 ⇒ v ≤ distance to the solid (a shell of a bound: shell.hpp)
  estimate,     ///< neither (fast mode: F/|∇F|, the ellipsoid's approximation, and what uses them)
};

/// A parameter exposed to the front-end as a GLSL uniform.
struct SceneUniform {
  std::string name;            ///< NODENAME_PARAMETER, a checked GLSL identifier
  ParameterType type;          ///< scalar (`uniform float`) or vec3 (`uniform vec3`)
  Vec3<double> default_value;  ///< the value given in the scene (scalar: in x)
  std::string field;           ///< the path of the node's parameter, e.g. "scene.child.radius"
};

/// Values of the uniforms, in uniforms() order (a scalar in x).
using UniformValues = std::vector<Vec3<double>>;

/// A compiled scene. Copyable; evaluation is const and thread-safe.
class CompiledScene {
 public:
  /// The signed value at p with the uniforms at their defaults: float runs use the
  /// float constants the GLSL states, double runs the double values.
  template <typename T>
  T evaluate(const Vec3<T>& p) const;
  /// The same with the uniforms set to `values` (size uniforms().size(); each value is
  /// rounded to T, as glUniform*f rounds to float). Throws std::invalid_argument on a
  /// size mismatch.
  template <typename T>
  T evaluate(const Vec3<T>& p, const UniformValues& values) const;

  /// The GLSL: uniform declarations, helpers of the kinds present, the polynomial
  /// leaves NAME_leaf<k>, then `float NAME_sdf(vec3 p)` (dimension 2: `float
  /// NAME_space(vec3 p)` and `float NAME_sdf(vec2 p)` calling it at vec3(p, 0.0)).
  /// Compiles as GLSL ES 3.00 (with `precision highp float`) and GLSL 330.
  std::string to_glsl() const { return glsl_; }

  /// The uniforms, in order of first appearance (depth first, children in order).
  const std::vector<SceneUniform>& uniforms() const { return uniforms_; }
  /// Every uniform at its default.
  UniformValues default_uniform_values() const;
  /// The index of uniform `name` in uniforms(), if any.
  std::optional<std::size_t> find_uniform(const std::string& name) const;

  /// NAME_sdf.
  std::string function_name() const { return name_ + "_sdf"; }
  /// 3 (NAME_sdf takes a vec3) or 2 (a plane curve: NAME_sdf takes a vec2 and calls
  /// the 3-D function NAME_space at z = 0; evaluate() then wants points with z = 0).
  int dimension() const { return dimension_; }
  /// The mode compiled for.
  SdfMode mode() const { return mode_; }
  /// What the root's value guarantees.
  NodeClass root_class() const { return nodes_.empty() ? NodeClass::estimate : nodes_[root_].node_class; }
  /// Number of nodes.
  std::size_t node_count() const { return nodes_.size(); }
  /// The polynomial leaves (implicit and parametric), in order of appearance: their
  /// equations (a parametric leaf's is the one the library implicitized) and boxes.
  const std::vector<PolynomialLeaf>& leaves() const { return leaves_; }

  /// One numeric parameter after compilation: a baked constant or a uniform.
  struct Slot {
    std::int32_t uniform = -1;  ///< index into uniforms(), or -1: baked
    Vec3<double> value;         ///< the baked value (double runs)
    Vec3<float> value_float;    ///< float(value): what the GLSL states (float runs)
  };
  /// An unbounded side of a node's box.
  static constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  /// One compiled node. `slots` holds the table's parameters in order, then any
  /// constants the kind derives at compile time (e.g. cos and sin of a baked angle).
  struct Node {
    NodeKind kind = NodeKind::sphere;
    const NodeOperations* operations = nullptr;  ///< the kind's (node_kind_info(kind).operations)
    std::vector<std::uint32_t> children;
    std::vector<Slot> slots;
    std::int32_t leaf = -1;  ///< index of the polynomial leaf (implicit, parametric)
    std::int32_t count = 0;  ///< the kind's count parameter, if it has one (smooth n)
    NodeClass node_class = NodeClass::estimate;
    /// A box containing the node's solid {v ≤ 0} (the kind's bound, node_operations.hpp): ±inf
    /// where unbounded or unknown (e.g. it depends on a uniform); the float copy is
    /// rounded outwards and is what the GLSL states.
    Vec3<double> box_lo{-kUnbounded, -kUnbounded, -kUnbounded}, box_hi{kUnbounded, kUnbounded, kUnbounded};
    Vec3<float> box_lo_float, box_hi_float;  ///< box_lo, box_hi rounded outwards (±inf → ±largest float)
    /// Whether v(p) ≥ dist(p, box) wherever p is outside the box (exact distances
    /// do): what lets round, smooth union and displace bound their own box.
    bool box_grows = false;
  };

 private:
  friend class SceneCompiler;
  friend class SceneGlslWriter;

  std::string name_;
  SdfMode mode_ = SdfMode::fast;
  int dimension_ = 3;
  std::vector<Node> nodes_;
  std::uint32_t root_ = 0;
  std::vector<PolynomialLeaf> leaves_;
  std::vector<SceneUniform> uniforms_;
  UniformValues defaults_;
  std::string glsl_;  // printed once by compile_scene, which checks its identifiers
};

/// Validates `root` and compiles it. Throws InputError with the field set to the node's
/// path ("scene", "scene.children[1]", "scene.child.radius"): `invalid_name`,
/// `name_collision` (two nodes with one name, or a uniform named like another GLSL
/// identifier of the scene), `invalid_scene` (wrong number of children, uniforms on a
/// node without a name, an unknown parameter), `missing_parameter`, `invalid_value`
/// (out of range, or a parameter that cannot be a uniform; `dimension` not 2 or 3; a
/// curve's parametric leaf with a z), `unsafe_operator` (safe mode: a smooth
/// operator, round or displace over a child that is not 1-Lipschitz, a shell over an
/// outer bound, a difference subtracting one), `scene_too_large`,
/// the errors of the leaves (parse errors, `unknown_variable` for a z in a curve's
/// equation, `constant_polynomial`, `invalid_box`,
/// `invalid_domain`, `unbounded_patch`, NoSingleEquation); LimitExceeded when
/// `budget` runs out.
CompiledScene compile_scene(const SceneNode& root, const SceneParams& options, const Budget& budget = Budget());

}  // namespace implicitizer
