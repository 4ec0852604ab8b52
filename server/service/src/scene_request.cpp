#include "implicitizer/service/scene_request.hpp"

#include <algorithm>

#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer {
namespace {

InputError invalid_box(const std::string& message) { return InputError("invalid_box", message).in_field("box"); }

InputError invalid_domain(const std::string& message, const std::string& field) {
  return InputError("invalid_domain", message).in_field(field);
}

// An exact constant expression ("0.25", "1e-30", "-3/7", "2^-10" is not one: exponents
// are non-negative); nullopt when the text is anything else. Every such number is a
// finite rational, so "inf" and "nan" are refused here by construction.
std::optional<Rational> parse_exact_number(const std::string& text, const Budget& budget) {
  Polynomial c(space_ring());
  try {
    c = parse_polynomial(text, space_ring(), budget);
  } catch (const InputError&) {
    return std::nullopt;
  }
  if (!c.is_constant()) return std::nullopt;
  return c.is_zero() ? Rational(0) : c.coefficient(0);
}

Rational parse_box_number(const std::string& text, const Budget& budget) {
  const std::optional<Rational> q = parse_exact_number(text, budget);
  if (!q) throw invalid_box("'" + text + "' is not a number");
  return *q;
}

// Whether the equation involves z (a term with a zero coefficient does not). Parse errors are
// the request's ("implicit"), found here before the scene compiler would.
bool mentions_z(const std::string& equation, const Budget& budget) {
  try {
    return parse_polynomial(equation, space_ring(), budget).involves(2);
  } catch (const InputError& e) {
    throw e.in_field("implicit");
  }
}

// The one leaf of an implicit or parametric input, and its dimension.
SceneNode leaf_of(const SceneRequest& request, int& dimension, const Budget& budget) {
  SceneNode node;
  node.leaf.shape = request.shape;
  // The leaf checks it (an implicit input's is `invalid_tolerance` there).
  node.leaf.tolerance = request.tolerance;
  if (request.parametric) {
    node.kind = NodeKind::parametric;
    node.leaf.coordinates = *request.parametric;
    node.leaf.parameter_names = request.parameters;
    dimension = (*request.parametric)[2].empty() ? 2 : 3;
    const std::size_t parameters = request.parameters ? request.parameters->size() : (dimension == 2 ? 1 : 2);
    if (!request.domain.empty()) node.leaf.domain = parse_request_domain(request.domain, parameters, budget);
    return node;
  }
  if (request.implicit.empty()) {
    throw InputError("missing_field", "give implicit, x/y[/z] (parametric) or scene").in_field("implicit");
  }
  if (!request.domain.empty()) {
    throw invalid_domain("a domain goes with a parametric surface or curve (x, y[, z])", "domain");
  }
  node.kind = NodeKind::implicit;
  node.leaf.equation = request.implicit;
  // In space when F involves z or the box has six numbers (F(x, y) = 0 is then the
  // cylinder over the curve); else a plane curve.
  const bool with_z = mentions_z(request.implicit, budget);
  dimension = with_z || request.box.size() == 6 ? 3 : 2;
  return node;
}

}  // namespace

const char* to_string(SdfMode mode) { return mode == SdfMode::safe ? "safe" : "fast"; }

std::size_t count_lines(const std::string& text) {
  const auto newlines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  return newlines + (!text.empty() && text.back() != '\n' ? 1 : 0);
}

std::optional<ApproximationSummary> summarize_approximation(const PolynomialLeaf& leaf, std::size_t glsl_lines) {
  if (!leaf.tolerance()) return std::nullopt;
  ApproximationSummary s;
  s.tolerance = *leaf.tolerance();
  s.glsl_lines = glsl_lines;
  s.pieces = leaf.piece_count();
  const PatchApproximation* a = leaf.approximation();
  if (!a) {
    // The exact equation: its zero set is the patch's surface, both distances 0.
    s.kept_exact = leaf.tolerance_kept_exact();
    s.degree = leaf.equation().total_degree();
    return s;
  }
  s.degree = a->max_degree;
  s.patch_to_surface = a->patch_to_surface;
  s.patch_to_surface_method = a->patch_to_surface_method;
  s.surface_to_patch = a->surface_to_patch;
  s.surface_to_patch_method = a->surface_to_patch_method;
  s.surface_to_patch_samples = a->surface_to_patch_samples;
  return s;
}

