#include "sdf_command.hpp"

#include <iostream>

#include "arguments.hpp"
#include "error_report.hpp"
#include "help.hpp"
#include "implicitizer/codec/json_codec.hpp"
#include "implicitizer/codec/sdf_request.hpp"

namespace implicitizer::cli {
namespace {

constexpr const char* kCommand = "sdf";

constexpr OptionSpec kOptions[] = {{"implicit", true}, {"scene", true}, {"mode", true}, {"box", true},
                                   {"name", true},     {"json", false}, {"help", false}};

}  // namespace

int run_sdf_command(std::span<const std::string> args) {
  SdfRequest request;
  ErrorReport report;
  try {
    const Arguments arguments = parse_arguments(args, kOptions);
    if (arguments.has("help")) {
      std::cout << kSdfHelp;
      return kExitOk;
    }
    report.json = arguments.has("json");
    // Unbuilt features are usage errors (exit 2), whatever else is given, as for
    // `implicitize --method interpolation`.
    if (arguments.has("scene")) throw UsageError("--scene is not built yet (use --implicit E)");
    if (const auto mode = arguments.value("mode")) {
      if (*mode != "fast" && *mode != "safe") throw UsageError("unknown --mode '" + *mode + "' (expected fast or safe)");
      request.mode = *mode;
    }
    if (!arguments.positionals().empty()) throw UsageError("unexpected argument '" + arguments.positionals()[0] + "'");
    const auto implicit = arguments.value("implicit");
    if (!implicit) throw UsageError("missing --implicit E (the surface E = 0)");
    request.implicit = *implicit;
    if (const auto box = arguments.value("box")) request.box = split_list(*box, "box");
    if (const auto name = arguments.value("name")) request.name = *name;
  } catch (const UsageError& e) {
    return report_usage_error(e.what(), kCommand);
  }
  report.field_texts["implicit"] = request.implicit;

  return run_reporting_errors(report, [&] {
    const SdfAnswer answer = answer_sdf_request(request);
    if (report.json) {
      std::cout << encode_sdf_response(answer) << '\n';
    } else {
      std::cout << answer.glsl;
    }
  });
}

}  // namespace implicitizer::cli
