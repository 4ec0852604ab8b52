#include "implicitizer/service/sdf_request.hpp"

#include <algorithm>
#include <cmath>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/sdf/glsl_name.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"

namespace implicitizer {
namespace {

InputError invalid_box(const std::string& message) { return InputError("invalid_box", message).in_field("box"); }

// One box coordinate: an exact constant expression.
Rational parse_box_number(const std::string& text, const RingPtr& ring, const Budget& budget) {
  Polynomial c(ring);
  try {
    c = parse_polynomial(text, ring, budget);
  } catch (const InputError&) {
    throw invalid_box("'" + text + "' is not a number");
  }
  if (!c.is_constant()) throw invalid_box("'" + text + "' is not a number");
  return c.is_zero() ? Rational(0) : c.coefficient(0);
}

// The double nearest to q: GMP's mpq_get_d truncates toward zero, which would turn
// a box side of 1e-6 (read from JSON as a double) into the next double below it.
double nearest_double(const Rational& q) {
  const mpq_class exact = to_mpq(q);
  const double truncated = exact.get_d();
  const double away = std::nextafter(truncated, exact > 0 ? HUGE_VAL : -HUGE_VAL);
  if (!std::isfinite(away)) return truncated;
  const mpq_class a = abs(exact - mpq_class(truncated));
  const mpq_class b = abs(exact - mpq_class(away));
  return b < a ? away : truncated;
}

}  // namespace

const char* to_string(SdfMode mode) { return mode == SdfMode::safe ? "safe" : "fast"; }

SceneBox parse_request_box(const std::vector<std::string>& numbers, const Budget& budget) {
  SceneBox box = SceneBox::default_box();
  if (numbers.empty()) return box;
  if (numbers.size() != 6) throw invalid_box("a box is six numbers x0,y0,z0,x1,y1,z1");
  const RingPtr ring = Ring::make({"x", "y", "z"});
  for (std::size_t i = 0; i < 3; ++i) {
    box.lo[i] = parse_box_number(numbers[i], ring, budget);
    box.hi[i] = parse_box_number(numbers[i + 3], ring, budget);
  }
  return box;
}

SdfAnswer answer_sdf_request(const SdfRequest& request, const Budget& caller_budget) {
  Budget budget = caller_budget;
  if (request.timeout_seconds) budget.set_timeout(*request.timeout_seconds);
  const SdfMode mode = request.mode;
  check_glsl_name(request.name);
  const RingPtr ring = Ring::make({"x", "y", "z"});
  const SceneBox box = parse_request_box(request.box, budget);
  SdfAnswer answer;
  answer.function = request.name + "_sdf";
  answer.mode = mode;
  for (std::size_t i = 0; i < 3; ++i) {
    answer.box[i] = nearest_double(box.lo[i]);
    answer.box[i + 3] = nearest_double(box.hi[i]);
  }
  if (request.scene) {
    make_scene_frame(box);  // validates a box no leaf may read
    const CompiledScene scene = compile_scene(*request.scene, SceneParams{mode, box, request.name, "scene"}, budget);
    answer.glsl = scene.to_glsl();
    answer.nodes = scene.node_count();
    answer.uniforms = scene.uniforms();
    for (const PolynomialLeaf& leaf : scene.leaves()) {
      answer.leaves.push_back({to_string(leaf.equation()), leaf.equation().total_degree(), leaf.trimmed()});
      answer.degree = std::max(answer.degree, leaf.equation().total_degree());
    }
    return answer;
  }
  Polynomial f(ring);
  try {
    f = parse_polynomial(request.implicit, ring, budget);
  } catch (const InputError& e) {
    throw e.in_field("implicit");
  }
  try {
    answer.glsl = mode == SdfMode::safe ? SafeSdf::build(f, box, budget).to_glsl(answer.function)
                                        : FastSdf::build(f, box, budget).to_glsl(answer.function);
  } catch (const InputError& e) {
    throw e.code() == "constant_polynomial" || e.code() == "degree_too_high" ? e.in_field("implicit") : e;
  }
  answer.degree = f.total_degree();
  return answer;
}

}  // namespace implicitizer
