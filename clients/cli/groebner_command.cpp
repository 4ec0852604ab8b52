#include "groebner_command.hpp"

#include <iostream>
#include <iterator>
#include <vector>

#include "arguments.hpp"
#include "buchberger_flags.hpp"
#include "choice_flag.hpp"
#include "error_report.hpp"
#include "help.hpp"
#include "implicitizer/codec/groebner_json.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/service/groebner_request.hpp"

namespace implicitizer::cli {
namespace {

constexpr const char* kCommand = "groebner";

std::vector<OptionSpec> option_specs() {
  std::vector<OptionSpec> spec = {{"vars", true},      {"order", true},  {"weights", true},
                                  {"eliminate", true}, {"method", true}, {"modular", false},
                                  {"proof", true},     {"json", false},  {"help", false}};
  spec.insert(spec.end(), std::begin(kBuchbergerOptions), std::end(kBuchbergerOptions));
  return spec;
}

// One polynomial per line; the zero ideal (empty basis) prints `0`, which generates it.
void print_polynomials(const std::vector<Polynomial>& polynomials) {
  if (polynomials.empty()) std::cout << "0\n";
  for (const Polynomial& p : polynomials) std::cout << to_string(p) << '\n';
}

}  // namespace

int run_groebner_command(std::span<const std::string> args) {
  GroebnerRequest request;
  Budget budget;
  BuchbergerVariant variant;
  ErrorReport report;
  try {
    const std::vector<OptionSpec> spec = option_specs();
    const Arguments arguments = parse_arguments(args, spec);
    if (arguments.has("help")) {
      std::cout << kGroebnerHelp;
      return kExitOk;
    }
    report.json = arguments.has("json");
    request.polynomials = arguments.positionals();
    if (request.polynomials.empty()) throw UsageError("no polynomials given");
    if (const auto vars = arguments.value("vars")) request.variables = split_list(*vars, "vars");
    if (const auto order = read_choice(arguments, "order", &MonomialOrder::from_name, report.json)) {
      request.order = *order;
    }
    if (const auto weights = arguments.value("weights")) {
      std::vector<int> w;
      for (const std::string& item : split_list(*weights, "weights")) w.push_back(parse_int(item, "weights"));
      request.weights = std::move(w);
    }
    if (const auto eliminate = arguments.value("eliminate")) request.eliminate = split_list(*eliminate, "eliminate");
    const auto method = read_choice(arguments, "method", parse_groebner_method, report.json);
    if (method) request.method = *method;
    if (arguments.has("modular")) {
      if (method && *method != GroebnerMethod::modular) {
        throw UsageError(std::string("--modular contradicts --method ") + to_string(*method));
      }
      request.method = GroebnerMethod::modular;
    }
    if (const auto proof = read_choice(arguments, "proof", parse_groebner_proof, report.json)) request.proof = *proof;
    request.timeout_seconds = timeout_from(arguments);
    variant = buchberger_variant_from(arguments);
    budget = budget_from(arguments);
  } catch (const UsageError& e) {
    return report_usage_error(e.what(), kCommand);
  }
  for (std::size_t i = 0; i < request.polynomials.size(); ++i) {
    report.field_texts["polynomials[" + std::to_string(i) + "]"] = request.polynomials[i];
  }

  return run_reporting_errors(report, [&] {
    const auto answer = compute_charging(budget, [&] { return answer_groebner_request(request, budget, variant); });
    if (report.json) {
      std::cout << encode_groebner_response(answer) << '\n';
    } else {
      print_polynomials(answer.elimination_ideal ? *answer.elimination_ideal : answer.basis);
      if (!answer.route.proven()) {
        std::cerr << "note: not proven; the basis agrees with the reduced bases modulo "
                  << answer.route.modular->random_primes.size() << " random primes (docs/algorithms.md)\n";
      }
    }
  });
}

}  // namespace implicitizer::cli
