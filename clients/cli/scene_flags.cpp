#include "scene_flags.hpp"

#include <array>
#include <cstdlib>
#include <limits>

#include "choice_flag.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer::cli {
namespace {

// The number --tolerance gives; a text that is not one whole number reads as NaN, which
// the leaf refuses as `invalid_tolerance` (status 3, as a bad JSON tolerance is).
double parse_tolerance(const std::string& text) {
  char* end = nullptr;
  const double eps = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return std::numeric_limits<double>::quiet_NaN();
  return eps;
}

}  // namespace

std::vector<OptionSpec> with_scene_options(std::initializer_list<OptionSpec> own) {
  std::vector<OptionSpec> options = {{"implicit", true}, {"x", true},     {"y", true},     {"z", true},
                                     {"params", true},   {"scene", true}, {"shape", true}, {"domain", true},
                                     {"mode", true},     {"box", true},   {"name", true},  {"tolerance", true}};
  options.insert(options.end(), own);
  return options;
}

std::optional<std::string> read_scene_flags(const Arguments& arguments, bool json, SceneRequest& request) {
  const auto implicit = arguments.value("implicit");
  const auto scene = arguments.value("scene");
  const bool parametric = arguments.has("x") || arguments.has("y") || arguments.has("z");
  if ((implicit ? 1 : 0) + (scene ? 1 : 0) + (parametric ? 1 : 0) != 1) {
    throw UsageError("give exactly one of --implicit E, --x E --y E [--z E], or --scene FILE.json");
  }
  std::optional<std::string> scene_text;
  if (implicit) request.implicit = *implicit;
  if (scene) scene_text = read_text_file(*scene);
  if (parametric) {
    if (!arguments.has("x") || !arguments.has("y")) {
      throw UsageError("a parametric surface needs --x, --y and --z, a plane curve --x and --y");
    }
    // No --z: a plane curve (its z stays empty).
    request.parametric =
        std::array<std::string, 3>{*arguments.value("x"), *arguments.value("y"), arguments.value("z").value_or("")};
    if (request.parametric->at(2).empty() && arguments.has("z")) {
      throw UsageError("--z is empty; leave it out for a plane curve");
    }
    if (const auto params = arguments.value("params")) request.parameters = split_list(*params, "params");
  } else if (arguments.has("params")) {
    throw UsageError("--params goes with --x --y [--z]");
  }
  if (const auto mode = read_choice(arguments, "mode", parse_sdf_mode, json)) request.mode = *mode;
  if (const auto shape = read_choice(arguments, "shape", parse_sdf_shape, json)) request.shape = *shape;
  if (const auto domain = arguments.value("domain")) request.domain = split_list(*domain, "domain");
  if (const auto box = arguments.value("box")) request.box = split_list(*box, "box");
  if (const auto name = arguments.value("name")) request.name = *name;
  if (const auto tolerance = arguments.value("tolerance")) request.tolerance = parse_tolerance(*tolerance);
  return scene_text;
}

void note_scene_field_texts(const SceneRequest& request, const std::optional<std::string>& scene_text,
                            ErrorReport& report) {
  if (scene_text) {
    report.field_texts["scene"] = *scene_text;
  } else if (request.parametric) {
    report.field_texts["x"] = (*request.parametric)[0];
    report.field_texts["y"] = (*request.parametric)[1];
    report.field_texts["z"] = (*request.parametric)[2];
  } else {
    report.field_texts["implicit"] = request.implicit;
  }
}

}  // namespace implicitizer::cli
