#pragma once
// Private to the groebner module: replays of the first prime's F4 trace while the
// trace is still being learned (f4_trace.hpp).
//
// Why: the learning run is mostly one thread's work (the pair criteria, symbolic
// preprocessing, every matrix too small to share, f4_row_echelon.hpp), and it takes
// as long as many replays (docs/algorithms.md, "F4 modulo primes", has the
// measurements). Meanwhile the other core has nothing to do, while the multi-modular
// route will need those replays anyway. A follower thread replays further primes
// step by step behind the learning run, each step as soon as it is recorded; when
// every prime it follows has caught up, it takes the next prime, up to the primes it
// was given.
//
// The follower runs at the same priority as the learning run. Under the idle policy
// (SCHED_IDLE), or at the lowest nice value, it should have taken a core only when
// the learning run left one idle; on a machine otherwise idle it made no difference,
// and on one loaded by two other busy processes the driver waited for a starved
// follower to end its step (docs/algorithms.md, "F4 modulo primes", item 9, has the
// measurements). How far the follower gets is a matter of timing; what the driver
// does with it is not: each prime it hands over is finished like any replayed prime
// (replayed to the end, or run in full when it left the path).

#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <thread>
#include <vector>

#include "f4_trace.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/memory_account.hpp"

namespace implicitizer::detail {

class TraceFollowers {
 public:
  // The generators modulo a prime (monic), or nullopt when the prime divides a
  // leading coefficient (a bad prime, not replayed).
  using Prepare = std::function<std::optional<std::vector<ModPolynomial>>(std::uint64_t prime)>;

  // Starts following `trace`, which the calling thread is learning, on a thread of
  // its own: the primes are taken from `primes`, in order. The trace must be
  // closed before the follower is stopped or destroyed.
  TraceFollowers(const Ring& ring, const F4Trace& trace, std::vector<std::uint64_t> primes, Prepare prepare,
                 const Budget& budget);
  TraceFollowers(const TraceFollowers&) = delete;
  TraceFollowers& operator=(const TraceFollowers&) = delete;
  ~TraceFollowers();

  // What the follower did.
  struct Followed {
    std::vector<F4Trace::Replay> replays;  // begun, in the order of their primes
    std::vector<std::uint64_t> bad;        // primes that divided a leading coefficient
    std::vector<std::uint64_t> untaken;    // primes not begun, in order
  };
  // Once the trace is closed: waits for the follower to stop (after the step it is
  // replaying) and hands over its replays. Rethrows what stopped it (the budget).
  Followed stop();

 private:
  void follow();

  const Ring& ring_;
  const F4Trace& trace_;
  std::vector<std::uint64_t> primes_;
  Prepare prepare_;
  const Budget& budget_;
  MemoryAccount* account_;
  std::size_t taken_ = 0;  // primes_ begun or found bad
  Followed followed_;
  std::exception_ptr error_;
  std::thread thread_;  // last: started once everything it reads is set
};

}  // namespace implicitizer::detail
