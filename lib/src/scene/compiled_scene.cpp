#include "implicitizer/scene/compiled_scene.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/scene/affine_transforms.hpp"
#include "implicitizer/scene/boolean_operators.hpp"
#include "implicitizer/scene/domain_operators.hpp"
#include "implicitizer/scene/primitives.hpp"
#include "implicitizer/sdf/glsl_name.hpp"
#include "implicitizer/sdf/polynomial_program.hpp"

// Four switches over NodeKind live here, each case marked "NODE KIND": classify()
// (validation and the safe-mode class), bound() (a box containing the node's solid),
// evaluate_node() (the C++ evaluator) and emit_node() (the GLSL). A kind's C++ twin and GLSL text come from its
// concept's header (primitives, boolean_operators, affine_transforms, polynomial_leaf, …); these cases only wire
// parameters and children to them, in the same order on both sides. See scene_node.hpp, "How to add a node kind".

namespace implicitizer {

using Node = CompiledScene::Node;
using Slot = CompiledScene::Slot;

namespace {

// Reads a node's slots as T: a uniform's current value, or the baked constant (float
// runs: the float the GLSL states).
template <typename T>
struct SlotReader {
  const Node& node;
  const UniformValues& values;

  Vec3<T> vector(std::size_t i) const {
    const Slot& s = node.slots[i];
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

Slot baked(const Vec3<double>& v) {
  return Slot{-1, v, Vec3<float>{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)}};
}

Slot baked(double x) { return baked(Vec3<double>{x, 0, 0}); }

std::string child_field(const std::string& path, NodeArity arity, std::size_t i) {
  return arity == NodeArity::unary ? path + ".child" : path + ".children[" + std::to_string(i) + "]";
}

}  // namespace

// ---------------------------------------------------------------------------------
// Compilation: validation, slots, uniforms, leaves, classes.

class SceneCompiler {
 public:
  SceneCompiler(const SceneParams& options, const Budget& budget) : options_(options), budget_(budget) {
    scene_.name_ = options.name;
    scene_.mode_ = options.mode;
  }

  CompiledScene run(const SceneNode& root);

 private:
  std::uint32_t compile(const SceneNode& node, const std::string& path, std::size_t depth);
  void read_parameters(const SceneNode& node, const NodeKindInfo& info, const std::string& path, Node& out);
  void classify(const SceneNode& node, const std::string& path, Node& out);
  void bound(Node& out) const;

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

