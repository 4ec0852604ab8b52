#include "render_command.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "arguments.hpp"
#include "choice_flag.hpp"
#include "error_report.hpp"
#include "help.hpp"
#include "implicitizer/codec/render_json.hpp"
#include "implicitizer/codec/scene_json.hpp"
#include "implicitizer/service/render_request.hpp"
#include "scene_flags.hpp"

namespace implicitizer::cli {
namespace {

constexpr const char* kCommand = "render";

// "256x192" → (256, 192).
std::pair<std::size_t, std::size_t> parse_size(const std::string& text) {
  const auto x = text.find('x');
  if (x == std::string::npos) throw UsageError("--size must be WIDTHxHEIGHT, e.g. 256x256, not '" + text + "'");
  return {parse_count(text.substr(0, x), "size"), parse_count(text.substr(x + 1), "size")};
}

// "3,3,5" → three finite numbers.
std::array<double, 3> parse_point(const std::string& text, const char* flag) {
  const std::vector<std::string> items = split_list(text, flag);
  if (items.size() != 3) throw UsageError(std::string("--") + flag + " must be three numbers x,y,z");
  std::array<double, 3> p{};
  for (std::size_t i = 0; i < 3; ++i) {
    char* end = nullptr;
    errno = 0;
    p[i] = std::strtod(items[i].c_str(), &end);
    if (end == items[i].c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(p[i])) {
      throw UsageError(std::string("--") + flag + ": '" + items[i] + "' is not a finite number");
    }
  }
  return p;
}

// What the flags say, before the scene file and --method are parsed (their errors
// are invalid input, status 3, as over HTTP, not usage errors).
struct RenderCommand {
  RenderRequest request;
  std::optional<std::string> scene_text;   // the --scene file's contents
  std::optional<std::string> method_text;  // --method
  std::string output;
  std::size_t threads = 0;
};

// Everything but the surface: how to draw it and where to write it.
void read_drawing_flags(const Arguments& arguments, bool json, RenderCommand& command) {
  RenderRequest& request = command.request;
  command.method_text = arguments.value("method");
  if (const auto size = arguments.value("size")) std::tie(request.width, request.height) = parse_size(*size);
  if (const auto aa = arguments.value("aa")) {
    const std::size_t n = parse_count(*aa, "aa");
    if (n < 1 || n > 8) throw UsageError("--aa must be 1 to 8");
    request.antialiasing = static_cast<std::uint32_t>(n);
  }
  if (const auto eye = arguments.value("eye")) request.eye = parse_point(*eye, "eye");
  if (const auto target = arguments.value("target")) request.target = parse_point(*target, "target");
  if (const auto precision = read_choice(arguments, "precision", parse_evaluation_precision, json)) {
    request.precision = *precision;
  }
  if (const auto t = arguments.value("threads")) command.threads = parse_count(*t, "threads");
  if (const auto timeout = arguments.value("timeout")) request.timeout_seconds = parse_seconds(*timeout, "timeout");
  const auto out = arguments.value("output");
  if (!out) throw UsageError("missing -o FILE.png (where to write the image)");
  command.output = *out;
}

// Renders, writes the PNG and reports; returns kExitUsage when the file cannot be written.
int render_and_write(RenderCommand& command, bool json) {
  RenderRequest& request = command.request;
  if (command.scene_text) request.scene = parse_scene_json(*command.scene_text, "scene");
  if (command.method_text) request.method = parse_march_method(*command.method_text);
  const RenderAnswer answer = answer_render_request(request, Budget(), RenderRequestParams{}, command.threads);
  std::ofstream file(command.output, std::ios::binary | std::ios::trunc);
  file.write(answer.png.data(), static_cast<std::streamsize>(answer.png.size()));
  file.close();
  if (!file) {
    std::cerr << "error: cannot write '" << command.output << "'\n";
    return kExitUsage;
  }
  if (json) {
    std::cout << encode_render_response(answer, false) << '\n';
  } else {
    std::cerr << "wrote " << command.output << " (" << answer.stats.width << "x" << answer.stats.height << ", "
              << answer.stats.hits << " of " << answer.stats.rays << " rays hit, " << answer.stats.mean_evaluations()
              << " evaluations per ray, " << answer.stats.elapsed_ms << " ms)\n";
  }
  return kExitOk;
}

}  // namespace

int run_render_command(std::span<const std::string> args) {
  RenderCommand command;
  ErrorReport report;
  try {
    // `-o FILE` is the contract's spelling; the parser only knows `--` options.
    std::vector<std::string> words(args.begin(), args.end());
    for (std::string& w : words) {
      if (w == "-o") w = "--output";
    }
    const Arguments arguments = parse_arguments(words, with_scene_options({{"method", true},
                                                                           {"size", true},
                                                                           {"aa", true},
                                                                           {"eye", true},
                                                                           {"target", true},
                                                                           {"precision", true},
                                                                           {"threads", true},
                                                                           {"timeout", true},
                                                                           {"output", true},
                                                                           {"json", false},
                                                                           {"help", false}}));
    if (arguments.has("help")) {
      std::cout << kRenderHelp;
      return kExitOk;
    }
    report.json = arguments.has("json");
    if (!arguments.positionals().empty()) throw UsageError("unexpected argument '" + arguments.positionals()[0] + "'");
    command.scene_text = read_scene_flags(arguments, report.json, command.request);
    read_drawing_flags(arguments, report.json, command);
  } catch (const UsageError& e) {
    return report_usage_error(e.what(), kCommand);
  }
  note_scene_field_texts(command.request, command.scene_text, report);

  int status = kExitOk;
  const int answered = run_reporting_errors(report, [&] { status = render_and_write(command, report.json); });
  return answered != kExitOk ? answered : status;
}

}  // namespace implicitizer::cli
