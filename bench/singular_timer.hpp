#pragma once
/// \file
/// Times Singular's `eliminate` on the ideal implicitize() eliminates from, so that a
/// benchmark compares the two in the same run on the same machine.
///
/// The script is the one every answer carries as reproduce.singular (reproduce.hpp:
/// the common-denominator formulation ⟨q_i·X_i − p_i, 1 − L·w⟩, L the lcm of the
/// denominators), with its last lines replaced by a loop that times `eliminate`
/// alone with Singular's wall-clock `rtimer` (and its CPU `timer`): process start-up, parsing the ring and
/// printing the answer are excluded, as parsing and printing are on our side.

#include <string>
#include <vector>

#include "implicitizer/implicitization/parametrization.hpp"

namespace implicitizer::bench {

/// How Singular is run.
struct SingularOptions {
  std::string executable = "Singular";  ///< found on PATH unless a path is given
  double timeout_seconds = 60;          ///< one `eliminate` longer than this is a timeout
  int repeat = 5;                       ///< runs when the first one is fast
  double repeat_below_seconds = 1;      ///< "fast": the first run took less than this
};

/// What one Singular process reported.
struct SingularRun {
  enum class Status {
    ok,       ///< eliminate finished within the timeout; `generators` holds its answer
    timeout,  ///< killed by `timeout`, or its first eliminate took longer than allowed
    error,    ///< Singular failed (message says how)
  };
  Status status = Status::error;
  std::vector<double> times_ms;         ///< wall time of each eliminate, in run order
  std::vector<double> cpu_ms;           ///< CPU time of each eliminate (Singular's `timer`:
                                        ///< 10 ms resolution, so only slow runs read well)
  double process_cpu_ms = 0;            ///< CPU time of the whole process, start-up included
                                        ///< (also known after a timeout)
  std::vector<std::string> generators;  ///< the elimination ideal as Singular prints it
  std::string message;                  ///< for `error`: Singular's complaint or the exit status
};

/// Whether `executable` runs (`executable --version` exits with status 0).
bool singular_available(const std::string& executable);

/// The first line `executable --version` prints, e.g.
/// "Singular for x86_64-Linux version 4.3.1 (4313, 64 bit) ..."; "" when it does not run.
std::string singular_version(const std::string& executable);

/// Runs eliminate on the ideal of `parametrization` once, then `repeat − 1` more times
/// when the first run took less than `repeat_below_seconds`, in one Singular process
/// under coreutils' `timeout`. Precondition: singular_available(options.executable).
SingularRun time_singular_eliminate(const Parametrization& parametrization, const SingularOptions& options);

}  // namespace implicitizer::bench
