#include "implicitizer/service/render_request.hpp"

#include "implicitizer/core/errors.hpp"
#include "implicitizer/render/png_codec.hpp"
#include "implicitizer/render/render_target.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/sdf/glsl_name.hpp"

namespace implicitizer {

EvaluationPrecision parse_evaluation_precision(const std::string& name) {
  if (name == "float") return EvaluationPrecision::single;
  if (name == "double") return EvaluationPrecision::double_run;
  throw InputError("invalid_value", "precision must be float or double").in_field("precision");
}

const char* to_string(EvaluationPrecision precision) {
  return precision == EvaluationPrecision::double_run ? "double" : "float";
}

RenderFormat parse_render_format(const std::string& name) {
  if (name == "png") return RenderFormat::png;
  if (name == "json") return RenderFormat::json;
  throw InputError("invalid_value", "format must be png or json").in_field("format");
}

void check_render_size(const RenderRequest& request, const RenderRequestParams& limits) {
  for (const auto& [field, value] : {std::pair{"width", request.width}, std::pair{"height", request.height}}) {
    if (value == 0 || value > limits.max_side) {
      throw InputError("invalid_size", std::string(field) + " must be 1 to " + std::to_string(limits.max_side))
          .in_field(field);
    }
  }
  if (request.antialiasing == 0 || request.antialiasing > 8) {
    throw InputError("invalid_value", "aa must be 1 to 8 (AA×AA samples per pixel)").in_field("aa");
  }
  const std::uint64_t rays =
      static_cast<std::uint64_t>(request.width) * request.height * request.antialiasing * request.antialiasing;
  if (rays > limits.max_rays) {
    throw InputError("render_too_large", "width·height·aa² = " + std::to_string(rays) + " rays; at most " +
                                             std::to_string(limits.max_rays) + " are rendered")
        .in_field("width");
  }
}

RenderAnswer answer_render_request(const RenderRequest& request, const Budget& caller_budget,
                                   const RenderRequestParams& limits, std::size_t threads) {
  Budget budget = caller_budget;
  if (request.timeout_seconds) budget.set_timeout(*request.timeout_seconds);
  check_render_size(request, limits);
  check_glsl_name(request.name);
  const RequestScene source = make_request_scene(request, budget);
  const RenderTarget target = compile_request_scene(
      source, budget, [&] { return RenderTarget::compile(source.root, source.params, request.precision, budget); });

  RenderParams settings;
  settings.width = request.width;
  settings.height = request.height;
  settings.antialiasing = request.antialiasing;
  settings.method = request.method;
  settings.threads = threads;
  settings.camera = default_camera(target);
  if (request.eye) settings.camera.eye = *request.eye;
  if (request.target) settings.camera.target = *request.target;
  settings.march = default_render_march_params(target, settings.camera);
  const RenderResult result = render_image(target, settings, budget);
  RenderAnswer answer;
  answer.png = encode_png(result.image);
  answer.stats = result.stats;
  answer.precision = request.precision;
  answer.dimension = target.scene().dimension();
  const CompiledScene& scene = target.scene();
  if (scene.leaves().size() == 1 && scene.node_count() == 1) {
    answer.shape = scene.leaves()[0].shape();
    if (source.one_leaf && scene.leaves()[0].tolerance()) {
      answer.approximation = summarize_approximation(scene.leaves()[0], count_lines(scene.to_glsl()));
    }
  }
  return answer;
}

}  // namespace implicitizer
