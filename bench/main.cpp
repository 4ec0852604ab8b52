/// \file
/// implicitizer-bench: how long implicitize() takes on the surfaces of shared/bench
/// (surfaces_public.json, surfaces_hard.json), beside Singular's `eliminate` on the
/// same ideal, timed in the same run on the same machine.
///
/// Measured on our side: one call of implicitize() with the route of --method (auto
/// by default: the auxiliary resultant when the parametrization has no base points,
/// else Buchberger with sugar and Gebauer–Möller; then exact verification), parsing
/// excluded; on Singular's side: `eliminate` alone, timed with
/// `rtimer` inside the Singular process (singular_timer.hpp). Both are wall-clock
/// times, and a second ratio compares CPU times, which other processes on the
/// machine disturb less; a run that takes less than --repeat-below seconds is repeated until
/// --repeat runs and the median is reported. Every run has the same time limit
/// (--budget): a Budget deadline for us, `timeout` for Singular. When both finish,
/// the answers are compared up to a non-zero rational factor; when Singular gives no
/// answer, ours is compared with shared/bench/expected/NAME.txt if it exists.
///
/// With --routes, each surface is run by every route (groebner, resultant,
/// interpolation, auto) under the same repeat and budget policy, beside Singular
/// once, in one table whose last ratio, auto / min(groebner, resultant,
/// interpolation), is what auto's choice of route costs against an oracle that knew
/// the fastest of the routes auto chooses from.
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
    "usage: implicitizer-bench [--suite public|hard|all] [--only NAME,NAME...]\n"
    "                          [--method auto|groebner|resultant|interpolation | --routes] [--modular]\n"
    "                          [--repeat N] [--repeat-below SECONDS] [--budget SECONDS] [--markdown]\n"
    "                          [--no-singular] [--singular PATH] [--surfaces DIR]\n"
    "\n"
    "Times implicitize() on the benchmark surfaces and Singular's eliminate on the same\n"
    "ideal, in the same run. --method picks our route (the column \"method\" shows the one\n"
    "taken); --routes instead times every route (groebner, resultant, interpolation, auto)\n"
    "on each surface beside Singular, with the ratios auto / Singular and\n"
    "auto / min(groebner, resultant, interpolation). --modular runs the groebner route\n"
    "modulo primes (ImplicitizeParams::modular_groebner). Defaults: --suite all --method auto --repeat 5\n"
    "--repeat-below 1 --budget 60 --singular Singular --surfaces " IMPLICITIZER_BENCH_DIR "\n";

/// The command line.
struct Config {
  std::string suite = "all";      ///< public, hard or all
  std::vector<std::string> only;  ///< when non-empty, only these surfaces
  /// Our route in the default table.
  ImplicitizationMethod method = ImplicitizationMethod::automatic;
  bool method_given = false;        ///< --method was on the command line
  bool routes = false;              ///< time every route instead (--routes)
  bool modular = false;             ///< the Gröbner route modulo primes (--modular)
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
    } else if (flag == "--method") {
      const std::string name = take_value();
      try {
        config.method = parse_implicitization_method(name);
      } catch (const InputError& e) {
        throw UsageError(std::string("--method: ") + e.what());
      }
      config.method_given = true;
    } else if (flag == "--routes") {
      config.routes = true;
    } else if (flag == "--modular") {
      config.modular = true;
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
  // --routes runs every route; a --method beside it would be silently ignored.
  if (config.routes && config.method_given) throw UsageError("--routes times every route: drop --method");
  return config;
}

// ---------------------------------------------------------------- measurements

/// Our side of one surface, by one route.
struct OurRun {
  enum class Status {
    ok,           ///< finished; `result` holds the answer
    time_limit,   ///< the budget ran out
    base_points,  ///< the resultant route refused: the auxiliary resultant vanishes
    error,        ///< anything else (message says what)
  };
  Status status = Status::error;
  std::vector<double> times_ms;   ///< wall time of each implicitize() call that finished
  std::vector<double> cpu_ms;     ///< CPU time of each of those calls
  std::vector<double> verify_ms;  ///< of which verification (wall), per call
  double stopped_cpu_ms = 0;      ///< for time_limit: CPU time spent before the budget ran out
  ImplicitizeResult result;       ///< of the last call that finished
  std::string message;            ///< for time_limit, base_points and error: what stopped it
};

