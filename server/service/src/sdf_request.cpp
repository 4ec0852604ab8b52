#include "implicitizer/service/sdf_request.hpp"

#include <algorithm>
#include <cmath>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/sdf/glsl_name.hpp"

namespace implicitizer {
namespace {

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

CompiledSdfRequest compile_sdf_request(const SdfRequest& request, const Budget& caller_budget) {
  Budget budget = caller_budget;
  if (request.timeout_seconds) budget.set_timeout(*request.timeout_seconds);
  check_glsl_name(request.name);
  RequestScene source = make_request_scene(request, budget);
  CompiledScene scene =
      compile_request_scene(source, budget, [&] { return compile_scene(source.root, source.params, budget); });
  return {std::move(source), std::move(scene)};
}

SdfAnswer describe_sdf_request(const CompiledSdfRequest& compiled) {
  const CompiledScene& scene = compiled.scene;
  const RequestScene& source = compiled.source;
  SdfAnswer answer;
  answer.glsl = scene.to_glsl();
  answer.function = scene.function_name();
  answer.mode = scene.mode();
  answer.dimension = scene.dimension();
  answer.uniforms = scene.uniforms();
  // The box actually used: an input's leaf frame (fitted to a patch when no box was
  // given), a scene's box.
  const bool one_leaf = scene.leaves().size() == 1 && scene.node_count() == 1;
  const SceneBox& box = one_leaf ? scene.leaves()[0].frame_box() : source.params.box;
  for (std::size_t i = 0; i < 3; ++i) {
    answer.box[i] = nearest_double(box.lo[i]);
    answer.box[i + 3] = nearest_double(box.hi[i]);
  }
  if (one_leaf) answer.shape = scene.leaves()[0].shape();
  const std::size_t lines = count_lines(answer.glsl);
  for (const PolynomialLeaf& leaf : scene.leaves()) {
    // An approximation's degree is its largest piece's (equation() is its first piece).
    const std::optional<ApproximationSummary> approximation = summarize_approximation(leaf, lines);
    const std::int32_t degree = approximation ? approximation->degree : leaf.equation().total_degree();
    answer.degree = std::max(answer.degree, degree);
    std::optional<TrimmingSummary> trimming;
    if (leaf.trimmed()) trimming = leaf.trimming();
    if (!source.one_leaf) {
      answer.leaves.push_back(
          {to_string(leaf.equation()), degree, leaf.trimmed(), leaf.shape(), trimming, approximation});
    } else {
      answer.approximation = approximation;
      answer.trimming = trimming;
      if (const SheetSide* side = leaf.sheet_side()) {
        answer.side_function = source.params.name + "_side";
        answer.side_glsl = side->to_glsl(answer.side_function);
      }
    }
  }
  if (!source.one_leaf) answer.nodes = scene.node_count();
  return answer;
}

SdfAnswer answer_sdf_request(const SdfRequest& request, const Budget& budget) {
  return describe_sdf_request(compile_sdf_request(request, budget));
}

}  // namespace implicitizer
