#pragma once
/// \file
/// A scene as the user describes it: a tree of nodes whose leaves are primitives
/// (sphere, box, …), implicit equations or parametric surfaces, and whose inner
/// nodes are operators (union, smooth union, translate, …). A SceneNode is a plain
/// value (what the JSON decoder produces, what tests build by hand); compile_scene()
/// (compiled_scene.hpp) validates it and turns it into a CompiledScene that
/// evaluates in C++ (float, double) and prints GLSL with one semantics.
///
/// Every node kind is described by one row of a table (node_kind_info()): its JSON
/// type name, how many children it takes, and its numeric parameters (name, scalar
/// or vec3 or count, allowed range, whether it may be a uniform, default). The JSON
/// decoder and the validation of compile_scene() read that table, so a kind's
/// parameters are declared once.
///
/// How to add a node kind (e.g. `twist`), all local changes:
///  1. here: one enumerator in NodeKind (in the group of its arity);
///  2. lib/src/scene/scene_node.cpp: one row of kKinds (type name, arity,
///     parameters with their range, uniformability and default, and the kind's
///     NodeOperations). The JSON decoder (server/codec/src/scene_json.cpp) needs
///     nothing more for numeric parameters;
///  3. your concept's header and source (e.g. scene/domain_operators.hpp/.cpp): the C++
///     twin as a template over T = float/double on Vec3<T> (vec3.hpp), and next to
///     it the GLSL text of the same operations in the same order, as a function
///     `std::string xxx_glsl(const std::string& prefix)` that defines
///     `PREFIX_xxx(...)` (helpers are prefixed with the scene's NAME so two scenes can
///     share a shader; use no local variable containing `_` so no uniform can be
///     shadowed);
///  4. the same source: the kind's NodeOperations (lib/src/scene/node_operations.hpp),
///     four functions that wire its parameters and children to the twin and the text:
///       - classify: what the node guarantees in safe mode (NodeClass: 1-Lipschitz,
///         distance bound, or refuse with InputError `unsafe_operator`), from its
///         children's classes; plus any validation the table's ranges cannot say;
///       - bound: a box containing the node's solid {v ≤ 0} and whether v ≥ the
///         distance to that box outside it (what safe repetition needs of its child;
///         "unknown", NodeBox{}, is always a correct answer);
///       - evaluate<T>: map the point, evaluate the child(ren), map the value,
///         calling the twin;
///       - emit: the same in GLSL, calling writer.require_helper(id, text) once per
///         helper and writer.point()/writer.value() for each statement.
///     Parameters are read with the slot accessors (SlotReader's scalar/vector for
///     C++, the writer's scalar/vector for GLSL): they hide whether a parameter is
///     baked or a uniform. lib/src/scene/compiled_scene.cpp needs no change;
///  5. tests in tests/scene/ (closed-form values, GLSL compiles, runs on llvmpipe
///     and agrees with evaluate<float>) and the node's section in docs/sdf.md.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "implicitizer/core/rational.hpp"
#include "implicitizer/scene/vec3.hpp"
#include "implicitizer/sdf/scene_frame.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer {

/// What a node computes. The enumerators are grouped by arity.
enum class NodeKind : std::uint8_t {
  // Leaves: exact (or bounded) distances to primitives, and polynomial surfaces.
  sphere,
  box,
  round_box,
  torus,
  plane,
  capsule,
  cone,
  ellipsoid,
  cylinder,
  implicit,
  parametric,
  // Two or more children.
  csg_union,
  csg_intersection,
  csg_difference,
  smooth_union,
  smooth_intersection,
  smooth_difference,
  // One child.
  translate,
  rotate,
  scale,
  shell,
  // Domain operators (domain_operators.hpp), one child.
  twist,
  bend,
  round,
  elongate,
  symmetry,
  repeat,
  repeat_finite,
  displace,
};

/// How many children a kind takes.
enum class NodeArity : std::uint8_t {
  leaf,   ///< none
  unary,  ///< exactly one ("child" in JSON)
  nary,   ///< two or more ("children" in JSON), combined left to right
};

/// The type of a numeric parameter.
enum class ParameterType : std::uint8_t {
  scalar,  ///< a float (GLSL float)
  vec3,    ///< three floats (GLSL vec3)
  count,   ///< an integer in [1, kMaxCount], structural (it shapes the code): never a uniform
};

/// The values a parameter may take; compile_scene() checks baked values and uniform
/// defaults (values set later through a uniform are the caller's responsibility).
enum class ParameterRange : std::uint8_t {
  any,                  ///< any finite value(s)
  positive,             ///< > 0
  non_negative,         ///< >= 0
  nonzero_vector,       ///< a vec3 that is not (0, 0, 0)
  positive_components,  ///< a vec3 with every component > 0
  acute_angle,          ///< an angle in (0, π/2) radians (the cone's half-angle)
};

