#pragma once
/// \file
/// Running the oracles (Singular, Macaulay2) from the oracle tests: write a script to
/// a temporary file, run the program on it under coreutils' `timeout`, capture its
/// output, cut the output into sections between marker lines, compare polynomials.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "implicitization/surfaces.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer::testing {

/// How GoogleTest prints a surface parameter in test names' messages.
inline void PrintTo(const Surface& s, std::ostream* os) { *os << s.name; }

/// The oracles as CMake found them at configure time ("" or "...-NOTFOUND" if not).
inline const std::string kSingular = SINGULAR_EXECUTABLE;
inline const std::string kMacaulay2 = MACAULAY2_EXECUTABLE;

/// Whether `path` names an executable file.
inline bool is_runnable(const std::string& path) { return !path.empty() && ::access(path.c_str(), X_OK) == 0; }

/// What a script run produced.
struct ScriptRun {
  int exit_code = -1;  ///< the program's exit status; 124 when `timeout` stopped it
  std::string out;     ///< standard output
  std::string err;     ///< standard error
  /// A one-line summary plus both streams, for failure messages.
  std::string describe() const {
    return "exit " + std::to_string(exit_code) + (exit_code == 124 ? " (timed out)" : "") + "\n--- stdout\n" + out +
           "--- stderr\n" + err;
  }
};

/// A temporary file that is removed when it goes out of scope.
class TemporaryFile {
 public:
  TemporaryFile() {
    std::string pattern = (std::filesystem::temp_directory_path() / "implicitizer-oracle-XXXXXX").string();
    const int fd = ::mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error("mkstemp failed");
    ::close(fd);
    path_ = pattern;
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// `text` quoted for the POSIX shell.
inline std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Runs `program options... SCRIPT` where SCRIPT is a file holding `script`, with
/// standard input from /dev/null, killed after `timeout_seconds` (then 5 s more for
/// SIGKILL), so that a hanging oracle fails the test instead of stalling the suite.
inline ScriptRun run_script(const std::string& program, const std::vector<std::string>& options,
                            const std::string& script, int timeout_seconds) {
  TemporaryFile script_file;
  TemporaryFile err_file;
  std::ofstream(script_file.path()) << script;
  std::string command = "timeout -k 5 " + std::to_string(timeout_seconds) + " " + shell_quote(program);
  for (const auto& option : options) command += " " + shell_quote(option);
  command += " " + shell_quote(script_file.path()) + " </dev/null 2>" + shell_quote(err_file.path());
  ScriptRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("popen failed: " + command);
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::stringstream err;
  err << std::ifstream(err_file.path()).rdbuf();
  run.err = err.str();
  return run;
}

/// Runs a Singular script quietly, without the user's ~/.singularrc.
inline ScriptRun run_singular(const std::string& script, int timeout_seconds = 60) {
  return run_script(kSingular, {"-q", "--no-rc"}, script, timeout_seconds);
}

/// Runs a Macaulay2 script headless (`M2 --script FILE`: no banner, no prompts).
inline ScriptRun run_macaulay2(const std::string& script, int timeout_seconds = 60) {
  return run_script(kMacaulay2, {"--script"}, script, timeout_seconds);
}

/// `parts` separated by `separator`.
inline std::string join(const std::vector<std::string>& parts, const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? separator : "") + parts[i];
  return out;
}

/// The non-empty lines of `text`, trailing spaces and carriage returns removed.
inline std::vector<std::string> non_empty_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

/// The marker a script prints (as a line of its own) before section `label`.
inline std::string section_marker(const std::string& label) { return "@@ " + label; }

/// Cuts `output` into the sections that follow each marker line (section_marker()).
/// Lines before the first marker are kept under the label "" so that stray output
/// (warnings, errors) is noticed.
inline std::map<std::string, std::vector<std::string>> split_sections(const std::string& output) {
  std::map<std::string, std::vector<std::string>> sections;
  std::string label;
  const std::string prefix = section_marker("");
  for (const auto& line : non_empty_lines(output)) {
    if (line.rfind(prefix, 0) == 0) {
      label = line.substr(prefix.size());
      sections[label];
    } else {
      sections[label].push_back(line);
    }
  }
  return sections;
}

/// Whether `a` and `b` (same ring) differ by a non-zero rational factor.
inline ::testing::AssertionResult equal_up_to_scalar(const Polynomial& a, const Polynomial& b) {
  if (a.is_zero() || b.is_zero() || !(a.primitive_part() == b.primitive_part())) {
    return ::testing::AssertionFailure() << to_string(a) << "\n  is not a rational multiple of\n" << to_string(b);
  }
  return ::testing::AssertionSuccess();
}

}  // namespace implicitizer::testing
