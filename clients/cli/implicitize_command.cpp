#include "implicitize_command.hpp"

#include <iostream>
#include <iterator>
#include <vector>

#include "arguments.hpp"
#include "buchberger_flags.hpp"
#include "choice_flag.hpp"
#include "error_report.hpp"
#include "help.hpp"
#include "implicitizer/codec/implicitize_json.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/service/implicitize_request.hpp"

namespace implicitizer::cli {
namespace {

constexpr const char* kCommand = "implicitize";

std::vector<OptionSpec> option_specs() {
  std::vector<OptionSpec> spec = {{"x", true},      {"y", true},        {"z", true},     {"params", true},
                                  {"method", true}, {"modular", false}, {"json", false}, {"help", false}};
  spec.insert(spec.end(), std::begin(kBuchbergerOptions), std::end(kBuchbergerOptions));
  return spec;
}

// Stdout keeps the one line of the contract; what was implicitized instead of the
// input, when functions were made rational, goes to stderr.
void print_substitution(const ImplicitizeAnswer& answer) {
  if (answer.substitutions.empty()) return;
  std::cerr << "made rational by";
  for (std::size_t i = 0; i < answer.substitutions.size(); ++i) {
    std::cerr << (i ? ", " : " ") << to_string(answer.substitutions[i]);
  }
  std::cerr << '\n';
  const std::vector<std::string> names = coordinate_names(answer.rational_coordinates.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::cerr << "  " << names[i] << " = " << answer.rational_coordinates[i] << '\n';
  }
}

}  // namespace

int run_implicitize_command(std::span<const std::string> args) {
  ImplicitizeRequest request;
  Budget budget;
  BuchbergerVariant variant;
  ErrorReport report;
  try {
    const std::vector<OptionSpec> spec = option_specs();
    const Arguments arguments = parse_arguments(args, spec);
    if (arguments.has("help")) {
      std::cout << kImplicitizeHelp;
      return kExitOk;
    }
    if (!arguments.positionals().empty()) {
      throw UsageError("unexpected argument '" + arguments.positionals().front() + "'");
    }
    report.json = arguments.has("json");
    // --z is optional: without it the parametrization is a plane curve.
    for (const char* coordinate : {"x", "y"}) {
      if (!arguments.has(coordinate)) throw UsageError(std::string("missing --") + coordinate);
    }
    request.x = *arguments.value("x");
    request.y = *arguments.value("y");
    request.z = arguments.value("z");
    if (const auto params_text = arguments.value("params")) {
      request.parameters = split_list(*params_text, "params");
      report.field_texts["parameters"] = *params_text;
    }
    // The method is checked before anything is computed: an unknown method is a
    // usage error (status 2), whatever the expressions are.
    if (const auto method = read_choice(arguments, "method", parse_implicitization_method, report.json)) {
      request.method = *method;
    }
    request.modular = arguments.has("modular");
    request.timeout_seconds = timeout_from(arguments);
    variant = buchberger_variant_from(arguments);
    budget = budget_from(arguments);
  } catch (const UsageError& e) {
    return report_usage_error(e.what(), kCommand);
  }
  report.field_texts["x"] = request.x;
  report.field_texts["y"] = request.y;
  if (request.z) report.field_texts["z"] = *request.z;

  return run_reporting_errors(report, [&] {
    const auto answer = compute_charging(budget, [&] { return answer_implicitize_request(request, budget, variant); });
    if (report.json) {
      std::cout << encode_implicitize_response(answer) << '\n';
    } else {
      std::cout << to_string(answer.result.implicit) << '\n';
      print_substitution(answer);
    }
  });
}

}  // namespace implicitizer::cli
