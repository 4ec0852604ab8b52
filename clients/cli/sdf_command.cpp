#include "sdf_command.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "arguments.hpp"
#include "error_report.hpp"
#include "help.hpp"
#include "implicitizer/codec/scene_json.hpp"
#include "implicitizer/codec/sdf_json.hpp"
#include "implicitizer/service/sdf_request.hpp"
#include "point_list.hpp"
#include "scene_flags.hpp"

namespace implicitizer::cli {
namespace {

constexpr const char* kCommand = "sdf";

// What the flags say, before the scene file and the points are parsed (their errors
// are invalid input, status 3, as a request body's are over HTTP).
struct SdfCommand {
  SdfRequest request;
  std::optional<std::string> scene_text;  // the --scene file's contents
  std::optional<std::string> eval_path;   // the --eval file ("-": standard input)
};

// One value per line: the scene's value at each point, by CompiledScene::evaluate<float>
// (the GLSL's operations in its order, on the point rounded to float as a shader
// receives it). %.9g prints a float exactly enough to read it back.
void print_values(const CompiledScene& scene, std::istream& in, int dimension) {
  PointListReader points(in, dimension);
  while (const std::optional<std::array<double, 3>> p = points.next()) {
    const float value = scene.evaluate<float>(
        Vec3<float>{static_cast<float>((*p)[0]), static_cast<float>((*p)[1]), static_cast<float>((*p)[2])});
    std::printf("%.9g\n", static_cast<double>(value));
  }
}

// Reads the whole point file once, keeping nothing, so that a malformed line is
// reported before any value is printed.
void check_points(std::istream& in, int dimension) {
  PointListReader points(in, dimension);
  while (points.next()) {
  }
}

}  // namespace

int run_sdf_command(std::span<const std::string> args) {
  SdfCommand command;
  ErrorReport report;
  try {
    const Arguments arguments =
        parse_arguments(args, with_scene_options({{"eval", true}, {"json", false}, {"help", false}}));
    if (arguments.has("help")) {
      std::cout << kSdfHelp;
      return kExitOk;
    }
    report.json = arguments.has("json");
    if (!arguments.positionals().empty()) throw UsageError("unexpected argument '" + arguments.positionals()[0] + "'");
    command.scene_text = read_scene_flags(arguments, report.json, command.request);
    if (const auto eval = arguments.value("eval")) {
      if (*eval != "-") open_point_file(*eval);  // unreadable: a usage error, before any work
      command.eval_path = *eval;
    }
  } catch (const UsageError& e) {
    return report_usage_error(e.what(), kCommand);
  }
  note_scene_field_texts(command.request, command.scene_text, report);

  return run_reporting_errors(report, [&] {
    SdfRequest& request = command.request;
    // The file's JSON errors are input errors (exit 3) with their byte offset.
    if (command.scene_text) request.scene = parse_scene_json(*command.scene_text, "scene");
    const CompiledSdfRequest compiled = compile_sdf_request(request);
    const SdfAnswer answer = describe_sdf_request(compiled);
    // A regular file is read twice, first to check it, so that a malformed line leaves
    // stdout empty; standard input or a pipe is read once, its values printed as its
    // lines arrive (a malformed line then ends the output after the values before it).
    std::ifstream file;
    if (command.eval_path && *command.eval_path != "-") {
      file = open_point_file(*command.eval_path);
      std::error_code ignored;
      if (std::filesystem::is_regular_file(*command.eval_path, ignored)) {
        check_points(file, answer.dimension);
        file.clear();
        file.seekg(0);
        if (!file) throw UsageError("cannot read point file '" + *command.eval_path + "' again");
      }
    }
    if (report.json) {
      std::cout << encode_sdf_response(answer) << '\n';
    } else if (!command.eval_path) {
      std::cout << answer.glsl;
    }
    std::cout.flush();
    if (command.eval_path) print_values(compiled.scene, file.is_open() ? file : std::cin, answer.dimension);
  });
}

}  // namespace implicitizer::cli
