#include "implicitizer/scene/polynomial_leaf.hpp"

#include <cmath>
#include <limits>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "implicitizer/scene/primitives.hpp"
#include "implicitizer/sdf/enclosure.hpp"
#include "implicitizer/sdf/polynomial_program.hpp"
#include "node_operations.hpp"

namespace implicitizer {
namespace {

// The largest F ≤ q and the smallest F ≥ q (F = float or double): mpq_get_d truncates
// toward zero, so step once or twice to the right side. Beyond F's range the answer is
// ±infinity (the caller refuses it); mpq_class(±inf) would raise SIGFPE in GMP, which
// the request fuzzer found with a patch whose box exceeds float's range.
template <typename F>
F round_down(const Rational& q) {
  const mpq_class exact = to_mpq(q);
  F x = static_cast<F>(exact.get_d());
  while (std::isfinite(x) && mpq_class(static_cast<double>(x)) > exact) {
    x = std::nextafter(x, -std::numeric_limits<F>::infinity());
  }
  return x;
}

template <typename F>
F round_up(const Rational& q) {
  const mpq_class exact = to_mpq(q);
  F x = static_cast<F>(exact.get_d());
  while (std::isfinite(x) && mpq_class(static_cast<double>(x)) < exact) {
    x = std::nextafter(x, std::numeric_limits<F>::infinity());
  }
  return x;
}

// Rethrows an InputError of a sub-field ("x", "domain", or "" for the whole text) as
// one of the leaf at `field`.
InputError at_field(const InputError& e, const std::string& field, const std::string& sub) {
  const std::string& part = e.field().empty() ? sub : e.field();
  return e.in_field(part.empty() ? field : field + "." + part);
}

}  // namespace

std::string trim_glsl(const std::string& prefix) {
  return "float " + prefix +
         "_trim(vec3 p, vec3 lo, vec3 hi, float d) {\n"
         "  vec3 q = max(lo - p, p - hi);\n"
         "  vec3 m = max(q, 0.0);\n"
         "  return max(abs(d), " +
         glsl_length("m") +
         ");\n"
         "}\n";
}

namespace {

// A leaf's implicit equation: parsed (kind implicit) or implicitized (kind
// parametric), with the bounds of the patch when the source gives a domain.
struct LeafEquation {
  Polynomial f{space_ring()};
  std::optional<PatchBounds> bounds;
};

// A plane curve's equation in x, y moved into the ring x, y, z (where it is the
// cylinder over the curve).
Polynomial into_space(const Polynomial& curve) {
  const std::size_t variables[2] = {0, 1};
  return curve.map_to(space_ring(), variables);
}

LeafEquation implicitize_leaf(const PolynomialLeafSource& source, const Budget& budget, const std::string& field,
                              int dimension) {
  LeafEquation out;
  Parametrization parametrization;
  if (dimension == 2 && !source.coordinates[2].empty()) {
    throw InputError("invalid_value", "a plane curve has coordinates x and y only").in_field(field + ".z");
  }
  try {
    std::vector<std::string> coordinates(source.coordinates.begin(),
                                         source.coordinates.begin() + (dimension == 2 ? 2 : 3));
    parametrization = parse_parametrization(coordinates, source.parameter_names, budget);
  } catch (const InputError& e) {
    throw at_field(e, field, "x");
  }
  if (!source.domain.empty()) {
    ParameterDomain domain;
    domain.intervals = source.domain;
    try {
      out.bounds = bound_patch(parametrization, domain, budget);
    } catch (const InputError& e) {
      throw at_field(e, field, "domain");
    }
    // A curve lies in the plane z = 0.
    if (dimension == 2) {
      out.bounds->lo.emplace_back(0);
      out.bounds->hi.emplace_back(0);
    }
  }
  ImplicitizeParams params;
  params.budget = budget;
  try {
    out.f = implicitize(parametrization, params).implicit;
    if (dimension == 2) out.f = into_space(out.f);
  } catch (const NoSingleEquation& e) {
    throw InputError(e.code(), std::string("the parametrization has no single implicit equation: ") + e.what())
        .in_field(field);
  } catch (const InputError& e) {
    throw at_field(e, field, "x");
  }
  return out;
}

LeafEquation leaf_equation(NodeKind kind, const PolynomialLeafSource& source, const Budget& budget,
                           const std::string& field, int dimension) {
  LeafEquation out;
  if (kind == NodeKind::implicit) {
    try {
      // A curve's equation is parsed in x, y: a z in it is `unknown_variable`.
      out.f = dimension == 2 ? into_space(parse_polynomial(source.equation, plane_ring(), budget))
                             : parse_polynomial(source.equation, space_ring(), budget);
    } catch (const InputError& e) {
      throw at_field(e, field, "equation");
    }
  } else {
    out = implicitize_leaf(source, budget, field, dimension);
  }
  if (out.f.is_constant()) {
    throw InputError("constant_polynomial", "a constant polynomial has no surface")
        .in_field(field + (kind == NodeKind::implicit ? ".equation" : ""));
  }
  return out;
}

// A patch's box rounded outwards, in double and in float.
struct TrimBox {
  Vec3<double> lo, hi;
  Vec3<float> lo_float, hi_float;
};

// The box that trims a patch; also pads `frame_box` around it when the source gives
// no box of its own.
TrimBox trim_box(const PatchBounds& bounds, const PolynomialLeafSource& source, SceneBox& frame_box,
                 const std::string& field) {
  // Pad by 1e-3 of the largest side so that the patch never lies on the frame's
  // edge; a patch whose box is a point is not a surface piece.
  Rational largest(0);
  for (std::size_t i = 0; i < 3; ++i) {
    const Rational side = bounds.hi[i] - bounds.lo[i];
    if (side > largest) largest = side;
  }
  if (largest == Rational(0)) {
    throw InputError("invalid_domain", "the domain's image is a single point").in_field(field + ".domain");
  }
  const Rational pad = largest / Rational(1000);
  if (!source.box) {
    for (std::size_t i = 0; i < 3; ++i) {
      frame_box.lo[i] = bounds.lo[i] - pad;
      frame_box.hi[i] = bounds.hi[i] + pad;
    }
  }
  TrimBox box;
  double* lo_d[3] = {&box.lo.x, &box.lo.y, &box.lo.z};
  double* hi_d[3] = {&box.hi.x, &box.hi.y, &box.hi.z};
  float* lo_f[3] = {&box.lo_float.x, &box.lo_float.y, &box.lo_float.z};
  float* hi_f[3] = {&box.hi_float.x, &box.hi_float.y, &box.hi_float.z};
  for (std::size_t i = 0; i < 3; ++i) {
    *lo_d[i] = round_down<double>(bounds.lo[i]);
    *hi_d[i] = round_up<double>(bounds.hi[i]);
    *lo_f[i] = round_down<float>(bounds.lo[i]);
    *hi_f[i] = round_up<float>(bounds.hi[i]);
    if (!std::isfinite(*lo_f[i]) || !std::isfinite(*hi_f[i])) {
      throw InputError("invalid_domain", "the patch's box exceeds float's range").in_field(field + ".domain");
    }
  }
  return box;
}

}  // namespace

namespace {

// A curve's frame box: its x–y rectangle, and z in [−m, m] with m the larger half side
// of the rectangle, so that the frame's scale is the rectangle's and z = 0 its centre.
SceneBox curve_frame_box(SceneBox box) {
  const Rational half = std::max(box.hi[0] - box.lo[0], box.hi[1] - box.lo[1]) / Rational(2);
  box.lo[2] = -half;
  box.hi[2] = half;
  return box;
}

// The box a leaf's value is clipped to: the frame's cube c ± 1/s (docs/sdf.md §3), in
// x, y, z, or its x–y square for a curve.
std::vector<std::pair<Rational, Rational>> clipping_box(const SceneBox& frame_box, int dimension) {
  const SceneFrame frame = make_scene_frame(frame_box);
  const Rational half = Rational(1) / frame.scale;
  std::vector<std::pair<Rational, Rational>> box;
  for (std::size_t i = 0; i < static_cast<std::size_t>(dimension); ++i) {
    box.emplace_back(frame.centre[i] - half, frame.centre[i] + half);
  }
  return box;
}

// The shape the leaf draws (sdf_shape.hpp), and whether F is negated for it.
Enclosure resolve_shape(const PolynomialLeafSource& source, const Polynomial& f, const SceneBox& frame_box, bool patch,
                        int dimension, const Budget& budget) {
  if (source.shape != SdfShape::automatic) return {source.shape, false, "asked"};
  // A patch is an open piece of its surface: it encloses nothing.
  if (patch) return {SdfShape::sheet, false, "a patch with a parameter domain is a sheet"};
  return decide_enclosure(f, clipping_box(frame_box, dimension), budget);
}

}  // namespace

PolynomialLeaf PolynomialLeaf::build(NodeKind kind, const PolynomialLeafSource& source, const SceneBox& default_box,
                                     SdfMode mode, const Budget& budget, const std::string& field, int dimension) {
  const LeafEquation equation = leaf_equation(kind, source, budget, field, dimension);
  SceneBox frame_box = source.box ? *source.box : default_box;
  std::optional<TrimBox> trim;
  if (equation.bounds) trim = trim_box(*equation.bounds, source, frame_box, field);
  if (dimension == 2) frame_box = curve_frame_box(frame_box);
  PolynomialLeaf leaf(equation.f);
  Enclosure shape;
  try {
    shape = resolve_shape(source, equation.f, frame_box, equation.bounds.has_value(), dimension, budget);
    const Polynomial f = shape.negate ? -equation.f : equation.f;
    if (mode == SdfMode::safe) {
      leaf.safe_ = SafeSdf::build(f, frame_box, budget, shape.shape);
    } else {
      leaf.fast_ = FastSdf::build(f, frame_box, budget, shape.shape);
    }
  } catch (const InputError& e) {
    // invalid_box concerns the box; degree_too_high the equation.
    throw at_field(e, field, e.code() == "invalid_box" ? "box" : (kind == NodeKind::implicit ? "equation" : ""));
  }
  // A solid asked of a patch is the solid F <= 0 in its box: nothing to trim.
  if (shape.shape == SdfShape::solid) trim.reset();
  leaf.frame_box_ = frame_box;
  leaf.shape_ = shape.shape;
  leaf.shape_reason_ = shape.reason;
  leaf.negated_ = shape.negate;
  if (trim) {
    leaf.trimmed_ = true;
    leaf.lo_ = trim->lo;
    leaf.hi_ = trim->hi;
    leaf.lo_float_ = trim->lo_float;
    leaf.hi_float_ = trim->hi_float;
  }
  return leaf;
}

// ---------------------------------------------------------------------------------
// The leaf as a scene node (kinds implicit and parametric).

namespace {

// Safe: SafeSdf bounds the distance but is not 1-Lipschitz (a polynomial's gradient
// grows away from the surface); fast: F/|∇F| is an estimate.
void classify_leaf(NodeCompilation& c) { c.out.node_class = c.safe() ? NodeClass::bound : NodeClass::estimate; }

NodeBox bound_leaf(const NodeCompilation& c) {
  const PolynomialLeaf& leaf = c.leaves[static_cast<std::size_t>(c.out.leaf)];
  if (leaf.trimmed()) {
    // t ≥ 0 everywhere: the solid {t ≤ 0} is the sheet, inside the trimming box.
    const Vec3<float>& l = leaf.trim_lo();
    const Vec3<float>& h = leaf.trim_hi();
    return {{l.x, l.y, l.z}, {h.x, h.y, h.z}, false};
  }
  // Beyond kFarField (u = (p − c)·s, max norm) both modes return the positive box
  // distance: the solid lies in the cube c ± kFarField/s (widened by 1e-6 for fp32's
  // rounding of u). A sheet is max(|d|, box distance) ≥ 0, 0 only inside the cube
  // c ± 1/s itself (safe: |u_i| ≤ b/(1 − 4ε), b one float above 1 at most).
  const SceneFrame frame = make_scene_frame(leaf.frame_box());
  const double reach = leaf.shape() == SdfShape::sheet ? 1 : std::max(FastSdf::kFarField, SafeSdf::kFarField);
  const double half = reach / to_mpq(frame.scale).get_d() * (1 + 1e-6);
  const Vec3<double> centre{to_mpq(frame.centre[0]).get_d(), to_mpq(frame.centre[1]).get_d(),
                            to_mpq(frame.centre[2]).get_d()};
  // A fast sheet is max(|d|, b) with b the exact distance to the cube outside it: it
  // grows. (Safe mode rounds b down by a relative 2^-19 or so, which the absolute
  // widening above cannot cover far away.)
  const bool grows = leaf.shape() == SdfShape::sheet && !c.safe();
  return {centre - cube_corner(half), centre + cube_corner(half), grows};
}

template <typename T>
T evaluate_leaf(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return e.leaf(n).evaluate(p);
}

std::string emit_leaf(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  const PolynomialLeaf& leaf = w.leaf(n);
  const std::string id = "leaf" + std::to_string(n.leaf);
  w.require_helper(id, leaf.to_glsl(w.prefix() + "_" + id));
  const std::string d = w.value(w.call(id, p), SceneGlslWriter::type(n));
  if (!leaf.trimmed()) return d;
  w.require_helper("trim", trim_glsl(w.prefix()));
  return w.value(w.call("trim", p + ", " + glsl_vec3(leaf.trim_lo()) + ", " + glsl_vec3(leaf.trim_hi()) + ", " + d),
                 "trimmed to the patch's box");
}

}  // namespace

const NodeOperations kPolynomialLeafOperations = {classify_leaf, bound_leaf, evaluate_leaf<float>,
                                                  evaluate_leaf<double>, emit_leaf};

}  // namespace implicitizer
