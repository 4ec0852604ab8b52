#include "implicitizer/service/render_request.hpp"

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/render/png_codec.hpp"
#include "implicitizer/render/render_target.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "implicitizer/sdf/glsl_name.hpp"
#include "implicitizer/service/sdf_request.hpp"

namespace implicitizer {
namespace {

// The request's surface as a scene: an implicit leaf (a parametric surface's is its
// implicit equation, computed here so that a parametrization whose image is not a
// surface is NoSingleEquation, exit 4 / HTTP 422, as for implicitize, rather than
// the error of one leaf of a scene), or the scene.
SceneNode scene_of(const RenderRequest& request, const Budget& budget) {
  const int given = (request.scene ? 1 : 0) + (request.parametric ? 1 : 0) + (request.implicit.empty() ? 0 : 1);
  if (given > 1) {
    throw InputError("invalid_value", "send one of implicit, x/y/z (parametric) or scene").in_field("scene");
  }
  if (request.scene) return *request.scene;
  SceneNode node;
  node.kind = NodeKind::implicit;
  if (request.parametric) {
    const auto& [x, y, z] = *request.parametric;
    ImplicitizeParams options;
    options.budget = budget;
    node.leaf.equation =
        to_string(implicitize(parse_parametrization(x, y, z, request.parameters, budget), options).implicit);
    return node;
  }
  if (request.implicit.empty()) {
    throw InputError("missing_field", "give implicit, x/y/z (parametric) or scene").in_field("implicit");
  }
  node.leaf.equation = request.implicit;
  return node;
}

// Leaf errors name "scene.equation", "scene.x", …: a request without a scene names
// its own fields ("implicit", "x").
InputError in_request_field(const InputError& e, const RenderRequest& request) {
  if (request.scene) return e;
  const std::string& field = e.field();
  if (field == "scene.equation") return e.in_field("implicit");
  if (field.rfind("scene.", 0) == 0) return e.in_field(field.substr(6));
  return e;
}

}  // namespace

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
  const SceneBox box = parse_request_box(request.box, budget);
  make_scene_frame(box);  // validates a box no leaf may read
  const SceneNode root = scene_of(request, budget);
  RenderTarget target = [&] {
    try {
      return RenderTarget::compile(root, SceneParams{request.mode, box, request.name, "scene"}, request.precision,
                                   budget);
    } catch (const InputError& e) {
      throw in_request_field(e, request);
    }
  }();

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
  return {encode_png(result.image), result.stats, request.precision};
}

}  // namespace implicitizer
