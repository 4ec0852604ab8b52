#pragma once
/// \file
/// Elapsed wall time for stats, logs and metrics, on the steady clock: one way to
/// write "milliseconds since the start of this phase".

#include <chrono>

namespace implicitizer {

/// Wall time since construction or the last restart().
class Stopwatch {
 public:
  /// Starts now.
  Stopwatch() : start_(Clock::now()) {}
  /// Starts again, now.
  void restart() { start_ = Clock::now(); }
  /// Milliseconds since the start.
  double elapsed_ms() const { return std::chrono::duration<double, std::milli>(Clock::now() - start_).count(); }
  /// Seconds since the start.
  double elapsed_seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

}  // namespace implicitizer
