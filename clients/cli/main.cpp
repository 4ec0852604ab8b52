/// \file
/// build/bin/implicitizer: dispatches to one command. Every failure becomes an exit
/// status (docs/cli.md); nothing escapes main, so the program never aborts.

#include <exception>
#include <iostream>
#include <span>
#include <string>
#include <vector>

#include "error_report.hpp"
#include "groebner_command.hpp"
#include "help.hpp"
#include "implicitize_command.hpp"
#include "render_command.hpp"
#include "resultant_command.hpp"
#include "sdf_command.hpp"

namespace {

using namespace implicitizer::cli;

int run(const std::vector<std::string>& words) {
  if (words.empty()) {
    std::cerr << kGeneralHelp;
    return kExitUsage;
  }
  const std::string& command = words.front();
  const std::span<const std::string> rest(words.data() + 1, words.size() - 1);
  if (command == "implicitize") return run_implicitize_command(rest);
  if (command == "groebner") return run_groebner_command(rest);
  if (command == "resultant") return run_resultant_command(rest);
  if (command == "sdf") return run_sdf_command(rest);
  if (command == "render") return run_render_command(rest);
  if (command == "--version" || command == "version") {
    std::cout << "implicitizer " << IMPLICITIZER_VERSION << '\n';
    return kExitOk;
  }
  if (command == "--help" || command == "-h" || command == "help") {
    if (rest.empty()) {
      std::cout << kGeneralHelp;
    } else if (rest.front() == "implicitize") {
      std::cout << kImplicitizeHelp;
    } else if (rest.front() == "groebner") {
      std::cout << kGroebnerHelp;
    } else if (rest.front() == "resultant") {
      std::cout << kResultantHelp;
    } else if (rest.front() == "sdf") {
      std::cout << kSdfHelp;
    } else if (rest.front() == "render") {
      std::cout << kRenderHelp;
    } else {
      return report_usage_error("no help for unknown command '" + rest.front() + "'", nullptr);
    }
    return kExitOk;
  }
  return report_usage_error("unknown command '" + command + "'", nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& e) {
    std::cerr << "error: internal error: " << e.what() << '\n';
  } catch (...) {
    std::cerr << "error: internal error\n";
  }
  return kExitInternalError;
}
