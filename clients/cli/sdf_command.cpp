#include "sdf_command.hpp"

#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "arguments.hpp"
#include "choice_flag.hpp"
#include "error_report.hpp"
#include "help.hpp"
#include "implicitizer/codec/scene_json.hpp"
#include "implicitizer/codec/sdf_json.hpp"
#include "implicitizer/service/sdf_request.hpp"

namespace implicitizer::cli {
namespace {

constexpr const char* kCommand = "sdf";

constexpr OptionSpec kOptions[] = {{"implicit", true}, {"scene", true}, {"mode", true}, {"box", true},
                                   {"name", true},     {"json", false}, {"help", false}};

}  // namespace

int run_sdf_command(std::span<const std::string> args) {
  SdfRequest request;
  std::optional<std::string> scene_text;  // the --scene file's contents
  ErrorReport report;
  try {
    const Arguments arguments = parse_arguments(args, kOptions);
    if (arguments.has("help")) {
      std::cout << kSdfHelp;
      return kExitOk;
    }
    report.json = arguments.has("json");
    if (const auto mode = read_choice(arguments, "mode", parse_sdf_mode, report.json)) request.mode = *mode;
    if (!arguments.positionals().empty()) throw UsageError("unexpected argument '" + arguments.positionals()[0] + "'");
    const auto implicit = arguments.value("implicit");
    const auto scene = arguments.value("scene");
    if (implicit && scene) throw UsageError("give --implicit E or --scene FILE.json, not both");
    if (!implicit && !scene) throw UsageError("missing --implicit E (the surface E = 0) or --scene FILE.json");
    if (implicit) request.implicit = *implicit;
    if (scene) scene_text = read_text_file(*scene);
    if (const auto box = arguments.value("box")) request.box = split_list(*box, "box");
    if (const auto name = arguments.value("name")) request.name = *name;
  } catch (const UsageError& e) {
    return report_usage_error(e.what(), kCommand);
  }
  if (scene_text) {
    report.field_texts["scene"] = *scene_text;
  } else {
    report.field_texts["implicit"] = request.implicit;
  }

  return run_reporting_errors(report, [&] {
    // The file's JSON errors are input errors (exit 3) with their byte offset.
    if (scene_text) request.scene = parse_scene_json(*scene_text, "scene");
    const SdfAnswer answer = answer_sdf_request(request);
    if (report.json) {
      std::cout << encode_sdf_response(answer) << '\n';
    } else {
      std::cout << answer.glsl;
    }
  });
}

}  // namespace implicitizer::cli
