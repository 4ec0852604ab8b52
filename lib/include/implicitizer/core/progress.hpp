#pragma once
/// \file
/// How far a long computation has got, for whoever watches it (the server's jobs).
/// The loops that know a fraction report one (primes lifted, S-pairs left, matrix rows
/// reduced); the others name their phase. Written from hot loops, so writing is a few
/// relaxed atomic stores and never a lock; a reader may see one report's phase with
/// the next report's counts, which is harmless for a progress bar.

#include <atomic>
#include <cstdint>

namespace implicitizer {

/// One report: a phase and, when the loop knows them, the units done of a total.
struct ProgressReport {
  const char* phase = nullptr;  ///< a string literal naming the loop; null before any report
  std::uint64_t done = 0;       ///< units done of `total`
  std::uint64_t total = 0;      ///< 0 when the loop does not know how many units there are

  /// done / total in [0, 1], or a negative value when the total is unknown.
  double fraction() const {
    if (total == 0) return -1;
    return done >= total ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
  }
};

/// The latest progress of one computation, at two levels: the outer stage (a modular
/// computation's primes) and the inner step (one prime's S-pairs or matrix rows), so
/// that an inner loop's reports do not hide the outer count. Shared by every copy of
/// the computation's Budget (Budget::progress()).
class ProgressSink {
 public:
  /// Records the inner step. `phase` must be a string literal (it is kept by address).
  void report_step(const char* phase, std::uint64_t done, std::uint64_t total) { store(step_, phase, done, total); }
  /// Records the outer stage; `phase` must be a string literal.
  void report_stage(const char* phase, std::uint64_t done, std::uint64_t total) { store(stage_, phase, done, total); }

  /// The latest inner step.
  ProgressReport step() const { return load(step_); }
  /// The latest outer stage (phase null when no loop reported one).
  ProgressReport stage() const { return load(stage_); }

 private:
  struct Slot {
    std::atomic<const char*> phase{nullptr};
    std::atomic<std::uint64_t> done{0};
    std::atomic<std::uint64_t> total{0};
  };
  static void store(Slot& slot, const char* phase, std::uint64_t done, std::uint64_t total) {
    slot.phase.store(phase, std::memory_order_relaxed);
    slot.done.store(done, std::memory_order_relaxed);
    slot.total.store(total, std::memory_order_relaxed);
  }
  static ProgressReport load(const Slot& slot) {
    return {slot.phase.load(std::memory_order_relaxed), slot.done.load(std::memory_order_relaxed),
            slot.total.load(std::memory_order_relaxed)};
  }

  Slot step_;
  Slot stage_;
};

}  // namespace implicitizer
