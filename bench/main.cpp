/// \file
/// implicitizer-bench: how long implicitize() takes on the surfaces of shared/bench
/// (surfaces_public.json, surfaces_hard.json), beside Singular's `eliminate` on the
/// same ideal, timed in the same run on the same machine.
///
/// Measured on our side: one call of implicitize() with the default options
/// (Buchberger with sugar and Gebauer–Möller, then exact verification by
/// substitution), parsing excluded; on Singular's side: `eliminate` alone, timed with
/// `rtimer` inside the Singular process (singular_timer.hpp). Both are wall-clock
/// times, and a second ratio compares CPU times, which other processes on the
/// machine disturb less; a run that takes less than --repeat-below seconds is repeated until
/// --repeat runs and the median is reported. Every run has the same time limit
/// (--budget): a Budget deadline for us, `timeout` for Singular. When both finish,
/// the answers are compared up to a non-zero rational factor; when Singular gives no
/// answer, ours is compared with shared/bench/expected/NAME.txt if it exists.
///
/// This is not a test: it is not registered with ctest and its exit status only says
/// whether an answer differed or a run failed (1) or not (0), never how fast it was.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "singular_timer.hpp"
#include "surface_suite.hpp"

#ifndef IMPLICITIZER_BENCH_DIR
#define IMPLICITIZER_BENCH_DIR "../shared/bench"
#endif

namespace implicitizer::bench {
namespace {

constexpr const char* kUsage =
    "usage: implicitizer-bench [--suite public|hard|all] [--only NAME,NAME...] [--repeat N]\n"
    "                          [--repeat-below SECONDS] [--budget SECONDS] [--markdown]\n"
    "                          [--no-singular] [--singular PATH] [--surfaces DIR]\n"
    "\n"
    "Times implicitize() on the benchmark surfaces and Singular's eliminate on the same\n"
    "ideal, in the same run. Defaults: --suite all --repeat 5 --repeat-below 1 --budget 60\n"
    "--singular Singular --surfaces " IMPLICITIZER_BENCH_DIR "\n";

/// The command line.
struct Config {
  std::string suite = "all";        ///< public, hard or all
  std::vector<std::string> only;    ///< when non-empty, only these surfaces
  int repeat = 5;                   ///< runs of a fast surface (median reported)
  double repeat_below_seconds = 1;  ///< a first run shorter than this is repeated
  double budget_seconds = 60;       ///< time limit of each run, ours and Singular's
  bool markdown = false;            ///< print Markdown tables instead of aligned text
  bool singular = true;             ///< time Singular too
  std::string singular_executable = "Singular";
  std::filesystem::path surfaces_dir = IMPLICITIZER_BENCH_DIR;
};

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double parse_number(const std::string& flag, const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && value > 0) return value;
  } catch (const std::exception&) {
  }
  throw UsageError(flag + " needs a positive number, not '" + text + "'");
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) {
    if (!part.empty()) parts.push_back(part);
  }
  return parts;
}