SceneBox parse_request_box(const std::vector<std::string>& numbers, int dimension, const Budget& budget) {
  SceneBox box = SceneBox::default_box();
  if (numbers.empty()) return box;
  if (dimension == 2) {
    if (numbers.size() != 4 && numbers.size() != 6) {
      throw invalid_box("a curve's box is four numbers x0,y0,x1,y1 (or six, z ignored)");
    }
    const std::size_t hi = numbers.size() / 2;  // x1's index
    for (std::size_t i = 0; i < 2; ++i) {
      box.lo[i] = parse_box_number(numbers[i], budget);
      box.hi[i] = parse_box_number(numbers[hi + i], budget);
    }
    // z spans the larger half side around 0: the frame's scale is the plane box's.
    const Rational m = std::max(box.hi[0] - box.lo[0], box.hi[1] - box.lo[1]) / Rational(2);
    box.lo[2] = -m;
    box.hi[2] = m;
    return box;
  }
  if (numbers.size() != 6) throw invalid_box("a box is six numbers x0,y0,z0,x1,y1,z1");
  for (std::size_t i = 0; i < 3; ++i) {
    box.lo[i] = parse_box_number(numbers[i], budget);
    box.hi[i] = parse_box_number(numbers[i + 3], budget);
  }
  return box;
}

std::vector<std::pair<Rational, Rational>> parse_request_domain(const std::vector<std::string>& numbers,
                                                                std::size_t parameters, const Budget& budget) {
  if (numbers.size() != 2 * parameters) {
    throw invalid_domain("a domain is " + std::to_string(2 * parameters) + " numbers (lo, hi for each of the " +
                             std::to_string(parameters) + " parameters), not " + std::to_string(numbers.size()),
                         "domain");
  }
  std::vector<std::pair<Rational, Rational>> domain;
  for (std::size_t i = 0; i < numbers.size(); i += 2) {
    const std::string lo_field = "domain[" + std::to_string(i) + "]";
    const std::optional<Rational> lo = parse_exact_number(numbers[i], budget);
    if (!lo) throw invalid_domain("'" + numbers[i] + "' is not a finite number", lo_field);
    const std::optional<Rational> hi = parse_exact_number(numbers[i + 1], budget);
    if (!hi)
      throw invalid_domain("'" + numbers[i + 1] + "' is not a finite number", "domain[" + std::to_string(i + 1) + "]");
    if (!(*lo < *hi)) {
      throw invalid_domain("an interval needs lo < hi: [" + numbers[i] + ", " + numbers[i + 1] + "]", lo_field);
    }
    domain.emplace_back(*lo, *hi);
  }
  return domain;
}

RequestScene make_request_scene(const SceneRequest& request, const Budget& budget) {
  const int given = (request.scene ? 1 : 0) + (request.parametric ? 1 : 0) + (request.implicit.empty() ? 0 : 1);
  if (given > 1) {
    throw InputError("invalid_value", "send one of implicit, x/y[/z] (parametric) or scene").in_field("scene");
  }
  RequestScene out;
  out.params.mode = request.mode;
  out.params.name = request.name;
  out.params.root_field = "scene";
  if (request.scene) {
    if (request.shape != SdfShape::automatic) {
      throw InputError("invalid_value", "a scene's implicit and parametric leaves carry their own \"shape\"")
          .in_field("shape");
    }
    if (!request.domain.empty()) {
      throw invalid_domain("a scene's parametric leaves carry their own \"domain\"", "domain");
    }
    if (request.tolerance) {
      throw InputError("invalid_tolerance", "a scene's parametric leaves carry their own \"tolerance\"")
          .in_field("tolerance");
    }
    out.params.box = parse_request_box(request.box, 3, budget);
    make_scene_frame(out.params.box);  // validates a box no leaf may read
    out.root = *request.scene;
    return out;
  }
  out.one_leaf = true;
  out.root = leaf_of(request, out.params.dimension, budget);
  out.params.box = parse_request_box(request.box, out.params.dimension, budget);
  make_scene_frame(out.params.box);
  // A box the request gives is the leaf's frame; without one a patch is fitted.
  if (!request.box.empty()) out.root.leaf.box = out.params.box;
  return out;
}

void rethrow_request_error(const InputError& e, const RequestScene& scene, const Budget& budget) {
  if (!scene.one_leaf) throw e;
  if (e.code() == "no_single_equation" && scene.root.kind == NodeKind::parametric) {
    // The leaf reports one wrong leaf of a scene, an InputError without the ideal.
    // The request's own parametrization is answered as implicitize answers it, with
    // the generators of its elimination ideal: eliminating once more, on this error
    // path only, rethrows that NoSingleEquation.
    const std::array<std::string, 3>& c = scene.root.leaf.coordinates;
    std::vector<std::string> texts{c[0], c[1]};
    if (!c[2].empty()) texts.push_back(c[2]);
    ImplicitizeParams params;
    params.budget = budget;
    (void)implicitize(parse_parametrization(texts, scene.root.leaf.parameter_names, budget), params);
    throw NoSingleEquation(e.what(), {});  // the elimination is deterministic: not reached
  }
  const std::string& field = e.field();
  if (field == "scene.equation") throw e.in_field("implicit");
  if (field == "scene") throw e.in_field(scene.root.kind == NodeKind::implicit ? "implicit" : "");
  if (field.rfind("scene.", 0) == 0) throw e.in_field(field.substr(6));
  throw e;
}

}  // namespace implicitizer
