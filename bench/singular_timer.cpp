#include "singular_timer.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "implicitizer/implicitization/reproduce.hpp"

namespace implicitizer::bench {

namespace {

constexpr const char* kTimeMarker = "implicitizer-bench-time ";
constexpr const char* kGeneratorsMarker = "implicitizer-bench-generators ";

// Quotes `word` for /bin/sh.
std::string shell_quote(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct ProcessOutput {
  std::string text;   // stdout and stderr together
  int status = -1;    // as waitpid reports it
  double cpu_ms = 0;  // user + system time of the shell and everything it waited for
};

double children_cpu_ms() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  const auto ms = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_usec) / 1e3;
  };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

// popen's shell waits for `timeout`, which waits for Singular, so the growth of
// RUSAGE_CHILDREN across pclose() is Singular's CPU time (and two small processes').
ProcessOutput run_shell(const std::string& command) {
  ProcessOutput out;
  const double cpu_before = children_cpu_ms();
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run: " + command);
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) out.text.append(buffer.data(), n);
  out.status = pclose(pipe);
  out.cpu_ms = children_cpu_ms() - cpu_before;
  return out;
}

// The script reproduce.cpp writes ends with `ideal J = eliminate(I, w*s*t);` and the
// lines printing J; everything from that line on is replaced by the timing loop. The
// variables to eliminate are read back from that line, so the ideal and the
// eliminated variables stay exactly the library's.
std::string timing_script(const std::string& reproduce_script, const SingularOptions& options) {
  const std::string head = "ideal J = eliminate(I, ";
  const std::size_t at = reproduce_script.find(head);
  const std::size_t close = at == std::string::npos ? at : reproduce_script.find(");", at);
  if (close == std::string::npos) {
    throw std::runtime_error("singular_script() no longer has the line 'ideal J = eliminate(I, ...);'");
  }
  const std::string product = reproduce_script.substr(at + head.size(), close - at - head.size());
  const long below_us = static_cast<long>(options.repeat_below_seconds * 1e6);
  std::ostringstream s;
  s << reproduce_script.substr(0, at)  //
    << "system(\"--ticks-per-sec\", 1000000);\n"
    << "int bench_start = rtimer;\n"
    << "int bench_cpu_start = timer;\n"
    << "ideal J = eliminate(I, " << product << ");\n"
    << "int bench_elapsed = rtimer - bench_start;\n"
    << "print(\"" << kTimeMarker << "\" + string(bench_elapsed) + \" \" + string(timer - bench_cpu_start));\n"
    << "int bench_run;\n"
    << "if (bench_elapsed < " << below_us << ") {\n"
    << "  for (bench_run = 2; bench_run <= " << options.repeat << "; bench_run++) {\n"
    << "    bench_start = rtimer;\n"
    << "    bench_cpu_start = timer;\n"
    << "    J = eliminate(I, " << product << ");\n"
    << "    bench_elapsed = rtimer - bench_start;\n"
    << "    print(\"" << kTimeMarker << "\" + string(bench_elapsed) + \" \" + string(timer - bench_cpu_start));\n"
    << "  }\n"
    << "}\n"
    << "print(\"" << kGeneratorsMarker << "\" + string(size(J)));\n"
    << "int i;\n"
    << "for (i = 1; i <= size(J); i++) { print(J[i]); }\n"
    << "quit;\n";
  return s.str();
}

// A script file in the temporary directory, removed when this goes out of scope.
class TemporaryScript {
 public:
  explicit TemporaryScript(const std::string& text) {
    const char* dir = std::getenv("TMPDIR");
    std::string pattern = std::string(dir != nullptr && *dir != '\0' ? dir : "/tmp") + "/implicitizer-bench-XXXXXX.sgl";
    const int fd = mkstemps(pattern.data(), 4);
    if (fd < 0) throw std::runtime_error("cannot create a temporary file from " + pattern);
    close(fd);
    path_ = pattern;
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path_);
  }
  ~TemporaryScript() { std::remove(path_.c_str()); }
  TemporaryScript(const TemporaryScript&) = delete;
  TemporaryScript& operator=(const TemporaryScript&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

bool starts_with(const std::string& line, const char* prefix) { return line.rfind(prefix, 0) == 0; }

}  // namespace

bool singular_available(const std::string& executable) {
  const ProcessOutput out = run_shell(shell_quote(executable) + " --version </dev/null 2>&1");
  return WIFEXITED(out.status) && WEXITSTATUS(out.status) == 0;
}

std::string singular_version(const std::string& executable) {
  if (!singular_available(executable)) return "";
  const ProcessOutput out = run_shell(shell_quote(executable) + " --version </dev/null 2>&1");
  return out.text.substr(0, out.text.find('\n'));
}

SingularRun time_singular_eliminate(const Parametrization& parametrization, const SingularOptions& options) {
  const TemporaryScript script(timing_script(singular_script(parametrization), options));
  // The process may run `repeat` fast eliminates after the first, plus start-up: the
  // kill deadline leaves room for those, and the first run's own time decides a timeout.
  const double deadline = options.timeout_seconds + options.repeat * options.repeat_below_seconds + 10;
  std::ostringstream command;
  command << "timeout --kill-after=5 " << deadline << " " << shell_quote(options.executable) << " -q --no-rc --no-warn "
          << shell_quote(script.path()) << " </dev/null 2>&1";
  const ProcessOutput out = run_shell(command.str());

  SingularRun run;
  run.process_cpu_ms = out.cpu_ms;
  if (WIFEXITED(out.status) && (WEXITSTATUS(out.status) == 124 || WEXITSTATUS(out.status) == 137)) {
    run.status = SingularRun::Status::timeout;
    return run;
  }
  std::istringstream lines(out.text);
  std::string line;
  std::string complaints;
  long expected_generators = -1;
  while (std::getline(lines, line)) {
    if (starts_with(line, kTimeMarker)) {
      std::istringstream times(line.substr(std::char_traits<char>::length(kTimeMarker)));
      double wall_us = 0;
      double cpu_us = 0;
      times >> wall_us >> cpu_us;
      run.times_ms.push_back(wall_us / 1000.0);
      run.cpu_ms.push_back(cpu_us / 1000.0);
    } else if (starts_with(line, kGeneratorsMarker)) {
      expected_generators = std::stol(line.substr(std::char_traits<char>::length(kGeneratorsMarker)));
    } else if (expected_generators >= 0 && static_cast<long>(run.generators.size()) < expected_generators) {
      run.generators.push_back(line);
    } else if (!line.empty()) {
      complaints += (complaints.empty() ? "" : " | ") + line;
    }
  }
  const bool exited_cleanly = WIFEXITED(out.status) && WEXITSTATUS(out.status) == 0;
  if (!exited_cleanly || run.times_ms.empty() || expected_generators < 0 ||
      static_cast<long>(run.generators.size()) != expected_generators) {
    run.status = SingularRun::Status::error;
    run.message = "Singular exit status " + std::to_string(WIFEXITED(out.status) ? WEXITSTATUS(out.status) : -1) +
                  (complaints.empty() ? "" : ": " + complaints);
    return run;
  }
  run.status =
      run.times_ms.front() > options.timeout_seconds * 1000 ? SingularRun::Status::timeout : SingularRun::Status::ok;
  return run;
}

}  // namespace implicitizer::bench
