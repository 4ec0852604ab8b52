#include "implicitizer/scene/polynomial_leaf.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/implicitization/patch_domain.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "implicitizer/scene/primitives.hpp"
#include "implicitizer/sdf/enclosure.hpp"
#include "implicitizer/sdf/polynomial_program.hpp"
#include "node_operations.hpp"

namespace implicitizer {
namespace {

// Rethrows an InputError of a sub-field ("x", "domain", or "" for the whole text) as
// one of the leaf at `field`.
InputError at_field(const InputError& e, const std::string& field, const std::string& sub) {
  const std::string& part = e.field().empty() ? sub : e.field();
  return e.in_field(part.empty() ? field : field + "." + part);
}

}  // namespace

namespace {

// A leaf's implicit equation: parsed (kind implicit) or implicitized (kind
// parametric), with the patch it stands for (parametric only).
struct LeafEquation {
  Polynomial f{space_ring()};
  struct Patch {
    Parametrization parametrization;
    std::optional<ParameterDomain> domain;  ///< none: the whole parameter plane
    PatchBounds bounds;                     ///< a box containing X(domain), in x, y, z
  };
  std::optional<Patch> patch;
};

// The requested domain, checked: one interval per parameter, each with lo < hi (a
// degenerate interval makes a curve or a point, not a patch).
ParameterDomain checked_domain(const PolynomialLeafSource& source, const Parametrization& parametrization) {
  const RingPtr& ring = parametrization.parameter_ring;
  if (source.domain.size() != ring->num_variables()) {
    throw InputError("invalid_domain", "the domain has " + std::to_string(source.domain.size()) +
                                           " intervals, the parametrization " + std::to_string(ring->num_variables()) +
                                           " parameters")
        .in_field("domain");
  }
  for (std::size_t j = 0; j < source.domain.size(); ++j) {
    const auto& [lo, hi] = source.domain[j];
    if (!(lo < hi)) {
      throw InputError("invalid_domain", "the interval of " + ring->variables()[j] + " is [" + to_string(lo) + ", " +
                                             to_string(hi) + "]: its lower end must be below its upper end")
          .in_field("domain");
    }
  }
  // A domain in angles (cos(u), ...) is one in the rational parameters tan(u/2), ...
  return map_parameter_domain(parametrization.substitutions, *ring, ParameterDomain{source.domain});
}

// The patch of `source`: its domain (the default one when the source names none,
// patch_domain.hpp) and the exact bound of its image (a curve's in the plane z = 0).
LeafEquation::Patch leaf_patch(const PolynomialLeafSource& source, Parametrization parametrization,
                               const Budget& budget) {
  LeafEquation::Patch patch;
  if (source.domain.empty()) {
    DefaultPatchDomain d = default_patch_domain(parametrization, budget);
    if (!d.whole_plane) patch.domain = std::move(d.domain);
    patch.bounds = std::move(d.bounds);
  } else {
    patch.domain = checked_domain(source, parametrization);
    patch.bounds = bound_patch(parametrization, *patch.domain, budget);
  }
  if (patch.bounds.lo.size() == 2) {
    patch.bounds.lo.emplace_back(0);
    patch.bounds.hi.emplace_back(0);
  }
  patch.parametrization = std::move(parametrization);
  return patch;
}

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
  try {
    out.patch = leaf_patch(source, parametrization, budget);
  } catch (const InputError& e) {
    throw at_field(e, field, "domain");
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
      out.f = parse_polynomial(source.equation, space_ring(), budget);
      // A curve's equation is in x, y: a z that survives (its terms do not cancel) is
      // `unknown_variable`, as the plane ring's parser says it; a term with a zero
      // coefficient changes no variable.
      if (dimension == 2 && out.f.involves(2)) parse_polynomial(source.equation, plane_ring(), budget);
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

// The frame box fitted to a patch: its bound padded by 1e-4 of its largest side, so
// that the patch never lies on the frame's edge; no more, so that where Z runs on past
// an edge of D out of the box its box distance trims it (patch_cover.hpp, "Edges"). A patch whose bound is a point is
// not a surface piece, and one beyond float's range cannot be stated in the GLSL.
SceneBox fitted_box(const PatchBounds& bounds, const std::string& field) {
  Rational largest(0);
  for (std::size_t i = 0; i < 3; ++i) {
    const Rational side = bounds.hi[i] - bounds.lo[i];
    if (side > largest) largest = side;
  }
  if (largest == Rational(0)) {
    throw InputError("invalid_domain", "the domain's image is a single point").in_field(field + ".domain");
  }
  const Rational pad = largest / Rational(10000);
  SceneBox box;
  for (std::size_t i = 0; i < 3; ++i) {
    box.lo[i] = bounds.lo[i] - pad;
    box.hi[i] = bounds.hi[i] + pad;
    if (!std::isfinite(round_down<float>(box.lo[i])) || !std::isfinite(round_up<float>(box.hi[i]))) {
      throw InputError("invalid_domain", "the patch's box exceeds float's range").in_field(field + ".domain");
    }
  }
  return box;
}

// The source's tolerance, checked: a parametric surface over a bounded domain, a sheet,
// 0 < EPS <= 0.5 (beyond half the diagonal an approximation says nothing).
void check_tolerance(NodeKind kind, const PolynomialLeafSource& source, const std::string& field, int dimension) {
  const double eps = *source.tolerance;
  const auto refuse = [&](const std::string& message) {
    return InputError("invalid_tolerance", message).in_field(field + ".tolerance");
  };
  if (kind != NodeKind::parametric) throw refuse("only parametric inputs are approximated");
  if (!std::isfinite(eps) || !(eps > 0) || eps > 0.5) {
    throw refuse("a tolerance is a fraction of the patch box's diagonal in (0, 0.5]");
  }
  if (dimension == 2) throw refuse("only parametric surfaces are approximated, not plane curves");
  if (source.shape == SdfShape::solid) {
    throw refuse("an approximation is a sheet (the patch): ask for shape sheet or auto, or leave out the tolerance");
  }
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
  if (source.tolerance) check_tolerance(kind, source, field, dimension);
  const LeafEquation equation = leaf_equation(kind, source, budget, field, dimension);
  SceneBox frame_box = source.box ? *source.box : default_box;
  if (equation.patch && !source.box) frame_box = fitted_box(equation.patch->bounds, field);
  if (dimension == 2) frame_box = curve_frame_box(frame_box);
  // A patch over a bounded domain is trimmed to its cover; over the whole plane it is,
  // up to its closure, all of its algebraic surface in the fitted box (docs/sdf.md,
  // "Patches"), which the frame clips as for an implicit leaf.
  const bool bounded_patch = equation.patch && equation.patch->domain;
  const ExactSource exact{kind,
                          source,
                          equation.f,
                          frame_box,
                          bounded_patch ? &equation.patch->parametrization : nullptr,
                          bounded_patch ? &*equation.patch->domain : nullptr,
                          dimension};
  if (!bounded_patch || !source.tolerance) {
    PolynomialLeaf leaf = build_exact(exact, mode, budget, field);
    leaf.tolerance_ = source.tolerance;
    if (source.tolerance) {
      leaf.kept_exact_ =
          "a closed surface over the whole parameter plane keeps its exact equation (its degree is already low)";
    }
    return leaf;
  }
  // A tolerance: the exact equation meets every one, so the approximation is kept only
  // where its GLSL is shorter. Safe mode may have no exact leaf (degree_too_high).
  std::optional<PolynomialLeaf> exact_leaf;
  std::string no_exact;
  try {
    exact_leaf = build_exact(exact, mode, budget, field);
  } catch (const InputError& e) {
    if (e.code() != "degree_too_high") throw;
    no_exact = e.what();
  }
  PolynomialLeaf leaf = build_cheapest(std::move(exact_leaf), no_exact, equation.patch->parametrization,
                                       *equation.patch->domain, frame_box, *source.tolerance, mode, budget, field);
  leaf.tolerance_ = source.tolerance;
  return leaf;
}

PolynomialLeaf PolynomialLeaf::build_exact(const ExactSource& in, SdfMode mode, const Budget& budget,
                                           const std::string& field) {
  PolynomialLeaf leaf(in.f);
  Enclosure shape;
  Piece piece;
  try {
    shape = resolve_shape(in.source, in.f, in.frame_box, in.domain != nullptr, in.dimension, budget);
    const Polynomial f = shape.negate ? -in.f : in.f;
    if (mode == SdfMode::safe) {
      piece.safe = SafeSdf::build(f, in.frame_box, budget, shape.shape);
    } else {
      // A patch's sheet is trimmed by its cover, 0 on the patch: where G's rounding over
      // a vanishing gradient would make the estimate no distance (near double curves)
      // the cover's distance stands alone (FastSdf::SheetOptions).
      const bool covered = in.domain != nullptr && shape.shape == SdfShape::sheet;
      piece.fast = FastSdf::build(f, in.frame_box, budget, shape.shape, {0, covered});
    }
  } catch (const InputError& e) {
    // invalid_box concerns the box; degree_too_high the equation.
    throw at_field(e, field, e.code() == "invalid_box" ? "box" : (in.kind == NodeKind::implicit ? "equation" : ""));
  }
  leaf.frame_box_ = in.frame_box;
  leaf.shape_ = shape.shape;
  leaf.shape_reason_ = shape.reason;
  leaf.negated_ = shape.negate;
  // A solid asked of a patch is the solid F <= 0 in its box: nothing to trim.
  if (in.domain && shape.shape == SdfShape::sheet) {
    piece.cover = PatchCover::build(*in.parametrization, *in.domain, in.f, in.frame_box, budget);
  }
  leaf.pieces_.push_back(std::move(piece));
  return leaf;
}

namespace {

std::size_t count_lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

std::string count_of(std::size_t n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

std::string approximation_size(const PatchApproximation& a, std::size_t lines) {
  return count_of(a.pieces.size(), "piece") + " of degree at most " + std::to_string(a.max_degree) + ", " +
         count_of(lines, "line");
}

}  // namespace

std::size_t PolynomialLeaf::piece_glsl_lines(std::size_t k) const {
  // Beyond the first, a piece is also its culling test, its distance's call, its
  // cover's call with the min and the closing brace (emit_leaf).
  std::size_t lines = count_lines(to_glsl("f", k)) + (k > 0 ? 4 : 0);
  if (trimmed()) lines += count_lines(trim_glsl("c", k));
  return lines;
}

std::size_t PolynomialLeaf::glsl_lines() const {
  std::size_t lines = 0;
  for (std::size_t k = 0; k < pieces_.size(); ++k) lines += piece_glsl_lines(k);
  return lines;
}

PolynomialLeaf PolynomialLeaf::build_cheapest(std::optional<PolynomialLeaf> exact, const std::string& no_exact,
                                              const Parametrization& parametrization, const ParameterDomain& domain,
                                              const SceneBox& frame_box, double tolerance, SdfMode mode,
                                              const Budget& budget, const std::string& field) {
  const std::size_t exact_lines = exact ? exact->glsl_lines() : std::numeric_limits<std::size_t>::max();
  // The pieces are compiled as they are accepted, so the approximation stops as soon
  // as what it has plus a lower bound for what is left reaches the exact equation.
  PolynomialLeaf leaf{Polynomial(space_ring())};
  std::size_t lines = 0;
  const auto compile_accepted = [&](const std::vector<ApproximationPiece>& accepted) {
    while (leaf.pieces_.size() < accepted.size()) {
      leaf.pieces_.push_back(
          build_piece(accepted[leaf.pieces_.size()], parametrization, frame_box, mode, budget, field));
      lines += leaf.piece_glsl_lines(leaf.pieces_.size() - 1);
    }
  };
  ApproximationParams params;
  params.tolerance = tolerance;
  params.keep_going = [&](const std::vector<ApproximationPiece>& accepted, std::size_t pending) {
    compile_accepted(accepted);
    return lines + pending * kMinPieceGlslLines < exact_lines;
  };
  const auto keep_exact = [&](const std::string& why) {
    exact->kept_exact_ = why;
    return std::move(*exact);
  };
  PatchApproximation approximation;
  try {
    approximation = approximate_patch(parametrization, domain, params, budget);
  } catch (const InputError& e) {
    throw at_field(e, field, e.code() == "invalid_tolerance" ? "tolerance" : "x");
  } catch (const ApproximationStopped&) {
    return keep_exact("the exact equation's GLSL (" + count_of(exact_lines, "line") +
                      ") is shorter than any approximation's: the pieces accepted so far (" +
                      std::to_string(leaf.pieces_.size()) + ") take " + count_of(lines, "line") +
                      ", and the rest of the domain needs more");
  } catch (const ToleranceNotMet& e) {
    if (!exact) throw ToleranceNotMet(std::string(e.what()) + "; and the exact equation: " + no_exact, e.best());
    return keep_exact("no approximation meets the tolerance (" + std::string(e.what()) + "); the exact equation does");
  }
  compile_accepted(approximation.pieces);
  if (lines >= exact_lines) {
    return keep_exact("the exact equation's GLSL (" + count_of(exact_lines, "line") +
                      ") is no longer than the approximation's (" + approximation_size(approximation, lines) + ")");
  }
  leaf.equation_ = approximation.pieces.front().equation;
  leaf.frame_box_ = frame_box;
  // Each piece's signed estimate in the leaf's frame box, not its own: a solid is
  // clipped to its box (positive outside), and the side must keep q's sign wherever
  // the sheet may be crossed.
  std::vector<FastSdf> sides;
  for (const ApproximationPiece& piece : approximation.pieces) {
    sides.push_back(FastSdf::build(piece.equation, frame_box, budget, SdfShape::solid));
  }
  leaf.side_.emplace(std::move(sides));
  leaf.shape_ = SdfShape::sheet;
  leaf.shape_reason_ = "an approximated patch is a sheet";
  leaf.approximation_ = std::move(approximation);
  return leaf;
}

PolynomialLeaf::Piece PolynomialLeaf::build_piece(const ApproximationPiece& source,
                                                  const Parametrization& parametrization, const SceneBox& frame_box,
                                                  SdfMode mode, const Budget& budget, const std::string& field) {
  budget.check("approximated leaf");
  // Each piece in the box fitted to X(S_k), as a patch's frame is to X(D): its own
  // scale, so its fp32 evaluation is as accurate as a whole patch's; cut to the leaf's
  // frame box, which clips the object as it clips an exact leaf.
  SceneBox box = fitted_box(source.box, field);
  SceneBox cut = box;
  bool meets = true;
  for (std::size_t i = 0; i < 3; ++i) {
    cut.lo[i] = std::max(box.lo[i], frame_box.lo[i]);
    cut.hi[i] = std::min(box.hi[i], frame_box.hi[i]);
    meets = meets && cut.lo[i] < cut.hi[i];
  }
  if (meets) box = cut;
  Piece piece;
  try {
    if (mode == SdfMode::safe) {
      piece.safe = SafeSdf::build(source.equation, box, budget, SdfShape::sheet);
    } else {
      // q approximates the patch near its piece only: farther, its gradient may be small
      // where q is not, and q/|grad q| overshoot the drawn sheet by more than a step can
      // recover (docs/sdf.md, "Approximate implicitization"); capped at a quarter of the
      // piece's half side, a march crosses the piece's box in a few steps.
      piece.fast = FastSdf::build(source.equation, box, budget, SdfShape::sheet, {kPieceEstimateCap, false});
    }
  } catch (const InputError& e) {
    throw at_field(e, field, e.code() == "invalid_box" ? "box" : "");
  }
  // A polytope when the approximation measured its kept zeros there, else a cover.
  // A polytope keeps q's zeros within the tolerance of X(S), not sharp to D's edges:
  // its chords let q's continuation past an edge show as a halo up to a pixel wide
  // (docs/sdf.md, "Trimming a piece to a polytope"); a cover there costs several times
  // the polytope's lines and evaluation, what the tolerance is there to avoid.
  if (source.polytope) {
    piece.polytope.emplace(*source.polytope, source.box);
  } else {
    piece.cover = PatchCover::build(parametrization, source.domain, source.equation, box, budget);
  }
  return piece;
}

TrimmingSummary PolynomialLeaf::trimming() const {
  TrimmingSummary t;
  bool covers = false, polytopes = false;
  for (const Piece& piece : pieces_) {
    if (!piece.cover) {
      polytopes = polytopes || piece.polytope.has_value();
      continue;
    }
    covers = true;
    const PatchCoverStats& stats = piece.cover->stats();
    t.leaves += stats.leaves;
    t.box_leaves += stats.box_leaves;
    t.blunt_edge_leaves += stats.edge_unresolved;
  }
  const std::string slabs = t.box_leaves + t.blunt_edge_leaves > 0 ? "slabs and boxes" : "slabs";
  t.method = polytopes ? (covers ? "polytopes and " + slabs : "polytopes") : slabs;
  return t;
}

std::string PolynomialLeaf::trim_glsl(const std::string& function, std::size_t k) const {
  const Piece& piece = pieces_[k];
  return piece.cover ? piece.cover->to_glsl(function) : piece.polytope->to_glsl(function);
}

std::vector<std::string> PolynomialLeaf::trim_glsl_suffixes(std::size_t k) const {
  return pieces_[k].cover ? PatchCover::glsl_suffixes() : PolytopeTrim::glsl_suffixes();
}

std::string PolynomialLeaf::trim_hull_glsl(const std::string& p, std::size_t k) const {
  const Piece& piece = pieces_[k];
  return piece.cover ? piece.cover->hull_glsl(p) : piece.polytope->hull_glsl(p);
}

Vec3<float> PolynomialLeaf::trim_corner(bool upper) const {
  const auto corner_of = [&](const Piece& piece) {
    if (piece.cover) return upper ? piece.cover->hi() : piece.cover->lo();
    return upper ? piece.polytope->hi() : piece.polytope->lo();
  };
  Vec3<float> corner = corner_of(pieces_.front());
  for (const Piece& piece : pieces_) {
    const Vec3<float> c = corner_of(piece);
    corner = upper ? Vec3<float>{std::max(corner.x, c.x), std::max(corner.y, c.y), std::max(corner.z, c.z)}
                   : Vec3<float>{std::min(corner.x, c.x), std::min(corner.y, c.y), std::min(corner.z, c.z)};
  }
  return corner;
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
    // t ≥ 0 everywhere: the solid {t ≤ 0} is the sheet, inside the cover's boxes.
    const Vec3<float> l = leaf.trim_lo();
    const Vec3<float> h = leaf.trim_hi();
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

// Piece k of a leaf: its distance, then its cover. A leaf of one surface keeps the
// names leaf<n> and leaf<n>_cover; an approximation's pieces are leaf<n>_piece<k>.
// Piece k's untrimmed distance, stated as a value; returns its name.
std::string emit_piece_distance(SceneGlslWriter& w, const PolynomialLeaf& leaf, const std::string& id, std::size_t k,
                                const CompiledNode& n, const std::string& p) {
  w.require_helper(id, leaf.to_glsl(w.prefix() + "_" + id, k));
  return w.value(w.call(id, p), SceneGlslWriter::type(n));
}

// The call of piece k's cover on its distance `d`.
std::string cover_call(SceneGlslWriter& w, const PolynomialLeaf& leaf, const std::string& id, std::size_t k,
                       const std::string& p, const std::string& d) {
  const std::string cover = id + "_cover";
  w.require_helper(cover, leaf.trim_glsl(w.prefix() + "_" + cover, k), leaf.trim_glsl_suffixes(k));
  return w.call(cover, p + ", " + d);
}

std::string emit_piece(SceneGlslWriter& w, const PolynomialLeaf& leaf, const std::string& id, std::size_t k,
                       const CompiledNode& n, const std::string& p) {
  const std::string d = emit_piece_distance(w, leaf, id, k, n, p);
  if (!leaf.trimmed()) return d;
  return w.value(cover_call(w, leaf, id, k, p, d), "trimmed to the patch's cover");
}

std::string emit_leaf(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  const PolynomialLeaf& leaf = w.leaf(n);
  const std::string id = "leaf" + std::to_string(n.leaf);
  if (leaf.piece_count() == 1) return emit_piece(w, leaf, id, 0, n, p);
  // The union of the pieces' sheets, in evaluate()'s order (min is exact in float),
  // each piece skipped when its cover's hull is no nearer than the union so far, and
  // its cover when its |d| is not.
  const std::string value =
      w.value(emit_piece(w, leaf, id + "_piece0", 0, n, p), "the union of the approximation's pieces");
  for (std::size_t k = 1; k < leaf.piece_count(); ++k) {
    const std::string piece = id + "_piece" + std::to_string(k);
    w.statement("  if (" + leaf.trim_hull_glsl(p, k) + " < " + value + ") {\n");
    const std::string d = emit_piece_distance(w, leaf, piece, k, n, p);
    w.statement("  if (abs(" + d + ") < " + value + ") " + value + " = min(" + value + ", " +
                cover_call(w, leaf, piece, k, p, d) + ");\n  }\n");
  }
  return value;
}

}  // namespace

const NodeOperations kPolynomialLeafOperations = {classify_leaf, bound_leaf, evaluate_leaf<float>,
                                                  evaluate_leaf<double>, emit_leaf};

}  // namespace implicitizer