/// The name --method takes for `method`.
const char* method_name(ImplicitizationMethod method) {
  switch (method) {
    case ImplicitizationMethod::groebner:
      return "groebner";
    case ImplicitizationMethod::resultant:
      return "resultant";
    case ImplicitizationMethod::interpolation:
      return "interpolation";
    case ImplicitizationMethod::automatic:
      break;
  }
  return "auto";
}

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

/// Calls implicitize() by `method` until `repeat` runs, or once when the first run is
/// slow; each call gets a fresh budget of `budget_seconds`, so a limit stops one call
/// only. A refusal for base points stops at the first call: it is an answer of the
/// route, not a failure, and every later call would give it again.
OurRun time_implicitize(const Parametrization& p, ImplicitizationMethod method, const Config& config) {
  OurRun run;
  for (int k = 0; k < config.repeat; ++k) {
    ImplicitizeParams options;
    options.method = method;
    options.modular_groebner = config.modular;
    options.budget = Budget::with_timeout(config.budget_seconds);
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_ms();
    try {
      run.result = implicitize(p, options);
    } catch (const LimitExceeded& e) {
      run.status = OurRun::Status::time_limit;
      run.message = e.what();
      run.stopped_cpu_ms = process_cpu_ms() - cpu_start;
      return run;
    } catch (const NoSingleEquation& e) {
      run.status = e.code() == "base_points" ? OurRun::Status::base_points : OurRun::Status::error;
      run.message = e.what();
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

// ---------------------------------------------------------------- formatting

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

// Two significant digits below 0.1, so that a route 300× faster than Singular reads
// 0.0033 rather than 0.00.
std::string format_ratio(double ratio) {
  char text[32];
  std::snprintf(text, sizeof text, ratio < 0.1 ? "%.2g" : ratio < 10 ? "%.2f" : "%.0f", ratio);
  return text;
}

std::string format_seconds(double seconds) {
  std::ostringstream s;
  s << seconds << " s";
  return s.str();
}

/// One side of a ratio: a time that finished, or a bound (the run was stopped after
/// `ms`), or nothing to compare.
struct RatioTerm {
  enum class Kind { finished, stopped, unavailable };
  Kind kind = Kind::unavailable;
  double ms = 0;
};

/// "0.22" when both finished; "< x" or "> x" when one side was stopped, so that the
/// printed number is a bound that holds; "—" otherwise.
std::string format_ratio_cell(const RatioTerm& numerator, const RatioTerm& denominator) {
  using Kind = RatioTerm::Kind;
  if (numerator.kind == Kind::finished && denominator.kind == Kind::finished) {
    return format_ratio(numerator.ms / denominator.ms);
  }
  if (numerator.kind == Kind::finished && denominator.kind == Kind::stopped) {
    return "< " + format_ratio(numerator.ms / denominator.ms);
  }
  if (numerator.kind == Kind::stopped && denominator.kind == Kind::finished) {
    return "> " + format_ratio(numerator.ms / denominator.ms);
  }
  return "—";
}

/// Our wall time as a ratio term: the median, or the budget when it ran out.
RatioTerm wall_term(const OurRun& run, const Config& config) {
  switch (run.status) {
    case OurRun::Status::ok:
      return {RatioTerm::Kind::finished, median(run.times_ms)};
    case OurRun::Status::time_limit:
      return {RatioTerm::Kind::stopped, config.budget_seconds * 1000};
    default:
      return {};
  }
}

/// Our CPU time as a ratio term (all threads of the process: the resultant route
/// computes its primes on every core).
RatioTerm cpu_term(const OurRun& run) {
  switch (run.status) {
    case OurRun::Status::ok:
      return {RatioTerm::Kind::finished, median(run.cpu_ms)};
    case OurRun::Status::time_limit:
      return {RatioTerm::Kind::stopped, run.stopped_cpu_ms};
    default:
      return {};
  }
}

RatioTerm wall_term(const std::optional<SingularRun>& run, const Config& config) {
  if (!run) return {};
  if (run->status == SingularRun::Status::ok) return {RatioTerm::Kind::finished, median(run->times_ms)};
  if (run->status == SingularRun::Status::timeout) return {RatioTerm::Kind::stopped, config.budget_seconds * 1000};
  return {};
}

// Singular's `timer` counts in 10 ms steps: a CPU time is only usable from 100 ms on.
RatioTerm cpu_term(const std::optional<SingularRun>& run) {
  if (!run) return {};
  if (run->status == SingularRun::Status::ok) {
    const double ms = median(run->cpu_ms);
    return ms >= 100 ? RatioTerm{RatioTerm::Kind::finished, ms} : RatioTerm{};
  }
  if (run->status == SingularRun::Status::timeout && run->process_cpu_ms > 0) {
    return {RatioTerm::Kind::stopped, run->process_cpu_ms};
  }
  return {};
}

/// Our time as a table cell: the median, "> 60 s", "base points" or "—" (error).
std::string our_time_cell(const OurRun& run, const Config& config) {
  switch (run.status) {
    case OurRun::Status::ok:
      return format_ms(median(run.times_ms));
    case OurRun::Status::time_limit:
      return "> " + format_seconds(config.budget_seconds);
    case OurRun::Status::base_points:
      return "base points";
    case OurRun::Status::error:
      break;
  }
  return "—";
}

/// Singular's time as a table cell.
std::string singular_time_cell(const std::optional<SingularRun>& run, const Config& config) {
  if (!run) return "—";
  switch (run->status) {
    case SingularRun::Status::ok:
      return format_ms(median(run->times_ms));
    case SingularRun::Status::timeout:
      return "> " + format_seconds(config.budget_seconds);
    case SingularRun::Status::error:
      break;
  }
  return "—";
}

/// Singular's status as a table cell.
std::string singular_status_cell(const std::optional<SingularRun>& run, const Config& config) {
  if (!run) return "not run";
  switch (run->status) {
    case SingularRun::Status::ok:
      return "ok";
    case SingularRun::Status::timeout:
      return "timeout (" + format_seconds(config.budget_seconds) + ")";
    case SingularRun::Status::error:
      break;
  }
  return "error: " + run->message;
}

// ---------------------------------------------------------------- one surface

/// Singular's eliminate on the ideal of `p`, under the same repeat and budget policy
/// as our side; nullopt when Singular is not run (--no-singular, or not found).
std::optional<SingularRun> time_singular(const Parametrization& p, const Config& config) {
  if (!config.singular) return std::nullopt;
  SingularOptions options;
  options.executable = config.singular_executable;
  options.timeout_seconds = config.budget_seconds;
  options.repeat = config.repeat;
  options.repeat_below_seconds = config.repeat_below_seconds;
  return time_singular_eliminate(p, options);
}

/// The answer check of one surface: our finished answers, Singular's when it
/// finished, else shared/bench/expected/NAME.txt when it exists. "agree" means
/// every one of ours is a rational multiple of the reference (and of each other).
/// "—" when there is nothing to compare with.
std::string check_answers(const std::vector<const ImplicitizeResult*>& ours, const std::optional<SingularRun>& theirs,
                          const Surface& surface, const Config& config) {
  if (ours.empty()) return "—";
  std::vector<std::string> reference;
  std::string source;
  if (theirs && theirs->status == SingularRun::Status::ok) {
    reference = theirs->generators;
  } else if (const auto expected = config.surfaces_dir / "expected" / (surface.name + ".txt");
             std::filesystem::exists(expected)) {
    reference = read_lines(expected);
    source = " (expected/)";
  }
  if (reference.empty()) {
    // No outside reference: the routes can still be checked against each other.
    if (ours.size() < 2) return "—";
    for (const ImplicitizeResult* r : ours) {
      if (r->implicit.monic() != ours.front()->implicit.monic()) {
        return "DIFFER (" + r->method + " vs " + ours.front()->method + ")";
      }
    }
    return "agree (routes only)";
  }
  for (const ImplicitizeResult* r : ours) {
    const std::string verdict = compare_with(r->implicit, reference);
    if (verdict != "agree") return verdict + (ours.size() > 1 ? " (" + r->method + ")" : "") + source;
  }
  return "agree" + source;
}

/// Everything printed about one surface in the default table.
struct Row {
  std::string name;
  std::string degree;
  std::string ours;
  std::string method = "—";  ///< the route our side took
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

/// Parses the surface's coordinates; nullopt (with the reason in `error`) when they
/// do not parse, which is a fault of the suite file.
std::optional<Parametrization> parse_surface(const Surface& surface, std::string& error) {
  try {
    return parse_parametrization(surface.x, surface.y, surface.z);
  } catch (const std::exception& e) {
    error = std::string("error: ") + e.what();
    return std::nullopt;
  }
}

Row measure_surface(const Surface& surface, const Config& config) {
  Row row;
  row.name = surface.name;
  row.degree = surface.degree > 0 ? std::to_string(surface.degree) : "?";
  const std::string limit = format_seconds(config.budget_seconds);

  std::string parse_error;
  const std::optional<Parametrization> parsed = parse_surface(surface, parse_error);
  if (!parsed) {
    row.our_status = parse_error;
    row.failed = true;
    return row;
  }
  const Parametrization& p = *parsed;

  const OurRun ours = time_implicitize(p, config.method, config);
  row.ours = our_time_cell(ours, config);
  switch (ours.status) {
    case OurRun::Status::ok:
      row.method = ours.result.method;
      row.verify = format_ms(median(ours.verify_ms));
      row.our_status = "ok";
      if (surface.degree > 0 && ours.result.degree != surface.degree) {
        row.our_status = "ok, degree " + std::to_string(ours.result.degree);
        row.failed = true;
      }
      break;
    case OurRun::Status::time_limit:
      row.our_status = "time_limit (" + limit + ")";
      break;
    case OurRun::Status::base_points:
      // Only --method resultant refuses; that is the route's documented answer.
      row.our_status = "refused: base_points";
      break;
    case OurRun::Status::error:
      row.our_status = "error: " + ours.message;
      row.failed = true;
      break;
  }

  const std::optional<SingularRun> theirs = time_singular(p, config);
  row.singular = singular_time_cell(theirs, config);
  row.singular_status = singular_status_cell(theirs, config);
  if (theirs && theirs->status == SingularRun::Status::error) row.failed = true;
  row.runs = std::to_string(ours.times_ms.size()) + " / " +
             (theirs ? std::to_string(theirs->times_ms.size()) : std::string("—"));

  row.ratio = format_ratio_cell(wall_term(ours, config), wall_term(theirs, config));
  row.cpu_ratio = format_ratio_cell(cpu_term(ours), cpu_term(theirs));
  const bool our_ok = ours.status == OurRun::Status::ok;
  const RatioTerm their_wall = wall_term(theirs, config);
  const double our_ms = our_ok ? median(ours.times_ms) : 0;
  row.meets_target =
      our_ok && (our_ms < 5 || (their_wall.kind == RatioTerm::Kind::finished && our_ms <= 3 * their_wall.ms) ||
                 their_wall.kind == RatioTerm::Kind::stopped);

  row.check = our_ok ? check_answers({&ours.result}, theirs, surface, config) : "—";
  if (row.check.rfind("DIFFER", 0) == 0) row.failed = true;
  return row;
}

/// Everything printed about one surface in the --routes table.
struct RoutesRow {
  std::string name;
  std::string degree;
  std::string groebner;              ///< time of the Gröbner route
  std::string resultant;             ///< time of the resultant route, or "base points"
  std::string resultant_matrix;      ///< formulation, matrix size and primes of the resultant route
  std::string interpolation;         ///< time of the interpolation route
  std::string interpolation_matrix;  ///< degree found / bound, matrix size and primes of it
  std::string automatic;             ///< time of auto
  std::string auto_route;            ///< the route auto took
  std::string singular;
  std::string auto_vs_singular;      ///< wall times
  std::string auto_cpu_vs_singular;  ///< CPU times (auto's counts every thread)
  std::string auto_vs_best;          ///< auto / min(groebner, resultant, interpolation), wall times
  std::string runs;                  ///< runs of groebner / resultant / interpolation / auto / Singular
  std::string check;
  bool failed = false;  ///< an answer differed, had the wrong degree, or a run failed
};

/// "dixon 8×8, 3 primes": how the auxiliary resultant was computed.
std::string describe_resultant(const AuxiliaryResultantStats& stats) {
  std::string text = std::string(to_string(stats.formulation)) + " " + std::to_string(stats.matrix_size) + "×" +
                     std::to_string(stats.matrix_size);
  const std::size_t primes = stats.determinant.primes;
  return text + ", " + std::to_string(primes) + (primes == 1 ? " prime" : " primes");
}

/// "degree 2 of 4, 10 columns, 3 primes": what the interpolation route solved.
std::string describe_interpolation(const InterpolationStats& stats) {
  return "degree " + std::to_string(stats.degree) + " of " + std::to_string(stats.degree_bound) + ", " +
         std::to_string(stats.columns) + " columns, " + std::to_string(stats.primes) +
         (stats.primes == 1 ? " prime" : " primes");
}

RoutesRow measure_routes(const Surface& surface, const Config& config) {
  RoutesRow row;
  row.name = surface.name;
  row.degree = surface.degree > 0 ? std::to_string(surface.degree) : "?";

  std::string parse_error;
  const std::optional<Parametrization> parsed = parse_surface(surface, parse_error);
  if (!parsed) {
    row.check = parse_error;
    row.failed = true;
    return row;
  }
  const Parametrization& p = *parsed;

  const OurRun groebner = time_implicitize(p, ImplicitizationMethod::groebner, config);
  const OurRun resultant = time_implicitize(p, ImplicitizationMethod::resultant, config);
  const OurRun interpolation = time_implicitize(p, ImplicitizationMethod::interpolation, config);
  const OurRun automatic = time_implicitize(p, ImplicitizationMethod::automatic, config);
  const std::optional<SingularRun> theirs = time_singular(p, config);

  row.groebner = our_time_cell(groebner, config);
  row.resultant = our_time_cell(resultant, config);
  row.resultant_matrix = resultant.status == OurRun::Status::ok && resultant.result.resultant_stats
                             ? describe_resultant(*resultant.result.resultant_stats)
                             : "—";
  row.interpolation = our_time_cell(interpolation, config);
  row.interpolation_matrix = interpolation.status == OurRun::Status::ok && interpolation.result.interpolation_stats
                                 ? describe_interpolation(*interpolation.result.interpolation_stats)
                                 : "—";
  row.automatic = our_time_cell(automatic, config);
  row.auto_route = automatic.status == OurRun::Status::ok ? automatic.result.method : "—";
  row.singular = singular_time_cell(theirs, config);

  row.auto_vs_singular = format_ratio_cell(wall_term(automatic, config), wall_term(theirs, config));
  row.auto_cpu_vs_singular = format_ratio_cell(cpu_term(automatic), cpu_term(theirs));
  // The oracle's time: the fastest route that finished; when none did, the
  // budget is a lower bound for it only if one was stopped by it.
  RatioTerm best;
  for (const OurRun* route : {&groebner, &resultant, &interpolation}) {
    const RatioTerm term = wall_term(*route, config);
    if (term.kind == RatioTerm::Kind::finished && (best.kind != RatioTerm::Kind::finished || term.ms < best.ms)) {
      best = term;
    } else if (term.kind == RatioTerm::Kind::stopped && best.kind == RatioTerm::Kind::unavailable) {
      best = term;
    }
  }
  row.auto_vs_best = format_ratio_cell(wall_term(automatic, config), best);
  row.runs = std::to_string(groebner.times_ms.size()) + " / " + std::to_string(resultant.times_ms.size()) + " / " +
             std::to_string(interpolation.times_ms.size()) + " / " + std::to_string(automatic.times_ms.size()) + " / " +
             (theirs ? std::to_string(theirs->times_ms.size()) : std::string("—"));

  std::vector<const ImplicitizeResult*> answers;
  std::string problems;
  for (const OurRun* route : {&groebner, &resultant, &interpolation, &automatic}) {
    if (route->status == OurRun::Status::ok) {
      answers.push_back(&route->result);
      if (surface.degree > 0 && route->result.degree != surface.degree) {
        problems += "; " + route->result.method + " has degree " + std::to_string(route->result.degree);
      }
    } else if (route->status == OurRun::Status::error) {
      problems += "; error: " + route->message;
    }
  }
  // Base points are the resultant route's answer; for the others they would be a bug.
  if (groebner.status == OurRun::Status::base_points || interpolation.status == OurRun::Status::base_points ||
      automatic.status == OurRun::Status::base_points) {
    problems += "; base_points outside the resultant route";
  }
  if (theirs && theirs->status == SingularRun::Status::error) problems += "; Singular: " + theirs->message;
  row.check = check_answers(answers, theirs, surface, config) + problems;
  row.failed = !problems.empty() || row.check.rfind("DIFFER", 0) == 0;
  return row;
}

// ---------------------------------------------------------------- printing

/// A column: header (Markdown), header (text), width (text).
struct Column {
  const char* markdown;
  const char* text;
  std::size_t width;
};

/// The default table: our route of --method beside Singular.
const std::vector<Column> kColumns = {
    {"surface", "surface", 22},
    {"degree", "degree", 6},
    {"ours", "ours", 9},
    {"method", "method", 13},
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
  return {row.name,      row.degree, row.ours, row.method,     row.singular,        row.ratio,
          row.cpu_ratio, row.verify, row.runs, row.our_status, row.singular_status, row.check};
}

/// The --routes table: every route of ours beside Singular.
const std::vector<Column> kRoutesColumns = {
    {"surface", "surface", 22},
    {"degree", "degree", 6},
    {"groebner", "groebner", 11},
    {"resultant", "resultant", 11},
    {"resultant matrix", "matrix", 24},
    {"interpolation", "interp", 11},
    {"interpolation matrix", "interp matrix", 34},
    {"auto", "auto", 9},
    {"auto took", "auto took", 9},
    {"Singular", "Singular", 9},
    {"auto / Singular", "auto/Sing", 9},
    {"CPU auto / Singular", "CPU a/S", 7},
    {"auto / best route", "auto/best", 9},
    {"runs (g / r / i / a / S)", "runs g/r/i/a/S", 14},
    {"answers", "answers", 10},
};

std::vector<std::string> cells_of(const RoutesRow& row) {
  return {row.name,
          row.degree,
          row.groebner,
          row.resultant,
          row.resultant_matrix,
          row.interpolation,
          row.interpolation_matrix,
          row.automatic,
          row.auto_route,
          row.singular,
          row.auto_vs_singular,
          row.auto_cpu_vs_singular,
          row.auto_vs_best,
          row.runs,
          row.check};
}

// Columns count characters, not bytes: "µs" and "—" are several bytes in UTF-8.
std::size_t display_width(const std::string& text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

void print_cells(const std::vector<std::string>& cells, const std::vector<Column>& columns, bool markdown) {
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (markdown) {
      line += "| " + cells[i] + " ";
    } else {
      std::string cell = cells[i];
      if (const std::size_t width = display_width(cell); width < columns[i].width)
        cell.append(columns[i].width - width, ' ');
      line += (i ? "  " : "") + cell;
    }
  }
  if (markdown) line += "|";
  while (!line.empty() && line.back() == ' ') line.pop_back();
  std::cout << line << '\n' << std::flush;
}

void print_table_header(const std::string& suite, const std::vector<Column>& columns, bool markdown) {
  std::cout << '\n' << (markdown ? "### " : "== ") << suite << " surfaces" << (markdown ? "\n\n" : "\n");
  std::vector<std::string> header;
  for (const Column& column : columns) header.emplace_back(markdown ? column.markdown : column.text);
  print_cells(header, columns, markdown);
  if (markdown) print_cells(std::vector<std::string>(columns.size(), "---"), columns, true);
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
            << " times, median shown\n"
            << bullet
            << (config.routes ? std::string("ours: every route (groebner, resultant, interpolation, auto), each under "
                                            "that policy")
                              : "ours: --method " + std::string(method_name(config.method)))
            << '\n';

  std::string suite;
  int public_count = 0;
  std::vector<std::string> public_misses;
  bool failed = false;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const Surface& s = surfaces[i];
    if (s.suite != suite) {
      suite = s.suite;
      print_table_header(suite, config.routes ? kRoutesColumns : kColumns, config.markdown);
    }
    std::cerr << "[" << i + 1 << "/" << surfaces.size() << "] " << s.name << "\n";
    if (config.routes) {
      const RoutesRow row = measure_routes(s, effective);
      print_cells(cells_of(row), kRoutesColumns, config.markdown);
      failed = failed || row.failed;
      continue;  // the public target is about the default route, which --routes reports as "auto"
    }
    const Row row = measure_surface(s, effective);
    print_cells(cells_of(row), kColumns, config.markdown);
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
