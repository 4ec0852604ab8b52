#include "error_report.hpp"

#include <exception>
#include <iostream>
#include <new>

#include "arguments.hpp"
#include "implicitizer/codec/error_json.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer::cli {
namespace {

// `  x = s+t$` and a caret under the error, when the text is one line.
void print_caret(const std::string& field, const std::string& text, std::size_t position) {
  if (text.find('\n') != std::string::npos || position > text.size()) return;
  const std::string prefix = "  " + field + " = ";
  std::cerr << prefix << text << '\n' << std::string(prefix.size() + position, ' ') << "^\n";
}

void report_input_error(const ErrorReport& report, const InputError& e) {
  if (report.json) std::cout << encode_error(e) << '\n';
  std::cerr << "error: " << e.code();
  if (e.position()) std::cerr << " at position " << *e.position();
  if (!e.field().empty()) std::cerr << " in " << e.field();
  std::cerr << ": " << e.what() << '\n';
  if (e.position() && !e.field().empty()) {
    const auto it = report.field_texts.find(e.field());
    if (it != report.field_texts.end()) print_caret(e.field(), it->second, *e.position());
  }
}

void report_no_single_equation(const ErrorReport& report, const NoSingleEquation& e) {
  if (report.json) std::cout << encode_error(e) << '\n';
  std::cerr << "error: " << e.code() << ": " << e.what() << '\n';
  if (e.code() != "no_single_equation") return;  // base_points: no ideal was computed
  if (e.generators().empty()) {
    std::cerr << "the elimination ideal is zero\n";
  } else {
    std::cerr << "generators of the elimination ideal:\n";
    for (const std::string& g : e.generators()) std::cerr << "  " << g << '\n';
  }
}

void report_tolerance_not_met(const ErrorReport& report, const ToleranceNotMet& e) {
  if (report.json) std::cout << encode_error(e) << '\n';
  // The message states the best bound reached (ToleranceNotMet::best(), in the JSON).
  std::cerr << "error: tolerance_not_met: " << e.what() << '\n';
}

void report_limit(const ErrorReport& report, const LimitExceeded& e) {
  if (report.json) std::cout << encode_error(e) << '\n';
  std::cerr << "error: " << limit_error_code(e.limit()) << " (" << to_string(e.limit()) << " limit): " << e.what()
            << '\n';
}

}  // namespace

int run_reporting_errors(const ErrorReport& report, const std::function<void()>& body) {
  try {
    body();
    std::cout.flush();
    return kExitOk;
  } catch (const UsageError& e) {
    return report_usage_error(e.what(), nullptr);
  } catch (const InputError& e) {
    report_input_error(report, e);
    return kExitInvalidInput;
  } catch (const NoSingleEquation& e) {
    report_no_single_equation(report, e);
    return kExitNoSingleEquation;
  } catch (const ToleranceNotMet& e) {
    report_tolerance_not_met(report, e);
    return kExitToleranceNotMet;
  } catch (const LimitExceeded& e) {
    report_limit(report, e);
    return kExitLimit;
  } catch (const std::bad_alloc&) {
    // The machine's memory exhausted (one allocation past --max-memory arrives as
    // LimitExceeded: Budget::rethrow_bad_alloc).
    report_limit(report, LimitExceeded(Limit::memory,
                                       "out of memory: the machine has no memory left for this "
                                       "computation"));
    return kExitLimit;
  } catch (const std::exception& e) {
    if (report.json) std::cout << encode_error("internal_error", "internal error") << '\n';
    std::cerr << "error: internal error: " << e.what() << '\n';
    return kExitInternalError;
  }
}

int report_usage_error(const std::string& message, const char* command) {
  std::cerr << "error: " << message << '\n'
            << "run 'implicitizer " << (command != nullptr ? std::string(command) + " " : std::string())
            << "--help' for usage\n";
  return kExitUsage;
}

}  // namespace implicitizer::cli
