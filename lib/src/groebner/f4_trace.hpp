#pragma once
// Private to the groebner module: F4 with a trace (Traverso 1988, "Gröbner trace
// algorithms"; the "learning" of Giac's and msolve's modular F4). The multi-modular
// route runs F4 once per prime on the same generators, and for all but finitely many
// primes every run takes the same path: the same pairs, the same matrices, the same
// rows reducing to zero. The first prime's run records that path; the others replay
// it with their own coefficients and skip what the record says is wasted:
//
// - the pair queue and its criteria (the steps' matrices are known),
// - symbolic preprocessing (each row is stored as basis index and columns),
// - every row that reduced to zero, and every pivot that no remaining row reaches
//   (on the classic ideals about four rows in five reduce to zero).
// - the symbolic preprocessing of the final interreduction (f4_interreduce.hpp),
//   when the basis has the learned prime's supports.
//
// A replay checks what it can: each step must produce new rows with the recorded
// leading columns, in order, or it gives up and the prime is run in full. What it
// cannot check is a skipped row that would not have reduced to zero modulo this
// prime; then its basis is wrong. That happens only for the finitely many primes on
// which the two runs differ, and the route never trusts a basis modulo p anyway: a
// candidate must agree with further primes and, by default, is proven over ℚ
// (modular_groebner.hpp); the driver drops the trace when a candidate is rejected.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "f4_engine.hpp"
#include "f4_interreduce.hpp"
#include "f4_matrix.hpp"
#include "f4_row_echelon.hpp"

namespace implicitizer::detail {

// The path of one F4 run: per step, the rows that mattered.
//
// The steps are published as the learning run records them, so that other primes
// can replay a step as soon as it is recorded (trace_followers.hpp): the learning
// thread appends, other threads read the steps it has linked, without a lock (a
// follower waiting on a lock the learner needs would make the learner wait on the
// follower). Everything else the learning run writes (finish(), interreduction())
// is read only after close().
class F4Trace {
  struct Step;

 public:
  F4Trace() = default;
  F4Trace(const F4Trace&) = delete;
  F4Trace& operator=(const F4Trace&) = delete;

  // Called by the learning run before the first step: the non-zero generators it
  // starts from (the basis's first elements).
  void start(std::size_t generators) { generators_ = generators; }
  // One step: its matrix and what the echelon form found (before the new rows are
  // sorted and join the basis). Published to replays at once; then `after_step`, if
  // set, is called on the learning thread.
  void record_step(const Ring& ring, const MacaulayMatrix& matrix, const EchelonResult& echelon);
  // The end of the run: the indices of the elements of the minimal basis.
  void finish(std::vector<std::size_t> minimal_basis) {
    minimal_basis_ = std::move(minimal_basis);
    complete_ = true;
  }
  // The learning run and its caller are done with the trace (after the
  // interreduction's plan is recorded), whether the run ended with a basis or not:
  // no step follows. Wakes every thread waiting for a step, and forgets `after_step`
  // (it may refer to the caller's frame).
  void close();
  // Whether close() was called.
  bool closed() const { return closed_.load(std::memory_order_acquire); }
  // Whether the learning run ended with a basis (not the unit ideal, not stopped).
  // Read after close() by any thread but the learning one.
  bool complete() const { return complete_; }
  // Called on the learning thread after each step is published (the modular driver
  // starts followers once the run has taken long enough to be worth a thread).
  void set_after_step(std::function<void()> after_step) { after_step_ = std::move(after_step); }

  // The final interreduction's matrix, recorded by the learning run's caller after
  // F4 (f4_interreduce.hpp), and replayed by the other primes': part of the path.
  InterreductionPlan& interreduction() { return interreduction_; }
  const InterreductionPlan& interreduction() const { return interreduction_; }

  // One prime's progress along the trace: its basis so far and the last step it
  // replayed.
  class Replay {
   public:
    // `generators`: monic, modulo `prime`, the same polynomials as the learning run's
    // modulo another prime.
    Replay(std::uint64_t prime, std::vector<ModPolynomial> generators);

    std::uint64_t prime() const { return modulus_.n; }
    // The steps replayed so far.
    std::size_t steps() const { return steps_; }
    // Whether a step gave other new rows than the learning run's: the prime is to be
    // run in full.
    bool left_path() const { return left_path_; }

   private:
    friend class F4Trace;
    nmod_t modulus_;
    std::vector<ModPolynomial> basis_;
    const Step* last_ = nullptr;  // the last step replayed
    std::size_t steps_ = 0;
    bool left_path_ = false;
    BuchbergerStats stats_;  // rows and work, as F4 counts them
  };

  enum class StepResult {
    replayed,   // the next step was replayed
    not_yet,    // the learning run has not recorded it yet
    end,        // the trace is closed and every step replayed
    left_path,  // the step gave other rows (now, or at an earlier call)
  };
  // Replays the next step of `replay` if the learning run has recorded it. Charges and
  // checks `budget` as F4 does.
  StepResult replay_step(const Ring& ring, Replay& replay, const Budget& budget) const;
  // The number of publications (steps and close) so far, and a wait until there are
  // more than `seen`: how a replay that caught up with the learning run waits.
  std::uint32_t publications() const { return publications_.load(std::memory_order_acquire); }
  void wait_for_publication(std::uint32_t seen) const { publications_.wait(seen, std::memory_order_acquire); }
  // Replays what is left of `replay` on a closed trace: the run's outcome, or nullopt
  // when it left the path or the learning run ended without a basis. Counts the
  // replay's rows and work (all of its steps) in `stats`.
  std::optional<F4Outcome> replay(const Ring& ring, Replay& replay, const Budget& budget, BuchbergerStats& stats) const;

  // The run's outcome modulo `arithmetic`'s prime on `generators` (monic, the same
  // polynomials as the learning run's modulo another prime), or nullopt when the
  // replay leaves the recorded path: every step of a closed trace, one after the
  // other. Charges and checks `budget` as F4 does; counts rows and work in `stats`.
  std::optional<F4Outcome> replay(const Ring& ring, const ModularArithmetic& arithmetic,
                                  std::vector<ModPolynomial> generators, const Budget& budget,
                                  BuchbergerStats& stats) const;

 private:
  struct Row {
    std::size_t poly = 0;
    std::vector<std::uint32_t> columns;
  };
  struct Step {
    std::size_t columns = 0;
    std::vector<std::int32_t> column_monomials;
    std::vector<Row> pivots;
    std::vector<Row> to_reduce;               // the rows that gave new rows, in order
    std::vector<std::uint32_t> new_leads;     // the leading column of each new row, in order
    std::atomic<const Step*> next = nullptr;  // linked by the learning thread
  };

  std::size_t generators_ = 0;
  std::vector<std::unique_ptr<Step>> steps_;  // owned; touched by the learning thread only
  std::atomic<const Step*> first_ = nullptr;  // what replays follow, linked step after step
  std::atomic<bool> closed_ = false;
  std::atomic<std::uint32_t> publications_ = 0;
  std::function<void()> after_step_;
  std::vector<std::size_t> minimal_basis_;
  InterreductionPlan interreduction_;
  bool complete_ = false;
};

}  // namespace implicitizer::detail
