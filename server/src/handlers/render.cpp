#include "handlers/render.hpp"

#include <cstdio>

#include "implicitizer/codec/render_json.hpp"
#include "implicitizer/service/render_request.hpp"

namespace implicitizer::server {
namespace {

std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

// A bound and how it was established: "2.5e-05 certified", "4.1e-04 measured 1200"
// (the sample size of a measured bound).
std::string format_bound(double bound, BoundMethod method, std::size_t samples) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g %s", bound, to_string(method).c_str());
  std::string out = text;
  if (method == BoundMethod::measured) out += " " + std::to_string(samples);
  return out;
}

// The approximation's report (an input with a tolerance), as the JSON's members.
void set_approximation_headers(Response& response, const ApproximationSummary& a) {
  char tolerance[32];
  std::snprintf(tolerance, sizeof tolerance, "%.17g", a.tolerance);
  response.set("X-Render-Tolerance", tolerance);
  response.set("X-Render-Approximation-Exact", a.kept_exact.empty() ? "false" : "true");
  response.set("X-Render-Degree", std::to_string(a.degree));
  response.set("X-Render-Pieces", std::to_string(a.pieces));
  response.set("X-Render-Glsl-Lines", std::to_string(a.glsl_lines));
  response.set("X-Render-Patch-To-Surface", format_bound(a.patch_to_surface, a.patch_to_surface_method, 0));
  response.set("X-Render-Surface-To-Patch",
               format_bound(a.surface_to_patch, a.surface_to_patch_method, a.surface_to_patch_samples));
}

Response make_png_response(const RenderAnswer& answer) {
  const RenderStats& s = answer.stats;
  Response response = make_response(http::status::ok, answer.png, "image/png");
  response.set("X-Render-Width", std::to_string(s.width));
  response.set("X-Render-Height", std::to_string(s.height));
  response.set("X-Render-Method", to_string(s.method));
  response.set("X-Render-Mode", to_string(s.mode));
  response.set("X-Render-Precision", to_string(answer.precision));
  response.set("X-Render-Rays", std::to_string(s.rays));
  response.set("X-Render-Hits", std::to_string(s.hits));
  response.set("X-Render-Out-Of-Steps", std::to_string(s.out_of_steps));
  response.set("X-Render-Mean-Evaluations", format_number(s.mean_evaluations()));
  response.set("X-Render-Max-Evaluations", std::to_string(s.max_evaluations));
  response.set("X-Render-Elapsed-Ms", format_number(s.elapsed_ms));
  if (answer.shape) response.set("X-Render-Shape", to_string(*answer.shape));
  response.set("X-Render-Dimension", std::to_string(answer.dimension));
  if (answer.approximation) set_approximation_headers(response, *answer.approximation);
  return response;
}

}  // namespace

HandlerResult handle_render(const Request& request, const HandlerContext& context) {
  // The size is checked before anything is queued: a render too large is 413 at once.
  const auto decode_and_check = [](std::string_view body, const JsonParams& limits) {
    RenderRequest decoded = decode_render_request(body, limits);
    check_render_size(decoded);
    return decoded;
  };
  return handle_decoded(request, context, decode_and_check, [&](RenderRequest decoded) -> HandlerResult {
    Computation computation;
    computation.budget = make_computation_budget(decoded.timeout_seconds, context.config);
    decoded.timeout_seconds.reset();  // the budget's deadline already counts from now
    computation.run = [decoded = std::move(decoded), budget = computation.budget]() {
      const RenderAnswer answer = answer_render_request(decoded, budget, RenderRequestParams{}, 1);
      if (decoded.format == RenderFormat::json) {
        return make_json_response(http::status::ok, encode_render_response(answer, true));
      }
      return make_png_response(answer);
    };
    return computation;
  });
}

}  // namespace implicitizer::server
