#pragma once
/// \file
/// Turns the library's three refusals (and everything else) into the contract's
/// exit statuses and messages: stderr for people, stdout JSON with `--json`, the same
/// JSON the HTTP endpoint sends.

#include <functional>
#include <map>
#include <string>

namespace implicitizer::cli {

/// The contract's exit statuses.
enum ExitStatus : int {
  kExitOk = 0,
  kExitInternalError = 1,  ///< a bug or an exhausted machine: never an answer
  kExitUsage = 2,          ///< the program was called wrongly
  kExitInvalidInput = 3,   ///< InputError
  kExitNoSingleEquation = 4,
  /// ToleranceNotMet shares 4: like no single equation, a well-formed input the
  /// computation cannot answer as asked (both are HTTP 422).
  kExitToleranceNotMet = 4,
  kExitLimit = 5,  ///< LimitExceeded: time, size or cancelled
};

/// How a command reports failures.
struct ErrorReport {
  bool json = false;  ///< also print the error JSON on stdout
  /// The text behind each request field ("x", "polynomials[1]"), to show the input
  /// with a caret under the error position.
  std::map<std::string, std::string> field_texts;
};

/// Runs `body` (which prints its answer and returns), mapping what it throws to an
/// exit status: UsageError 2; InputError 3 (`error: CODE at position N in FIELD:
/// MESSAGE` on stderr); NoSingleEquation 4 (with the generators); LimitExceeded 5
/// (naming the limit); any other exception 1 (`error: internal error: ...`).
int run_reporting_errors(const ErrorReport& report, const std::function<void()>& body);

/// Prints `error: MESSAGE` and a hint to use --help on stderr; returns kExitUsage.
int report_usage_error(const std::string& message, const char* command);

}  // namespace implicitizer::cli