/// One parameter of a kind.
struct ParameterSpec {
  std::string_view name;  ///< the JSON key and the uniform suffix
  ParameterType type;
  ParameterRange range;
  bool uniformable;                     ///< may be listed in "uniforms"
  std::optional<double> default_value;  ///< when absent the parameter is required
};

/// What a kind does when a scene is compiled, evaluated and printed (private to
/// lib/src/scene: node_operations.hpp).
struct NodeOperations;

/// The table row of a kind.
struct NodeKindInfo {
  NodeKind kind;
  std::string_view type_name;  ///< the JSON "type"
  NodeArity arity;
  std::vector<ParameterSpec> parameters;  ///< in slot order
  const NodeOperations* operations;       ///< classify, bound, evaluate, emit
};

/// The row of `kind`.
const NodeKindInfo& node_kind_info(NodeKind kind);
/// The row whose type_name is `type_name`, or nullptr.
const NodeKindInfo* find_node_kind(std::string_view type_name);
/// Every row, in NodeKind order (for docs and the decoder's error messages).
const std::vector<NodeKindInfo>& node_kinds();

/// A numeric parameter value as given: a scalar (in x, with is_vector false) or a vec3.
struct ParameterValue {
  Vec3<double> value;
  bool is_vector = false;

  ParameterValue() = default;
  /// A scalar (also used for counts).
  ParameterValue(double scalar) : value{scalar, 0, 0} {}  // NOLINT(google-explicit-constructor)
  /// A vec3.
  ParameterValue(Vec3<double> vector) : value(vector), is_vector(true) {}  // NOLINT(google-explicit-constructor)
};

/// The sources of a polynomial leaf (kinds implicit and parametric).
struct PolynomialLeafSource {
  std::string equation;  ///< implicit: F(x, y, z) in the contract's syntax; the surface is F = 0
  /// parametric: x, y, z in the parameters (z empty for a plane curve, SceneParams::dimension 2)
  std::array<std::string, 3> coordinates;
  std::optional<std::vector<std::string>> parameter_names;  ///< parametric: their order (default: as they appear)
  /// parametric: one closed interval per parameter, in parameter order; empty: the
  /// default domain (docs/sdf.md, "Patches"). The leaf is the patch X(domain).
  std::vector<std::pair<Rational, Rational>> domain;
  std::optional<SceneBox> box;  ///< the frame box (default: fitted to the patch, else SceneParams::box)
  /// What the leaf's value describes (sdf_shape.hpp); automatic decides at compile
  /// time and PolynomialLeaf::shape() says what it picked.
  SdfShape shape = SdfShape::automatic;
  /// parametric over a bounded domain: approximate the patch within this fraction of
  /// its box's diagonal, both ways (polynomial_leaf.hpp, "Approximated patches");
  /// none: the exact equation. 0 < tolerance <= 0.5 (else `invalid_tolerance`).
  std::optional<double> tolerance;
};

/// One node of a scene tree.
struct SceneNode {
  NodeKind kind = NodeKind::sphere;
  std::string name;  ///< optional ("" = none); a GLSL identifier, unique in the scene
  /// The numeric parameters by name; compile_scene() matches them against the kind's
  /// table row (unknown names and missing required ones are errors).
  std::vector<std::pair<std::string, ParameterValue>> parameters;
  std::vector<std::string> uniforms;  ///< parameters exposed as `uniform NAME_PARAM` (needs a name)
  std::vector<SceneNode> children;
  PolynomialLeafSource leaf;  ///< only for implicit and parametric

  /// Adds (or replaces) parameter `key`; returns *this for chaining.
  SceneNode& set(const std::string& key, ParameterValue value);
};

/// A leaf or operator node of `kind` with `parameters` and `children` (a shorthand for tests
/// and builders: make_node(NodeKind::sphere, {{"radius", 1.0}})).
SceneNode make_node(NodeKind kind, std::vector<std::pair<std::string, ParameterValue>> parameters = {},
                    std::vector<SceneNode> children = {});

/// The largest scene compile_scene() and the decoder accept: scene_nodes nodes,
/// depth scene_depth (root = 1). Why: the GLSL is straight-line code, one function
/// call per node, so its size and the GPU compiler's time grow with the node count
/// (256 primitives are far beyond a hand-written scene and compile in well under a
/// second); the decoder, the compiler and the C++ evaluator recurse once per level,
/// so the depth bounds their stack use whatever a request sends.
inline constexpr std::size_t kMaxSceneNodes = 256;
/// See kMaxSceneNodes.
inline constexpr std::size_t kMaxSceneDepth = 64;
/// The largest count parameter (the smooth operators' n): the GLSL spells h^n as n
/// factors, and n = 16 already makes the blend indistinguishable from a corner.
inline constexpr std::int32_t kMaxCount = 16;
/// The largest magnitude of a numeric parameter: beyond it a float product of two
/// parameters (k·h, |p|·scale) can overflow fp32 (3.4e38).
inline constexpr double kMaxParameterMagnitude = 1e18;

}  // namespace implicitizer
