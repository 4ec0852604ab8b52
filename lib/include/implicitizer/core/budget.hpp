#pragma once
/// \file
/// One object that every long loop consults: wall time, size, memory, work,
/// cancellation. Modelled on FLINT's `_with_limits` functions and mathicgb's stop
/// callback: the loop calls `check()` and the budget throws LimitExceeded naming the
/// limit.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <string>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/memory_account.hpp"
#include "implicitizer/core/progress.hpp"

namespace implicitizer {

/// Limits of one computation. Copies share the cancellation flag, the progress sink,
/// the memory account and the work counter, so a server can cancel work it handed to another thread and
/// every thread of one computation draws on one allowance.
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

  /// Gives the computation a memory account of `bytes` (0 = none). The threads that
  /// compute must be attached to it (MemoryScope(memory_account())) for it to count.
  Budget& set_max_memory(std::size_t bytes);
  /// The memory limit in bytes (0 = none).
  std::size_t max_memory() const { return memory_ ? memory_->limit_bytes() : 0; }
  /// The memory account (null when there is no memory limit).
  MemoryAccount* memory_account() const { return memory_.get(); }

  /// Starts a fresh work allowance of `units` (0 = none) for this budget and the
  /// copies made from it afterwards. Work is counted by the loops that charge_work(),
  /// in units of about equal cost (terms and coefficient limbs written, reduction
  /// steps, pairs examined: lib/src/groebner/reducer.hpp). Unlike wall time it does
  /// not depend on the machine's load, so a decision taken on it (auto's head starts)
  /// is the same on every run.
  Budget& set_max_work(std::uint64_t units);
  /// The work allowance (0 = none).
  std::uint64_t max_work() const { return max_work_; }
  /// Adds `units` to the work done; throws LimitExceeded (work) naming `where` once it
  /// passes the allowance. One relaxed atomic add.
  void charge_work(std::uint64_t units, const char* where) const;
  /// The work charged since set_max_work() (0 without an allowance).
  std::uint64_t work_done() const { return work_ ? work_->load(std::memory_order_relaxed) : 0; }

  // Caps on what a request states, checked before any algebra (0 = none): the
  // variables of a ring (identifiers of a request) and the polynomials of an ideal.

  /// Sets the variables cap (0 = none).
  Budget& set_max_variables(std::size_t variables);
  /// The variables cap (0 = none).
  std::size_t max_variables() const { return max_variables_; }
  /// Sets the polynomials cap (0 = none).
  Budget& set_max_polynomials(std::size_t polynomials);
  /// The polynomials cap (0 = none).
  std::size_t max_polynomials() const { return max_polynomials_; }
  /// Throws LimitExceeded (size) naming `what` and the cap if `count` variables pass
  /// max_variables().
  void check_variables(std::size_t count, const char* what) const;
  /// Throws LimitExceeded (size) naming `what` and the cap if `count` polynomials pass
  /// max_polynomials().
  void check_polynomials(std::size_t count, const char* what) const;

  /// Asks every holder of this budget (or a copy) to stop at its next check.
  void cancel() const { shared_->cancelled.store(true, std::memory_order_relaxed); }
  /// Whether cancel() was called.
  bool is_cancelled() const { return shared_->cancelled.load(std::memory_order_relaxed); }

  /// Throws LimitExceeded (cancelled, memory or time) naming `where` if the budget is
  /// spent. Cheap: two relaxed loads and one clock read.
  void check(const char* where) const;
  /// Throws LimitExceeded (size) naming `where` if `terms` exceeds the term limit,
  /// then does check(where).
  void check_terms(std::size_t terms, const char* where) const;
  /// Throws LimitExceeded (size) naming `where` and `describe()` ("the product of 1001
  /// and 1001 terms", called only then) if a result predicted to have `terms` terms
  /// would pass the term limit: the refusal comes before the result is built, not
  /// after. Then does check(where).
  template <typename Describe>
  void check_predicted_terms(std::size_t terms, const char* where, Describe describe) const {
    if (max_terms_ != 0 && terms > max_terms_) throw_predicted_terms(terms, where, describe());
    check(where);
  }

  /// A copy whose messages add "in `phase`" to the loop they name ("polynomial
  /// multiplication in the common denominator"), so that a step used by many phases
  /// says which one it served. `phase` must be a string literal (it is kept by
  /// address). The copy shares everything else with this budget.
  Budget in_phase(const char* phase) const;
  /// The phase in_phase() named, or null.
  const char* phase() const { return phase_; }

  /// Called while a std::bad_alloc is being handled: throws LimitExceeded (memory)
  /// naming `where` when this budget's memory account refused the allocation
  /// (memory_account.hpp), else rethrows the bad_alloc (the machine's memory itself
  /// ran out).
  [[noreturn]] void rethrow_bad_alloc(const char* where) const;

  /// Seconds left before the deadline (infinity when there is none).
  double seconds_left() const;
  /// Throws LimitExceeded (time) naming `where` when a step that cannot stop halfway
  /// (one of FLINT's eliminations), predicted to take `predicted_seconds`, would end
  /// past the deadline; the message says what `what` ("the kernel of 3000 columns")
  /// would take and what is left. Nothing without a deadline.
  void refuse_past_deadline(double predicted_seconds, const char* where, const std::string& what) const;

  /// The progress sink every copy of this budget shares: what the long loops last
  /// reported (core/progress.hpp). Never null.
  const ProgressSink& progress() const { return shared_->progress; }
  /// Reports an inner loop's `done` of `total` units (total 0: unknown) under `phase`,
  /// a string literal. Three relaxed stores.
  void report_step(const char* phase, std::uint64_t done, std::uint64_t total) const {
    shared_->progress.report_step(phase, done, total);
  }
  /// Reports an outer loop's `done` of `total` (0: unknown) under `phase`, a string literal.
  void report_stage(const char* phase, std::uint64_t done, std::uint64_t total) const {
    shared_->progress.report_stage(phase, done, total);
  }

 private:
  // `where`, and the phase when there is one: what every message names.
  std::string located(const char* where) const;
  [[noreturn]] void throw_predicted_terms(std::size_t terms, const char* where, const std::string& what) const;

  bool has_deadline_ = false;
  Clock::time_point deadline_{};
  double timeout_seconds_ = 0;
  std::size_t max_terms_ = 0;
  std::size_t max_variables_ = 0;
  std::size_t max_polynomials_ = 0;
  std::uint64_t max_work_ = 0;
  const char* phase_ = nullptr;                       // a string literal, or null
  std::shared_ptr<std::atomic<std::uint64_t>> work_;  // null without an allowance
  std::shared_ptr<MemoryAccount> memory_;             // null without a memory limit
  // What every copy shares from construction on, in one allocation: whoever holds any
  // copy (a server's job) can cancel the computation and watch its progress.
  struct Shared {
    std::atomic<bool> cancelled{false};
    ProgressSink progress;
  };
  std::shared_ptr<Shared> shared_;
};

/// Runs `compute()` with the calling thread charging `budget`'s memory account
/// (MemoryScope), an allocation that account refused becoming the budget's
/// LimitExceeded (memory). A server worker attaches its thread itself; the command
/// line runs each computation through this.
template <typename Compute>
auto compute_charging(const Budget& budget, Compute compute) -> decltype(compute()) {
  const MemoryScope scope(budget.memory_account());
  try {
    return compute();
  } catch (const std::bad_alloc&) {
    budget.rethrow_bad_alloc("the computation");
  }
}

}  // namespace implicitizer