Config parse_config(int argc, char** argv) {
  Config config;
  for (int i = 1; i < argc; ++i) {
    std::string flag = argv[i];
    std::string value;
    bool has_value = false;
    if (const auto eq = flag.find('='); flag.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = flag.substr(eq + 1);
      flag = flag.substr(0, eq);
      has_value = true;
    }
    const auto take_value = [&]() -> std::string {
      if (has_value) return value;
      if (i + 1 >= argc) throw UsageError(flag + " needs a value");
      return argv[++i];
    };
    if (flag == "--help" || flag == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else if (flag == "--suite") {
      config.suite = take_value();
      if (config.suite != "public" && config.suite != "hard" && config.suite != "all") {
        throw UsageError("--suite is public, hard or all, not '" + config.suite + "'");
      }
    } else if (flag == "--only") {
      config.only = split_commas(take_value());
    } else if (flag == "--repeat") {
      const double n = parse_number(flag, take_value());
      if (n != static_cast<int>(n)) throw UsageError("--repeat needs a whole number");
      config.repeat = static_cast<int>(n);
    } else if (flag == "--repeat-below") {
      config.repeat_below_seconds = parse_number(flag, take_value());
    } else if (flag == "--budget") {
      config.budget_seconds = parse_number(flag, take_value());
    } else if (flag == "--markdown") {
      config.markdown = true;
    } else if (flag == "--no-singular") {
      config.singular = false;
    } else if (flag == "--singular") {
      config.singular_executable = take_value();
    } else if (flag == "--surfaces") {
      config.surfaces_dir = take_value();
    } else {
      throw UsageError("unknown argument '" + flag + "'");
    }
  }
  return config;
}

// ---------------------------------------------------------------- measurements

/// Our side of one surface.
struct OurRun {
  enum class Status { ok, time_limit, error };
  Status status = Status::error;
  std::vector<double> times_ms;   ///< wall time of each implicitize() call that finished
  std::vector<double> cpu_ms;     ///< CPU time of each of those calls
  std::vector<double> verify_ms;  ///< of which verification (wall), per call
  double stopped_cpu_ms = 0;      ///< for time_limit: CPU time spent before the budget ran out
  ImplicitizeResult result;       ///< of the last call that finished
  std::string message;            ///< for time_limit and error: what stopped it
};

/// The median (mean of the middle two for an even count); precondition: non-empty.
double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

/// CPU time of this process so far, in milliseconds (the library computes in the
/// calling thread, so under load this is the time it actually had a core).
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

/// Calls implicitize() until `repeat` runs, or once when the first run is slow; each
/// call gets a fresh budget of `budget_seconds`, so a limit stops one call only.
OurRun time_implicitize(const Parametrization& p, const Config& config) {
  OurRun run;
  for (int k = 0; k < config.repeat; ++k) {
    ImplicitizeOptions options;
    options.groebner.budget = Budget::with_timeout(config.budget_seconds);
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_ms();
    try {
      run.result = implicitize(p, options);
    } catch (const LimitExceeded& e) {
      run.status = OurRun::Status::time_limit;
      run.message = e.what();
      run.stopped_cpu_ms = process_cpu_ms() - cpu_start;
      return run;
    } catch (const std::exception& e) {
      run.status = OurRun::Status::error;
      run.message = e.what();
      return run;
    }
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    run.times_ms.push_back(elapsed.count());
    run.cpu_ms.push_back(process_cpu_ms() - cpu_start);
    run.verify_ms.push_back(run.result.verify_ms);
    run.status = OurRun::Status::ok;
    if (elapsed.count() >= config.repeat_below_seconds * 1000) break;
  }
  return run;
}

/// "agree" when `theirs` (printed in x, y, z) is a non-zero rational multiple of
/// `ours`; "DIFFER" otherwise, with a reason when it is not just another polynomial.
std::string compare_with(const Polynomial& ours, const std::vector<std::string>& theirs) {
  if (theirs.size() != 1) return "DIFFER (" + std::to_string(theirs.size()) + " generators)";
  try {
    const Polynomial other = parse_polynomial(theirs.front(), ours.ring());
    if (other.is_zero()) return "DIFFER (zero)";
    return other.monic() == ours.monic() ? "agree" : "DIFFER";
  } catch (const std::exception& e) {
    return std::string("DIFFER (unreadable: ") + e.what() + ")";
  }
}

std::vector<std::string> read_lines(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

// ---------------------------------------------------------------- one table row

/// Everything printed about one surface.
struct Row {
  std::string name;
  std::string degree;
  std::string ours;
  std::string verify = "—";
  std::string singular;
  std::string ratio;      ///< of wall times
  std::string cpu_ratio;  ///< of CPU times: what contention from other processes does not move
  std::string runs;
  std::string our_status;
  std::string singular_status;
  std::string check;
  bool meets_target = false;  ///< public target: ≤ 3× Singular's time, or under 5 ms
  bool failed = false;        ///< an answer differed or a run failed
};

std::string format_ms(double ms) {
  char text[32];
  if (ms < 1) {
    std::snprintf(text, sizeof text, "%.0f µs", ms * 1000);
  } else if (ms < 10) {
    std::snprintf(text, sizeof text, "%.2f ms", ms);
  } else if (ms < 1000) {
    std::snprintf(text, sizeof text, "%.1f ms", ms);
  } else if (ms < 10000) {
    std::snprintf(text, sizeof text, "%.2f s", ms / 1000);
  } else {
    std::snprintf(text, sizeof text, "%.1f s", ms / 1000);
  }
  return text;
}

std::string format_ratio(double ratio) {
  char text[32];
  std::snprintf(text, sizeof text, ratio < 10 ? "%.2f" : "%.0f", ratio);
  return text;
}

std::string format_seconds(double seconds) {
  std::ostringstream s;
  s << seconds << " s";
  return s.str();
}

Row measure_surface(const Surface& surface, const Config& config) {
  Row row;
  row.name = surface.name;
  row.degree = surface.degree > 0 ? std::to_string(surface.degree) : "?";
  const std::string limit = format_seconds(config.budget_seconds);

  std::optional<Parametrization> parsed;
  try {
    parsed = parse_parametrization(surface.x, surface.y, surface.z);
  } catch (const std::exception& e) {
    row.our_status = std::string("error: ") + e.what();
    row.failed = true;
    return row;
  }
  const Parametrization& p = *parsed;

  const OurRun ours = time_implicitize(p, config);
  double our_ms = 0;
  switch (ours.status) {
    case OurRun::Status::ok:
      our_ms = median(ours.times_ms);
      row.ours = format_ms(our_ms);
      row.verify = format_ms(median(ours.verify_ms));
      row.our_status = "ok";
      if (surface.degree > 0 && ours.result.degree != surface.degree) {
        row.our_status = "ok, degree " + std::to_string(ours.result.degree);
        row.failed = true;
      }
      break;
    case OurRun::Status::time_limit:
      row.ours = "> " + limit;
      row.our_status = "time_limit (" + limit + ")";
      break;
    case OurRun::Status::error:
      row.ours = "—";
      row.our_status = "error: " + ours.message;
      row.failed = true;
      break;
  }

  SingularRun theirs;
  double their_ms = 0;
  if (config.singular) {
    SingularOptions options;
    options.executable = config.singular_executable;
    options.timeout_seconds = config.budget_seconds;
    options.repeat = config.repeat;
    options.repeat_below_seconds = config.repeat_below_seconds;
    theirs = time_singular_eliminate(p, options);
    switch (theirs.status) {
      case SingularRun::Status::ok:
        their_ms = median(theirs.times_ms);
        row.singular = format_ms(their_ms);
        row.singular_status = "ok";
        break;
      case SingularRun::Status::timeout:
        row.singular = "> " + limit;
        row.singular_status = "timeout (" + limit + ")";
        break;
      case SingularRun::Status::error:
        row.singular = "—";
        row.singular_status = "error: " + theirs.message;
        row.failed = true;
        break;
    }
  } else {
    row.singular = "—";
    row.singular_status = "not run";
  }
  row.runs = std::to_string(ours.times_ms.size()) + " / " +
             (config.singular ? std::to_string(theirs.times_ms.size()) : std::string("—"));

  const bool our_ok = ours.status == OurRun::Status::ok;
  const bool their_ok = config.singular && theirs.status == SingularRun::Status::ok;
  const bool their_timeout = config.singular && theirs.status == SingularRun::Status::timeout;
  if (our_ok && their_ok) {
    row.ratio = format_ratio(our_ms / their_ms);
  } else if (our_ok && their_timeout) {
    row.ratio = "< " + format_ratio(our_ms / (config.budget_seconds * 1000));
  } else if (ours.status == OurRun::Status::time_limit && their_ok) {
    row.ratio = "> " + format_ratio(config.budget_seconds * 1000 / their_ms);
  } else {
    row.ratio = "—";
  }
  // Singular's `timer` counts in 10 ms steps: a CPU ratio needs a run of 100 ms or more.
  const double their_cpu_ms = their_ok ? median(theirs.cpu_ms) : 0;
  if (our_ok && their_ok && their_cpu_ms >= 100) {
    row.cpu_ratio = format_ratio(median(ours.cpu_ms) / their_cpu_ms);
  } else if (our_ok && their_timeout && theirs.process_cpu_ms > 0) {
    row.cpu_ratio = "< " + format_ratio(median(ours.cpu_ms) / theirs.process_cpu_ms);
  } else if (ours.status == OurRun::Status::time_limit && their_ok && their_cpu_ms >= 100) {
    row.cpu_ratio = "> " + format_ratio(ours.stopped_cpu_ms / their_cpu_ms);
  } else {
    row.cpu_ratio = "—";
  }
  row.meets_target = our_ok && (our_ms < 5 || (their_ok && our_ms <= 3 * their_ms) || their_timeout);

  if (our_ok && their_ok) {
    row.check = compare_with(ours.result.implicit, theirs.generators);
  } else if (const auto expected = config.surfaces_dir / "expected" / (surface.name + ".txt");
             our_ok && std::filesystem::exists(expected)) {
    row.check = compare_with(ours.result.implicit, read_lines(expected)) + " (expected/)";
  } else {
    row.check = "—";
  }
  if (row.check.rfind("DIFFER", 0) == 0) row.failed = true;
  return row;
}

// ---------------------------------------------------------------- printing

/// The columns, in order: header (Markdown), header (text), width (text).
struct Column {
  const char* markdown;
  const char* text;
  std::size_t width;
};
const std::vector<Column> kColumns = {
    {"surface", "surface", 22},
    {"degree", "degree", 6},
    {"ours", "ours", 9},
    {"Singular", "Singular", 9},
    {"ours / Singular", "ratio", 7},
    {"CPU ours / Singular", "CPU ratio", 9},
    {"of which verify", "verify", 9},
    {"runs", "runs", 7},
    {"status (ours)", "ours: status", 22},
    {"status (Singular)", "Singular: status", 18},
    {"answers", "answers", 10},
};

std::vector<std::string> cells_of(const Row& row) {
  return {row.name,   row.degree, row.ours,       row.singular,        row.ratio, row.cpu_ratio,
          row.verify, row.runs,   row.our_status, row.singular_status, row.check};
}

// Columns count characters, not bytes: "µs" and "—" are several bytes in UTF-8.
std::size_t display_width(const std::string& text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

void print_cells(const std::vector<std::string>& cells, bool markdown) {
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (markdown) {
      line += "| " + cells[i] + " ";
    } else {
      std::string cell = cells[i];
      if (const std::size_t width = display_width(cell); width < kColumns[i].width)
        cell.append(kColumns[i].width - width, ' ');
      line += (i ? "  " : "") + cell;
    }
  }
  if (markdown) line += "|";
  while (!line.empty() && line.back() == ' ') line.pop_back();
  std::cout << line << '\n' << std::flush;
}

void print_table_header(const std::string& suite, bool markdown) {
  std::cout << '\n' << (markdown ? "### " : "== ") << suite << " surfaces" << (markdown ? "\n\n" : "\n");
  std::vector<std::string> header;
  for (const Column& column : kColumns) header.emplace_back(markdown ? column.markdown : column.text);
  print_cells(header, markdown);
  if (markdown) print_cells(std::vector<std::string>(kColumns.size(), "---"), true);
}

std::string read_cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown CPU";
}

int run(const Config& config) {
  std::vector<Surface> surfaces;
  for (const char* suite : {"public", "hard"}) {
    if (config.suite != "all" && config.suite != suite) continue;
    const auto file = config.surfaces_dir / ("surfaces_" + std::string(suite) + ".json");
    for (Surface& s : read_surface_suite(file, suite)) {
      if (config.only.empty() || std::find(config.only.begin(), config.only.end(), s.name) != config.only.end()) {
        surfaces.push_back(std::move(s));
      }
    }
  }
  for (const auto& name : config.only) {
    if (std::none_of(surfaces.begin(), surfaces.end(), [&](const Surface& s) { return s.name == name; })) {
      throw UsageError("no surface named '" + name + "' in the selected suite(s)");
    }
  }
  if (surfaces.empty()) throw UsageError("no surface selected");

  Config effective = config;
  std::string singular_line = "not run (--no-singular)";
  if (effective.singular) {
    singular_line = singular_version(effective.singular_executable);
    if (singular_line.empty()) {
      std::cerr << "implicitizer-bench: '" << effective.singular_executable << "' does not run; timing ours only\n";
      effective.singular = false;
      singular_line = "not found";
    }
  }
  const char* bullet = config.markdown ? "- " : "";
  std::cout << bullet << "machine: " << read_cpu_model() << ", " << std::thread::hardware_concurrency()
            << " hardware threads\n"
            << bullet << "Singular: " << singular_line << '\n'
            << bullet << "budget " << format_seconds(config.budget_seconds) << " per run (ours and Singular's); "
            << "runs under " << format_seconds(config.repeat_below_seconds) << " repeated " << config.repeat
            << " times, median shown\n";

  std::string suite;
  int public_count = 0;
  std::vector<std::string> public_misses;
  bool failed = false;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const Surface& s = surfaces[i];
    if (s.suite != suite) {
      suite = s.suite;
      print_table_header(suite, config.markdown);
    }
    std::cerr << "[" << i + 1 << "/" << surfaces.size() << "] " << s.name << "\n";
    const Row row = measure_surface(s, effective);
    print_cells(cells_of(row), config.markdown);
    failed = failed || row.failed;
    if (s.suite == "public") {
      ++public_count;
      if (!row.meets_target) public_misses.push_back(s.name);
    }
  }
  if (public_count > 0) {
    std::cout << '\n'
              << bullet << "public target (within 3x of Singular, or under 5 ms"
              << (effective.singular ? "" : "; Singular not run, so only the 5 ms clause") << "): met by "
              << public_count - static_cast<int>(public_misses.size()) << " of " << public_count;
    if (!public_misses.empty()) {
      std::cout << "; missed by";
      for (const auto& name : public_misses) std::cout << ' ' << name;
    }
    std::cout << '\n';
  }
  return failed ? 1 : 0;
}

}  // namespace
}  // namespace implicitizer::bench

int main(int argc, char** argv) {
  try {
    return implicitizer::bench::run(implicitizer::bench::parse_config(argc, argv));
  } catch (const implicitizer::bench::UsageError& e) {
    std::cerr << "implicitizer-bench: " << e.what() << "\n\n" << implicitizer::bench::kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "implicitizer-bench: " << e.what() << '\n';
    return 1;
  }
}
