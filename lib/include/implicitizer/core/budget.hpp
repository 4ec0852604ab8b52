#pragma once
/// \file
/// One object that every long loop consults: wall time, size, cancellation.
/// Modelled on FLINT's `_with_limits` functions and mathicgb's stop callback:
/// the loop calls `check()` and the budget throws LimitExceeded naming the limit.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <string>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {

/// Limits of one computation. Copies share the cancellation flag, so a server can
/// cancel work it handed to another thread.
class Budget {
 public:
  using Clock = std::chrono::steady_clock;

  /// An unlimited budget (no deadline, no size limit), not cancelled.
  Budget();

  /// Returns a budget whose deadline is `seconds` from now (<= 0 means none).
  static Budget with_timeout(double seconds);

  /// Sets the wall-time deadline `seconds` from now; <= 0 removes it.
  Budget& set_timeout(double seconds);
  /// Sets the largest number of terms any intermediate polynomial may have (0 = none).
  Budget& set_max_terms(std::size_t terms);
  /// The term limit (0 = none).
  std::size_t max_terms() const { return max_terms_; }
  /// The timeout given at construction, in seconds (0 = none); for messages.
  double timeout_seconds() const { return timeout_seconds_; }

  /// Asks every holder of this budget (or a copy) to stop at its next check.
  void cancel() const { cancelled_->store(true, std::memory_order_relaxed); }
  /// Whether cancel() was called.
  bool is_cancelled() const { return cancelled_->load(std::memory_order_relaxed); }

  /// Throws LimitExceeded (time or cancelled) naming `where` if the budget is spent.
  /// Cheap: one relaxed load and one clock read.
  void check(const char* where) const;
  /// Throws LimitExceeded (size) naming `where` if `terms` exceeds the term limit,
  /// then does check(where).
  void check_terms(std::size_t terms, const char* where) const;

  /// Seconds left before the deadline (infinity when there is none).
  double seconds_left() const;

 private:
  bool has_deadline_ = false;
  Clock::time_point deadline_{};
  double timeout_seconds_ = 0;
  std::size_t max_terms_ = 0;
  std::shared_ptr<std::atomic<bool>> cancelled_;
};

}  // namespace implicitizer
