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
#include "error_report.hpp"
#include "help.hpp"
#include "implicitizer/codec/json_codec.hpp"
#include "implicitizer/codec/render_request.hpp"
#include "implicitizer/codec/scene_json.hpp"

namespace implicitizer::cli {
namespace {

constexpr const char* kCommand = "render";

constexpr OptionSpec kOptions[] = {{"implicit", true}, {"x", true},         {"y", true},       {"z", true},
                                   {"params", true},   {"scene", true},     {"method", true},  {"mode", true},
                                   {"size", true},     {"aa", true},        {"eye", true},     {"target", true},
                                   {"box", true},      {"precision", true}, {"threads", true}, {"timeout", true},
                                   {"output", true},   {"json", false},     {"help", false}};

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

}  // namespace

int run_render_command(std::span<const std::string> args) {
  RenderRequest request;
  std::optional<std::string> scene_text;  // the --scene file's contents
  std::string output;
  std::size_t threads = 0;
  ErrorReport report;
  try {
    // `-o FILE` is the contract's spelling; the parser only knows `--` options.
    std::vector<std::string> words(args.begin(), args.end());
    for (std::string& w : words) {
      if (w == "-o") w = "--output";
    }
    const Arguments arguments = parse_arguments(words, kOptions);
    if (arguments.has("help")) {
      std::cout << kRenderHelp;
      return kExitOk;
    }
    report.json = arguments.has("json");
    if (!arguments.positionals().empty()) throw UsageError("unexpected argument '" + arguments.positionals()[0] + "'");
    const auto implicit = arguments.value("implicit");
    const auto scene = arguments.value("scene");
    const bool parametric = arguments.has("x") || arguments.has("y") || arguments.has("z");
    if ((implicit ? 1 : 0) + (scene ? 1 : 0) + (parametric ? 1 : 0) != 1) {
      throw UsageError("give exactly one of --implicit E, --x E --y E --z E, or --scene FILE.json");
    }
    if (implicit) request.implicit = *implicit;
    if (scene) scene_text = read_text_file(*scene);
    if (parametric) {
      if (!arguments.has("x") || !arguments.has("y") || !arguments.has("z")) {
        throw UsageError("a parametric surface needs --x, --y and --z");
      }
      request.parametric =
          std::array<std::string, 3>{*arguments.value("x"), *arguments.value("y"), *arguments.value("z")};
      if (const auto params = arguments.value("params")) request.parameters = split_list(*params, "params");
    } else if (arguments.has("params")) {
      throw UsageError("--params goes with --x --y --z");
    }
    if (const auto method = arguments.value("method")) request.method = *method;
    if (const auto mode = arguments.value("mode")) {
      if (*mode != "fast" && *mode != "safe")
        throw UsageError("unknown --mode '" + *mode + "' (expected fast or safe)");
      request.mode = *mode;
    }
    if (const auto size = arguments.value("size")) std::tie(request.width, request.height) = parse_size(*size);
    if (const auto aa = arguments.value("aa")) {
      const std::size_t n = parse_count(*aa, "aa");
      if (n < 1 || n > 8) throw UsageError("--aa must be 1 to 8");
      request.antialiasing = static_cast<std::uint32_t>(n);
    }
    if (const auto eye = arguments.value("eye")) request.eye = parse_point(*eye, "eye");
    if (const auto target = arguments.value("target")) request.target = parse_point(*target, "target");
    if (const auto box = arguments.value("box")) request.box = split_list(*box, "box");
    if (const auto precision = arguments.value("precision")) {
      if (*precision != "float" && *precision != "double") {
        throw UsageError("unknown --precision '" + *precision + "' (expected float or double)");
      }
      request.precision = *precision;
    }
    if (const auto t = arguments.value("threads")) threads = parse_count(*t, "threads");
    if (const auto timeout = arguments.value("timeout")) request.timeout_seconds = parse_seconds(*timeout, "timeout");
    const auto out = arguments.value("output");
    if (!out) throw UsageError("missing -o FILE.png (where to write the image)");
    output = *out;
  } catch (const UsageError& e) {
    return report_usage_error(e.what(), kCommand);
  }
  if (scene_text) {
    report.field_texts["scene"] = *scene_text;
  } else if (request.parametric) {
    report.field_texts["x"] = (*request.parametric)[0];
    report.field_texts["y"] = (*request.parametric)[1];
    report.field_texts["z"] = (*request.parametric)[2];
  } else {
    report.field_texts["implicit"] = request.implicit;
  }

  int status = kExitOk;
  const int answered = run_reporting_errors(report, [&] {
    if (scene_text) request.scene = parse_scene_json(*scene_text, "scene");
    const RenderAnswer answer = answer_render_request(request, Budget(), RenderRequestParams{}, threads);
    std::ofstream file(output, std::ios::binary | std::ios::trunc);
    file.write(answer.png.data(), static_cast<std::streamsize>(answer.png.size()));
    file.close();
    if (!file) {
      std::cerr << "error: cannot write '" << output << "'\n";
      status = kExitUsage;
      return;
    }
    if (report.json) {
      std::cout << encode_render_response(answer, false) << '\n';
    } else {
      std::cerr << "wrote " << output << " (" << answer.stats.width << "x" << answer.stats.height << ", "
                << answer.stats.hits << " of " << answer.stats.rays << " rays hit, " << answer.stats.mean_evaluations()
                << " evaluations per ray, " << answer.stats.elapsed_ms << " ms)\n";
    }
  });
  return answered != kExitOk ? answered : status;
}

}  // namespace implicitizer::cli
