#include "trace_followers.hpp"

namespace implicitizer::detail {

TraceFollowers::TraceFollowers(const Ring& ring, const F4Trace& trace, std::vector<std::uint64_t> primes,
                               Prepare prepare, const Budget& budget)
    : ring_(ring),
      trace_(trace),
      primes_(std::move(primes)),
      prepare_(std::move(prepare)),
      budget_(budget),
      account_(current_memory_account()),
      thread_([this] { follow(); }) {}

TraceFollowers::~TraceFollowers() {
  if (thread_.joinable()) thread_.join();
}

TraceFollowers::Followed TraceFollowers::stop() {
  if (thread_.joinable()) thread_.join();
  if (error_) std::rethrow_exception(error_);
  followed_.untaken.assign(primes_.begin() + static_cast<long>(taken_), primes_.end());
  return std::move(followed_);
}

void TraceFollowers::follow() {
  const MemoryScope scope(account_);
  std::vector<F4Trace::Replay>& replays = followed_.replays;
  try {
    while (!trace_.closed()) {
      const std::uint32_t seen = trace_.publications();
      // The replay furthest behind: when it has no step to take, neither has any other.
      F4Trace::Replay* behind = nullptr;
      for (F4Trace::Replay& r : replays) {
        if (!r.left_path() && (behind == nullptr || r.steps() < behind->steps())) behind = &r;
      }
      const F4Trace::StepResult result =
          behind != nullptr ? trace_.replay_step(ring_, *behind, budget_) : F4Trace::StepResult::not_yet;
      if (result == F4Trace::StepResult::replayed || result == F4Trace::StepResult::left_path) continue;
      if (result == F4Trace::StepResult::end) break;
      // Every replay has caught up with the learning run: begin the next prime, or
      // wait for the next step.
      if (taken_ < primes_.size()) {
        const std::uint64_t prime = primes_[taken_++];
        if (std::optional<std::vector<ModPolynomial>> generators = prepare_(prime)) {
          replays.emplace_back(prime, std::move(*generators));
        } else {
          followed_.bad.push_back(prime);
        }
        continue;
      }
      trace_.wait_for_publication(seen);
    }
  } catch (...) {
    error_ = std::current_exception();
  }
}

}  // namespace implicitizer::detail
