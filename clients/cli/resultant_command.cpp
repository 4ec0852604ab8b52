#include "resultant_command.hpp"

#include <iostream>
#include <vector>

#include "arguments.hpp"
#include "buchberger_flags.hpp"
#include "error_report.hpp"
#include "help.hpp"
#include "implicitizer/codec/resultant_json.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/service/resultant_request.hpp"

namespace implicitizer::cli {
namespace {

constexpr const char* kCommand = "resultant";

// --timeout and --max-terms as for the other commands; --strategy and --criteria
// are Buchberger's and mean nothing here, so they are not accepted.
constexpr OptionSpec kOptions[] = {{"var", true},     {"json", false},     {"help", false},
                                   {"timeout", true}, {"max-terms", true}, {"max-memory", true}};

}  // namespace

int run_resultant_command(std::span<const std::string> args) {
  ResultantRequest request;
  Budget budget;
  ErrorReport report;
  try {
    const Arguments arguments = parse_arguments(args, kOptions);
    if (arguments.has("help")) {
      std::cout << kResultantHelp;
      return kExitOk;
    }
    report.json = arguments.has("json");
    const auto var = arguments.value("var");
    if (!var) throw UsageError("missing --var (the variable to eliminate)");
    request.variable = *var;
    request.polynomials = arguments.positionals();
    if (request.polynomials.size() != 2) {
      throw UsageError("a resultant needs exactly two polynomials F G, got " +
                       std::to_string(request.polynomials.size()));
    }
    request.timeout_seconds = timeout_from(arguments);
    budget = budget_from(arguments);
  } catch (const UsageError& e) {
    return report_usage_error(e.what(), kCommand);
  }
  report.field_texts["variable"] = request.variable;
  for (std::size_t i = 0; i < request.polynomials.size(); ++i) {
    report.field_texts["polynomials[" + std::to_string(i) + "]"] = request.polynomials[i];
  }

  return run_reporting_errors(report, [&] {
    const auto answer = compute_charging(budget, [&] { return answer_resultant_request(request, budget); });
    if (report.json) {
      std::cout << encode_resultant_response(answer) << '\n';
    } else {
      std::cout << to_string(answer.resultant) << '\n';
    }
  });
}

}  // namespace implicitizer::cli