  for (std::size_t i = 0; i < info.parameters.size(); ++i) {
    const ParameterSpec& spec = info.parameters[i];
    const std::string field = path + "." + std::string(spec.name);
    const auto given = std::find_if(node.parameters.begin(), node.parameters.end(),
                                    [&](const auto& p) { return p.first == spec.name; });
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
    if (spec.type == ParameterType::count) {
      if (v.x != std::floor(v.x) || v.x < 1 || v.x > kMaxCount) {
        throw fail("an integer from 1 to " + std::to_string(kMaxCount));
      }
      out.count = static_cast<std::int32_t>(v.x);
    }
    Slot slot = baked(v);
    if (exposed[i]) {
      SceneUniform uniform;
      uniform.name = node.name + "_" + std::string(spec.name);
      const std::string uniform_field = path + ".uniforms";
      try {
        check_glsl_name(uniform.name);
      } catch (const InputError& e) {
        throw InputError(e.code(), "uniform '" + uniform.name + "': " + e.what()).in_field(uniform_field);
      }
      if (scene_.find_uniform(uniform.name)) {
        throw InputError("name_collision", "two uniforms are named '" + uniform.name + "'").in_field(uniform_field);
      }
      uniform.type = spec.type;
      uniform.default_value = v;
      uniform.field = field;
      slot.uniform = static_cast<std::int32_t>(scene_.uniforms_.size());
      scene_.uniforms_.push_back(uniform);
      scene_.defaults_.push_back(v);
    }
    out.slots.push_back(slot);
  }
}

// NODE KIND: the safe-mode class of each kind, from its children's classes, and the
// constants a kind derives at compile time (appended after the table's slots).
void SceneCompiler::classify(const SceneNode& node, const std::string& path, Node& out) {
  const bool safe = options_.mode == SdfMode::safe;
  const auto children_class = [&] {
    // min, max and negation keep 1-Lipschitz functions 1-Lipschitz, and keep bounds
    // bounds (docs/sdf.md, "Scenes", safe mode): the weakest child decides.
    NodeClass weakest = NodeClass::lipschitz;
    for (std::uint32_t c : out.children) {
      weakest = std::max(weakest, scene_.nodes_[c].node_class);
    }
    return weakest;
  };
  switch (node.kind) {
    case NodeKind::sphere:
    case NodeKind::box:
    case NodeKind::round_box:
    case NodeKind::torus:
    case NodeKind::capsule:
    case NodeKind::cylinder:
      // Exact Euclidean distances (primitives.hpp): 1-Lipschitz.
      out.node_class = NodeClass::lipschitz;
      break;
    case NodeKind::cone:
      out.node_class = NodeClass::lipschitz;
      if (out.slots[0].uniform < 0 && out.slots[1].uniform < 0) {
        // q = (h·tan θ, −h), in double then rounded once.
        const double height = out.slots[1].value.x;
        out.slots.push_back(baked(height * std::tan(out.slots[0].value.x)));
        out.slots.push_back(baked(-height));
      }
      break;
    case NodeKind::plane: {
      // n̂ = n/|n| in double, then rounded: |n̂_float| = 1 within 2^-24, so the value
      // is 1-Lipschitz up to that rounding.
      Vec3<double> n = out.slots[0].value;
      n = n / length(n);
      out.slots[0] = baked(n);
      out.node_class = NodeClass::lipschitz;
      break;
    }
    case NodeKind::ellipsoid:
      out.node_class = safe ? NodeClass::lipschitz : NodeClass::estimate;
      break;
    case NodeKind::implicit:
    case NodeKind::parametric:
      // Safe: SafeSdf bounds the distance but is not 1-Lipschitz (a polynomial's
      // gradient grows away from the surface); fast: F/|∇F| is an estimate.
      out.node_class = safe ? NodeClass::bound : NodeClass::estimate;
      break;
    case NodeKind::csg_union:
    case NodeKind::csg_intersection:
    case NodeKind::csg_difference:
      out.node_class = children_class();
      break;
    case NodeKind::smooth_union:
    case NodeKind::smooth_intersection:
    case NodeKind::smooth_difference:
      // The blend is 1-Lipschitz in (a, b) for the max-norm (boolean_operators.hpp),
      // so it keeps 1-Lipschitz children 1-Lipschitz; over mere bounds it can
      // overshoot the distance (two planes-like bounds scaled by 1/10 blend by k
      // regardless of the true distances), so safe mode refuses.
      out.node_class = children_class();
      if (safe && out.node_class != NodeClass::lipschitz) {
        for (std::size_t i = 0; i < out.children.size(); ++i) {
          if (scene_.nodes_[out.children[i]].node_class != NodeClass::lipschitz) {
            throw InputError("unsafe_operator",
                             "in mode safe a smooth operator needs 1-Lipschitz children (primitives, their "
                             "transforms and sharp combinations); " +
                                 child_field(path, NodeArity::nary, i) +
                                 " is only a distance bound (an implicit or parametric leaf, or uses one)")
                .in_field(path);
          }
        }
      }
      break;
    case NodeKind::translate:
    case NodeKind::scale:
      // Isometries and uniform scaling keep both classes (affine_transforms.hpp).
      out.node_class = children_class();
      break;
    case NodeKind::rotate: {
      Vec3<double> k = out.slots[0].value;
      k = k / length(k);
      out.slots[0] = baked(k);
      if (out.slots[1].uniform < 0) {
        const double angle = out.slots[1].value.x;
        out.slots.push_back(baked(std::cos(angle)));
        out.slots.push_back(baked(std::sin(angle)));
      }
      out.node_class = children_class();
      break;
    }
    // Domain operators: the proofs are in domain_operators.hpp.
    case NodeKind::twist:
    case NodeKind::bend:
      // Safe: the child's value over the local Lipschitz constant of the warp, a
      // bound (not 1-Lipschitz); fast: the child at the warped point, which can
      // overshoot by that constant.
      out.node_class = safe ? NodeClass::bound : NodeClass::estimate;
      break;
    case NodeKind::round:
    case NodeKind::displace:
      // f − r and (f + δ)/(1 + |aω|) are 1-Lipschitz over a 1-Lipschitz child; over
      // a mere bound they bound nothing (a bound's level sets are not offsets).
      out.node_class = children_class();
      if (out.node_class != NodeClass::lipschitz) {
        if (safe) {
          throw InputError("unsafe_operator",
                           std::string("in mode safe ") + (node.kind == NodeKind::round ? "round" : "displace") +
                               " needs a 1-Lipschitz child (primitives, their transforms and sharp or smooth "
                               "combinations); " +
                               path +
                               ".child is only a distance bound (it is or uses an "
                               "implicit or parametric leaf, a twist, a bend or a repetition)")
              .in_field(path + ".child");
        }
        out.node_class = NodeClass::estimate;
      } else if (!safe && node.kind == NodeKind::displace) {
        out.node_class = NodeClass::estimate;  // f + δ overshoots by up to 1 + |aω|
      }
      break;
    case NodeKind::elongate: {
      const Vec3<double>& h = out.slots[0].value;
      if (!(h.x >= 0 && h.y >= 0 && h.z >= 0)) {
        throw InputError("invalid_value", "size must be at least 0 on every axis (GLSL's clamp(p, -h, h) needs h >= 0)")
            .in_field(path + ".size");
      }
      out.node_class = children_class();  // a 1-Lipschitz warp keeps both classes
      break;
    }
    case NodeKind::symmetry: {
      const Vec3<double>& a = out.slots[0].value;
      for (double c : {a.x, a.y, a.z}) {
        if (c != 0 && c != 1) {
          throw InputError("invalid_value", "axes must be 0 or 1 on every axis (1: mirror that axis)")
              .in_field(path + ".axes");
        }
      }
      out.node_class = children_class();  // |x| is 1-Lipschitz: both classes kept
      break;
    }
    case NodeKind::repeat:
    case NodeKind::repeat_finite: {
      const Vec3<double>& period = out.slots[0].value;
      if (!(period.x >= 0 && period.y >= 0 && period.z >= 0)) {
        throw InputError("invalid_value", "period must be at least 0 on every axis (0: not repeated)")
            .in_field(path + ".period");
      }
      const AxisSet axes = axes_of(period);
      if (node.kind == NodeKind::repeat_finite) {
        const Vec3<double>& limit = out.slots[1].value;
        for (double c : {limit.x, limit.y, limit.z}) {
          if (!(c >= 0 && c <= kMaxRepeatLimit && c == std::floor(c))) {
            throw InputError("invalid_value", "limit must be an integer from 0 to " +
                                                  std::to_string(static_cast<int>(kMaxRepeatLimit)) +
                                                  " on every axis (copies -limit..limit)")
                .in_field(path + ".limit");
          }
        }
      }
      if (safe) {
        // The copies beyond the evaluated cells are kept apart by the child's box,
        // checked against the period's default (a uniform's later value is the
        // caller's business: where it breaks the condition the value reads 0).
        // The box the GLSL states (rounded outwards), with its unbounded sides kept
        // infinite so that they are reported as such.
        const Node& child = scene_.nodes_[out.children[0]];
        const auto stated = [](const Vec3<double>& exact, const Vec3<float>& rounded) {
          const auto pick = [](double e, float r) { return std::isinf(e) ? e : static_cast<double>(r); };
          return Vec3<double>{pick(exact.x, rounded.x), pick(exact.y, rounded.y), pick(exact.z, rounded.z)};
        };
        check_repetition_box(stated(child.box_lo, child.box_lo_float), stated(child.box_hi, child.box_hi_float), period,
                             axes, path + ".child");
      }
      out.node_class = safe ? NodeClass::bound : NodeClass::estimate;
      break;
    }
  }
}

// NODE KIND: a box containing each kind's solid {v ≤ 0}, and whether v ≥ the
// distance to the box outside it ("grows": true of exact distances). Unknown (all
// ±inf, not growing) is always correct, and is the answer wherever the box would
// depend on a uniform (its value may change after compilation). Safe repetition
// needs its child's box (domain_operators.hpp).
void SceneCompiler::bound(Node& out) const {
  using V = Vec3<double>;
  const double inf = CompiledScene::kUnbounded;
  const bool safe = options_.mode == SdfMode::safe;
  const auto uniform = [&](std::initializer_list<std::size_t> slots) {
    for (std::size_t i : slots) {
      if (i < out.slots.size() && out.slots[i].uniform >= 0) return true;
    }
    return false;
  };
  const auto child = [&](std::size_t i) -> const Node& { return scene_.nodes_[out.children[i]]; };
  const auto lo_of = [](const V& a, const V& b) {
    return V{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
  };
  const auto hi_of = [](const V& a, const V& b) {
    return V{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
  };
  const auto cube = [](double r) { return V{r, r, r}; };
  V lo{-inf, -inf, -inf}, hi{inf, inf, inf};
  bool grows = false;
  const auto set = [&](const V& l, const V& h, bool g) {
    lo = l;
    hi = h;
    grows = g;
  };
  const auto keep_child = [&](const V& l, const V& h) { set(l, h, child(0).box_grows); };
  const V s0 = out.slots.empty() ? V{} : out.slots[0].value;
  switch (out.kind) {
    case NodeKind::sphere:
      if (!uniform({0})) set(-cube(s0.x), cube(s0.x), true);
      break;
    case NodeKind::box:
    case NodeKind::round_box:  // the size includes the rounding
      if (!uniform({0})) set(-s0, s0, true);
      break;
    case NodeKind::torus:
      if (!uniform({0, 1})) {
        const double r = out.slots[1].value.x, outer = s0.x + r;
        set({-outer, -outer, -r}, {outer, outer, r}, true);
      }
      break;
    case NodeKind::plane:
      grows = true;  // a half-space: unbounded, and "outside the box" is empty
      break;
    case NodeKind::capsule:
      if (!uniform({0, 1, 2})) {
        const V a = s0, b = out.slots[1].value;
        const double r = out.slots[2].value.x;
        set(lo_of(a, b) - cube(r), hi_of(a, b) + cube(r), true);
      }
      break;
    case NodeKind::cone:
      if (!uniform({0, 1})) {
        const double h = out.slots[1].value.x, r = h * std::tan(s0.x);
        set({-r, -r, 0}, {r, r, h}, true);
      }
      break;
    case NodeKind::ellipsoid:
      // Both modes have the ellipsoid's sign; neither is at least the box distance.
      if (!uniform({0})) set(-s0, s0, false);
      break;
    case NodeKind::cylinder:
      if (!uniform({0})) set({-s0.x, -s0.x, -inf}, {s0.x, s0.x, inf}, true);
      break;
    case NodeKind::implicit:
    case NodeKind::parametric: {
      const PolynomialLeaf& leaf = scene_.leaves_[static_cast<std::size_t>(out.leaf)];
      if (leaf.trimmed()) {
        // t ≥ 0 everywhere: the solid {t ≤ 0} is the sheet, inside the trimming box.
        const Vec3<float>& l = leaf.trim_lo();
        const Vec3<float>& h = leaf.trim_hi();
        set({l.x, l.y, l.z}, {h.x, h.y, h.z}, false);
      } else {
        // Beyond kFarField (u = (p − c)·s, max norm) both modes return the positive
        // box distance: the solid lies in the cube c ± kFarField/s (widened by 1e-6
        // for fp32's rounding of u).
        const SceneFrame frame = make_scene_frame(leaf.frame_box());
        const double half = std::max(FastSdf::kFarField, SafeSdf::kFarField) / to_mpq(frame.scale).get_d() * (1 + 1e-6);
        const V c{to_mpq(frame.centre[0]).get_d(), to_mpq(frame.centre[1]).get_d(), to_mpq(frame.centre[2]).get_d()};
        set(c - cube(half), c + cube(half), false);
      }
      break;
    }
    case NodeKind::csg_union:
    case NodeKind::smooth_union: {
      // {min ≤ 0} is the union of the solids; smin ≥ min − k/(2n), so where every
      // child grows the blend stays within k/(2n) of the union's hull.
      V l = child(0).box_lo, h = child(0).box_hi;
      bool g = true;
      for (std::size_t i = 0; i < out.children.size(); ++i) {
        l = lo_of(l, child(i).box_lo);
        h = hi_of(h, child(i).box_hi);
        g = g && child(i).box_grows;
      }
      if (out.kind == NodeKind::csg_union) {
        set(l, h, g);
      } else if (g && !uniform({0})) {
        const double margin = s0.x / (2.0 * out.count);
        set(l - cube(margin), h + cube(margin), true);
      }
      break;
    }
    case NodeKind::csg_intersection:
    case NodeKind::smooth_intersection: {
      // smax ≥ max: the solid lies in every child's solid.
      V l = child(0).box_lo, h = child(0).box_hi;
      for (std::size_t i = 1; i < out.children.size(); ++i) {
        l = hi_of(l, child(i).box_lo);
        h = lo_of(h, child(i).box_hi);
      }
      set(l, h, false);
      break;
    }
    case NodeKind::csg_difference:
    case NodeKind::smooth_difference:
      // max(a, −b) and smax(a, −b) are ≥ a.
      keep_child(child(0).box_lo, child(0).box_hi);
      break;
    case NodeKind::translate:
      if (!uniform({0})) keep_child(child(0).box_lo + s0, child(0).box_hi + s0);
      break;
    case NodeKind::rotate: {
      // The child's box rotated by θ about the unit axis k (rotate_point(·, k, c, −s)
      // is the forward rotation), boxed again; for a uniform angle, the box of the
      // ball around the origin through the farthest corner (any angle).
      const V l = child(0).box_lo, h = child(0).box_hi;
      const bool finite = std::isfinite(l.x) && std::isfinite(l.y) && std::isfinite(l.z) && std::isfinite(h.x) &&
                          std::isfinite(h.y) && std::isfinite(h.z);
      if (!finite) break;
      V rl{inf, inf, inf}, rh{-inf, -inf, -inf};
      double reach = 0;
      for (int corner = 0; corner < 8; ++corner) {
        const V q{corner & 1 ? h.x : l.x, corner & 2 ? h.y : l.y, corner & 4 ? h.z : l.z};
        reach = std::max(reach, length(q));
        if (!uniform({1})) {
          const V r = rotate_point(q, s0, out.slots[2].value.x, -out.slots[3].value.x);
          rl = lo_of(rl, r);
          rh = hi_of(rh, r);
        }
      }
      if (uniform({1})) {
        keep_child(-cube(reach), cube(reach));
      } else {
        // cos and sin were rounded to double: widen by a relative 1e-12 of the reach.
        keep_child(rl - cube(reach * 1e-12), rh + cube(reach * 1e-12));
      }
      break;
    }
    case NodeKind::scale:
      if (!uniform({0})) keep_child(child(0).box_lo * s0.x, child(0).box_hi * s0.x);
      break;
    case NodeKind::twist:
    case NodeKind::bend: {
      // The warp keeps the coordinate along its axis (y, z) and the distance ρ to
      // that axis: the solid lies within the largest ρ of the child's box, for any k.
      // The value is the child's at the warped point (fast: at least the distance to
      // the rotation-invariant box; safe: divided by L ≥ 1, so not).
      const V l = child(0).box_lo, h = child(0).box_hi;
      const double a = std::max(l.x * l.x, h.x * h.x);
      const bool twist = out.kind == NodeKind::twist;
      const double b = twist ? std::max(l.z * l.z, h.z * h.z) : std::max(l.y * l.y, h.y * h.y);
      const double rho = std::sqrt(a + b);
      const bool g = !safe && child(0).box_grows;
      if (twist) {
        set({-rho, l.y, -rho}, {rho, h.y, rho}, g);
      } else {
        set({-rho, -rho, l.z}, {rho, rho, h.z}, g);
      }
      break;
    }
    case NodeKind::round:
      // f ≤ r only within r of the child's box when f grows; f − r then grows too.
      if (child(0).box_grows && !uniform({0})) {
        set(child(0).box_lo - cube(s0.x), child(0).box_hi + cube(s0.x), true);
      }
      break;
    case NodeKind::elongate:
      // p = e(p) + clamp(p, −h, h): the child's box plus [−h, h]; and
      // dist(p, box ⊕ [−h, h]) ≤ dist(e(p), box).
      if (!uniform({0})) keep_child(child(0).box_lo - s0, child(0).box_hi + s0);
      break;
    case NodeKind::symmetry: {
      // |p_i| in the child's range: within the larger of |lo_i|, |hi_i|.
      const V l = child(0).box_lo, h = child(0).box_hi;
      const double m[3] = {std::max(-l.x, h.x), std::max(-l.y, h.y), std::max(-l.z, h.z)};
      const V mirrored_lo{s0.x != 0 ? -m[0] : l.x, s0.y != 0 ? -m[1] : l.y, s0.z != 0 ? -m[2] : l.z};
      const V mirrored_hi{s0.x != 0 ? m[0] : h.x, s0.y != 0 ? m[1] : h.y, s0.z != 0 ? m[2] : h.z};
      keep_child(mirrored_lo, mirrored_hi);
      break;
    }
    case NodeKind::repeat:
    case NodeKind::repeat_finite: {
      // Unbounded along the repeated axes (finite: the child's box swept over the
      // copies −l..l); every term of both modes is at least the distance to it.
      const V l = child(0).box_lo, h = child(0).box_hi;
      if (out.kind == NodeKind::repeat) {
        keep_child({s0.x != 0 ? -inf : l.x, s0.y != 0 ? -inf : l.y, s0.z != 0 ? -inf : l.z},
                   {s0.x != 0 ? inf : h.x, s0.y != 0 ? inf : h.y, s0.z != 0 ? inf : h.z});
      } else if (!uniform({0})) {
        const V reach = s0 * out.slots[1].value;
        keep_child(l - reach, h + reach);
      }
      break;
    }
    case NodeKind::displace:
      // f + δ ≤ 0 only where f ≤ |a|; fast f + δ ≥ dist − |a| grows, safe divides.
      if (child(0).box_grows && !uniform({0})) {
        const double a = std::abs(s0.x);
        set(child(0).box_lo - cube(a), child(0).box_hi + cube(a), !safe);
      }
      break;
  }
  out.box_lo = lo;
  out.box_hi = hi;
  out.box_grows = grows;
  // Outwards to float; ±inf (and beyond the float range) to ∓/± the largest float,
  // which GLSL can state and which stays outside every scene.
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
  read_parameters(node, info, path, out);
  for (std::size_t i = 0; i < n; ++i) {
    out.children.push_back(compile(node.children[i], child_field(path, info.arity, i), depth + 1));
  }
  if (node.kind == NodeKind::implicit || node.kind == NodeKind::parametric) {
    out.leaf = static_cast<std::int32_t>(scene_.leaves_.size());
    scene_.leaves_.push_back(PolynomialLeaf::build(node.kind, node.leaf, options_.box, options_.mode, budget_, path));
  }
  classify(node, path, out);
  bound(out);
  scene_.nodes_.push_back(std::move(out));
  return static_cast<std::uint32_t>(scene_.nodes_.size() - 1);
}

// ---------------------------------------------------------------------------------
// The C++ evaluator.

template <typename T>
T CompiledScene::evaluate(const Vec3<T>& p) const {
  return evaluate_node(root_, p, defaults_);
}

template <typename T>
T CompiledScene::evaluate(const Vec3<T>& p, const UniformValues& values) const {
  if (values.size() != uniforms_.size()) {
    throw std::invalid_argument("evaluate: " + std::to_string(values.size()) + " uniform values for " +
                                std::to_string(uniforms_.size()) + " uniforms");
  }
  return evaluate_node(root_, p, values);
}

// NODE KIND: one case per kind, the same steps as emit_node() below.
template <typename T>
T CompiledScene::evaluate_node(std::uint32_t index, const Vec3<T>& p, const UniformValues& values) const {
  const Node& n = nodes_[index];
  const SlotReader<T> s{n, values};
  const auto child = [&](std::size_t i, const Vec3<T>& q) { return evaluate_node(n.children[i], q, values); };
  switch (n.kind) {
    case NodeKind::sphere:
      return sdf_sphere(p, s.scalar(0));
    case NodeKind::box:
      return sdf_box(p, s.vector(0));
    case NodeKind::round_box:
      return sdf_round_box(p, s.vector(0), s.scalar(1));
    case NodeKind::torus:
      return sdf_torus(p, s.scalar(0), s.scalar(1));
    case NodeKind::plane:
      return sdf_plane(p, s.vector(0), s.scalar(1));
    case NodeKind::capsule:
      return sdf_capsule(p, s.vector(0), s.vector(1), s.scalar(2));
    case NodeKind::cone: {
      const T height = s.scalar(1);
      if (s.is_uniform(0) || s.is_uniform(1)) return sdf_cone(p, height, height * std::tan(s.scalar(0)), -height);
      return sdf_cone(p, height, s.scalar(2), s.scalar(3));
    }
    case NodeKind::ellipsoid:
      return mode_ == SdfMode::safe ? sdf_ellipsoid_bound(p, s.vector(0)) : sdf_ellipsoid_estimate(p, s.vector(0));
    case NodeKind::cylinder:
      return sdf_cylinder(p, s.scalar(0));
    case NodeKind::implicit:
    case NodeKind::parametric:
      return leaves_[static_cast<std::size_t>(n.leaf)].evaluate(p);
    case NodeKind::csg_union:
    case NodeKind::csg_intersection:
    case NodeKind::csg_difference:
    case NodeKind::smooth_union:
    case NodeKind::smooth_intersection:
    case NodeKind::smooth_difference: {
      T d = child(0, p);
      for (std::size_t i = 1; i < n.children.size(); ++i) {
        const T e = child(i, p);
        switch (n.kind) {
          case NodeKind::csg_union:
            d = std::min(d, e);
            break;
          case NodeKind::csg_intersection:
            d = std::max(d, e);
            break;
          case NodeKind::csg_difference:
            d = std::max(d, -e);
            break;
          case NodeKind::smooth_union:
            d = smooth_min(d, e, s.scalar(0), n.count);
            break;
          case NodeKind::smooth_intersection:
            d = smooth_max(d, e, s.scalar(0), n.count);
            break;
          default:  // smooth_difference
            d = smooth_max(d, -e, s.scalar(0), n.count);
            break;
        }
      }
      return d;
    }
    case NodeKind::translate:
      return child(0, translate_point(p, s.vector(0)));
    case NodeKind::rotate: {
      if (s.is_uniform(1)) {
        const T angle = s.scalar(1);
        return child(0, rotate_point(p, s.vector(0), T(std::cos(angle)), T(std::sin(angle))));
      }
      return child(0, rotate_point(p, s.vector(0), s.scalar(2), s.scalar(3)));
    }
    case NodeKind::scale: {
      const T factor = s.scalar(0);
      return child(0, scale_point(p, factor)) * factor;
    }
    case NodeKind::twist: {
      const T k = s.scalar(0);
      const T d = child(0, twist_point(p, k));
      return mode_ == SdfMode::safe ? twist_bound(p, k, d) : d;
    }
    case NodeKind::bend: {
      const T k = s.scalar(0);
      const T d = child(0, bend_point(p, k));
      return mode_ == SdfMode::safe ? bend_bound(p, k, d) : d;
    }
    case NodeKind::round:
      return round_value(child(0, p), s.scalar(0));
    case NodeKind::elongate: {
      const Vec3<T> h = s.vector(0);
      const T d = child(0, elongate_point(p, h));
      return mode_ == SdfMode::safe ? elongate_bound(p, h, d) : d;
    }
    case NodeKind::symmetry:
      return child(0, mirror_point(p, axes_of(n.slots[0].value)));
    case NodeKind::repeat:
    case NodeKind::repeat_finite: {
      const bool finite = n.kind == NodeKind::repeat_finite;
      const AxisSet axes = axes_of(n.slots[0].value);  // structural: from the default
      const Vec3<T> period = s.vector(0);
      if (mode_ != SdfMode::safe) {
        return child(0, finite ? repeat_finite_point(p, period, s.vector(1), axes) : repeat_point(p, period, axes));
      }
      const Node& c = nodes_[n.children[0]];
      const Vec3<T> lo{c.box_lo_float.x, c.box_lo_float.y, c.box_lo_float.z};
      const Vec3<T> hi{c.box_hi_float.x, c.box_hi_float.y, c.box_hi_float.z};
      const auto inner = [&](const Vec3<T>& q) { return child(0, q); };
      return finite ? repeat_finite_bound(p, period, s.vector(1), axes, lo, hi, inner)
                    : repeat_bound(p, period, axes, lo, hi, inner);
    }
    case NodeKind::displace: {
      const T d = child(0, p);
      return mode_ == SdfMode::safe ? displace_bound(p, s.scalar(0), s.scalar(1), d)
                                    : displace_value(p, s.scalar(0), s.scalar(1), d);
    }
  }
  throw std::logic_error("evaluate_node: unknown node kind");
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

class SceneGlslWriter {
 public:
  explicit SceneGlslWriter(const CompiledScene& scene) : scene_(scene), prefix_(scene.name_) {}

  // Prints the whole text; `globals` receives every global identifier it defines.
  std::string write(std::set<std::string>& globals);

 private:
  std::string emit_node(std::uint32_t index, const std::string& point);

  // Adds helper `id` (defining PREFIX_id) once, in order of first use.
  void require_helper(const std::string& id, const std::string& text) {
    if (helper_ids_.insert(id).second) {
      helpers_ += text;
      globals_.insert(prefix_ + "_" + id);
    }
  }
  std::string point(const std::string& expression, const std::string& comment) {
    const std::string name = "p" + std::to_string(++variables_);
    body_ += "  vec3 " + name + " = " + expression + ";  // " + comment + "\n";
    return name;
  }
  std::string value(const std::string& expression, const std::string& comment) {
    const std::string name = "d" + std::to_string(++variables_);
    body_ += "  float " + name + " = " + expression + ";  // " + comment + "\n";
    return name;
  }
  std::string scalar(const Node& n, std::size_t i) const {
    const Slot& s = n.slots[i];
    if (s.uniform >= 0) return scene_.uniforms_[static_cast<std::size_t>(s.uniform)].name;
    return format_glsl_float(s.value_float.x);
  }
  std::string vector(const Node& n, std::size_t i) const {
    const Slot& s = n.slots[i];
    if (s.uniform >= 0) return scene_.uniforms_[static_cast<std::size_t>(s.uniform)].name;
    return "vec3(" + format_glsl_float(s.value_float.x) + ", " + format_glsl_float(s.value_float.y) + ", " +
           format_glsl_float(s.value_float.z) + ")";
  }
  std::string call(const std::string& id, const std::string& arguments) const {
    return prefix_ + "_" + id + "(" + arguments + ")";
  }

  const CompiledScene& scene_;
  const std::string prefix_;
  std::set<std::string> helper_ids_;
  std::set<std::string> globals_;
  std::string helpers_, body_;
  std::size_t variables_ = 0;
};

// NODE KIND: one case per kind, the same steps as evaluate_node() above.
std::string SceneGlslWriter::emit_node(std::uint32_t index, const std::string& p) {
  const Node& n = scene_.nodes_[index];
  const std::string type(node_kind_info(n.kind).type_name);
  const auto primitive = [&](const std::string& id, const std::string& text, const std::string& arguments) {
    require_helper(id, text);
    return value(call(id, p + ", " + arguments), type);
  };
  switch (n.kind) {
    case NodeKind::sphere:
      return primitive("sphere", sphere_glsl(prefix_), scalar(n, 0));
    case NodeKind::box:
      return primitive("box", box_glsl(prefix_), vector(n, 0));
    case NodeKind::round_box:
      return primitive("round_box", round_box_glsl(prefix_), vector(n, 0) + ", " + scalar(n, 1));
    case NodeKind::torus:
      return primitive("torus", torus_glsl(prefix_), scalar(n, 0) + ", " + scalar(n, 1));
    case NodeKind::plane:
      return primitive("plane", plane_glsl(prefix_), vector(n, 0) + ", " + scalar(n, 1));
    case NodeKind::capsule:
      return primitive("capsule", capsule_glsl(prefix_), vector(n, 0) + ", " + vector(n, 1) + ", " + scalar(n, 2));
    case NodeKind::cone: {
      const std::string height = scalar(n, 1);
      if (n.slots[0].uniform >= 0 || n.slots[1].uniform >= 0) {
        return primitive("cone", cone_glsl(prefix_),
                         height + ", " + height + " * tan(" + scalar(n, 0) + "), -" + height);
      }
      return primitive("cone", cone_glsl(prefix_), height + ", " + scalar(n, 2) + ", " + scalar(n, 3));
    }
    case NodeKind::ellipsoid:
      return primitive("ellipsoid",
                       scene_.mode_ == SdfMode::safe ? ellipsoid_bound_glsl(prefix_) : ellipsoid_estimate_glsl(prefix_),
                       vector(n, 0));
    case NodeKind::cylinder:
      return primitive("cylinder", cylinder_glsl(prefix_), scalar(n, 0));
    case NodeKind::implicit:
    case NodeKind::parametric: {
      const PolynomialLeaf& leaf = scene_.leaves_[static_cast<std::size_t>(n.leaf)];
      const std::string id = "leaf" + std::to_string(n.leaf);
      require_helper(id, leaf.to_glsl(prefix_ + "_" + id));
      const std::string d = value(call(id, p), type);
      if (!leaf.trimmed()) return d;
      require_helper("trim", trim_glsl(prefix_));
      const auto corner = [](const Vec3<float>& c) {
        return "vec3(" + format_glsl_float(c.x) + ", " + format_glsl_float(c.y) + ", " + format_glsl_float(c.z) + ")";
      };
      return value(call("trim", p + ", " + corner(leaf.trim_lo()) + ", " + corner(leaf.trim_hi()) + ", " + d),
                   "trimmed to the patch's box");
    }
    case NodeKind::csg_union:
    case NodeKind::csg_intersection:
    case NodeKind::csg_difference:
    case NodeKind::smooth_union:
    case NodeKind::smooth_intersection:
    case NodeKind::smooth_difference: {
      std::string d = emit_node(n.children[0], p);
      const std::string count = std::to_string(n.count);
      if (n.kind == NodeKind::smooth_union) require_helper("smin" + count, smooth_min_glsl(prefix_, n.count));
      if (n.kind == NodeKind::smooth_intersection || n.kind == NodeKind::smooth_difference) {
        require_helper("smax" + count, smooth_max_glsl(prefix_, n.count));
      }
      for (std::size_t i = 1; i < n.children.size(); ++i) {
        const std::string e = emit_node(n.children[i], p);
        switch (n.kind) {
          case NodeKind::csg_union:
            d = value("min(" + d + ", " + e + ")", type);
            break;
          case NodeKind::csg_intersection:
            d = value("max(" + d + ", " + e + ")", type);
            break;
          case NodeKind::csg_difference:
            d = value("max(" + d + ", -" + e + ")", type);
            break;
          case NodeKind::smooth_union:
            d = value(call("smin" + count, d + ", " + e + ", " + scalar(n, 0)), type);
            break;
          case NodeKind::smooth_intersection:
            d = value(call("smax" + count, d + ", " + e + ", " + scalar(n, 0)), type);
            break;
          default:  // smooth_difference
            d = value(call("smax" + count, d + ", -" + e + ", " + scalar(n, 0)), type);
            break;
        }
      }
      return d;
    }
    case NodeKind::translate:
      return emit_node(n.children[0], point(p + " - " + vector(n, 0), type));
    case NodeKind::rotate: {
      require_helper("rotate", rotate_glsl(prefix_));
      const std::string trig = n.slots[1].uniform >= 0 ? "cos(" + scalar(n, 1) + "), sin(" + scalar(n, 1) + ")"
                                                       : scalar(n, 2) + ", " + scalar(n, 3);
      return emit_node(n.children[0], point(call("rotate", p + ", " + vector(n, 0) + ", " + trig), type));
    }
    case NodeKind::scale: {
      const std::string factor = scalar(n, 0);
      const std::string d = emit_node(n.children[0], point(p + " / " + factor, type));
      return value(d + " * " + factor, type);
    }
    case NodeKind::twist:
    case NodeKind::bend: {
      const std::string id = n.kind == NodeKind::twist ? "twist" : "bend";
      require_helper(id, n.kind == NodeKind::twist ? twist_glsl(prefix_) : bend_glsl(prefix_));
      const std::string k = scalar(n, 0);
      const std::string d = emit_node(n.children[0], point(call(id, p + ", " + k), type));
      if (scene_.mode_ != SdfMode::safe) return d;
      require_helper(id + "_bound", n.kind == NodeKind::twist ? twist_bound_glsl(prefix_) : bend_bound_glsl(prefix_));
      return value(call(id + "_bound", p + ", " + k + ", " + d), type + ": over the local Lipschitz constant");
    }
    case NodeKind::round: {
      require_helper("round", round_glsl(prefix_));
      const std::string d = emit_node(n.children[0], p);
      return value(call("round", d + ", " + scalar(n, 0)), type);
    }
    case NodeKind::elongate: {
      require_helper("elongate", elongate_glsl(prefix_));
      const std::string h = vector(n, 0);
      const std::string d = emit_node(n.children[0], point(call("elongate", p + ", " + h), type));
      if (scene_.mode_ != SdfMode::safe) return d;
      require_helper("elongate_bound", elongate_bound_glsl(prefix_));
      return value(call("elongate_bound", p + ", " + h + ", " + d), type + ": deeper inside the core box");
    }
    case NodeKind::symmetry: {
      const AxisSet axes = axes_of(n.slots[0].value);
      const std::string id = "symmetry_" + axes.letters();
      require_helper(id, symmetry_glsl(prefix_, axes));
      return emit_node(n.children[0], point(call(id, p), type));
    }
    case NodeKind::repeat:
    case NodeKind::repeat_finite: {
      const bool finite = n.kind == NodeKind::repeat_finite;
      const AxisSet axes = axes_of(n.slots[0].value);
      const std::string base = (finite ? "repeat_finite_" : "repeat_") + axes.letters();
      const std::string arguments = p + ", " + vector(n, 0) + (finite ? ", " + vector(n, 1) : "");
      if (scene_.mode_ != SdfMode::safe) {
        require_helper(base, finite ? repeat_finite_glsl(prefix_, axes) : repeat_glsl(prefix_, axes));
        return emit_node(n.children[0], point(call(base, arguments), type));
      }
      // The rest bound, then the child in each of the 2^m cells inside one loop, so
      // the child's code is written once whatever m.
      require_helper(base + "_cell", finite ? repeat_finite_safe_glsl(prefix_, axes) : repeat_safe_glsl(prefix_, axes));
      require_helper(base + "_rest", "");  // defined by the same text
      const Node& c = scene_.nodes_[n.children[0]];
      const auto corner = [](const Vec3<float>& v) {
        return "vec3(" + format_glsl_float(v.x) + ", " + format_glsl_float(v.y) + ", " + format_glsl_float(v.z) + ")";
      };
      const std::string v =
          value(call(base + "_rest", arguments + ", " + corner(c.box_lo_float) + ", " + corner(c.box_hi_float)),
                type + ": the copies beyond the evaluated cells");
      const std::string cell = "c" + std::to_string(++variables_);
      body_ +=
          "  for (int " + cell + " = 0; " + cell + " < " + std::to_string(1 << axes.size()) + "; ++" + cell + ") {\n";
      const std::string d = emit_node(n.children[0], point(call(base + "_cell", arguments + ", " + cell), type));
      body_ += "  " + v + " = min(" + v + ", " + d + ");\n  }\n";
      return v;
    }
    case NodeKind::displace: {
      const std::string id = scene_.mode_ == SdfMode::safe ? "displace_bound" : "displace";
      require_helper(id, scene_.mode_ == SdfMode::safe ? displace_bound_glsl(prefix_) : displace_glsl(prefix_));
      const std::string d = emit_node(n.children[0], p);
      return value(call(id, p + ", " + scalar(n, 0) + ", " + scalar(n, 1) + ", " + d), type);
    }
  }
  throw std::logic_error("emit_node: unknown node kind");
}

std::string SceneGlslWriter::write(std::set<std::string>& globals) {
  const std::string result = emit_node(scene_.root_, "p");
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
  out += "float " + function + "(vec3 p) {\n" + body_ + "  return " + result + ";\n}\n";
  globals = globals_;
  return out;
}

CompiledScene SceneCompiler::run(const SceneNode& root) {
  try {
    check_glsl_name(options_.name);
  } catch (const InputError& e) {
    throw e.in_field("name");
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
