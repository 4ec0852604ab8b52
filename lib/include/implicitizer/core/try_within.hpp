#pragma once
/// \file
/// A try with a work allowance: the shape of every head start of `auto` (a route runs
/// first within an allowance, and another takes over when the allowance, not the
/// caller's budget, stopped it). The allowance is work, not wall time, so which route
/// answers depends on the input alone, never on the machine's load.

#include <cstdint>
#include <optional>
#include <utility>

#include "implicitizer/core/budget.hpp"

namespace implicitizer {

/// Runs `attempt(trial)`, where `trial` is `budget` (its deadline, memory account,
/// limits and cancellation) with a fresh work allowance of `work` units. Returns its
/// result, or nullopt when the allowance ran out; every other limit propagates, so the
/// caller's own time limit, memory limit and cancellation stop everything and the
/// error names them.
template <typename Attempt>
auto try_within(const Budget& budget, std::uint64_t work, Attempt attempt)
    -> std::optional<decltype(attempt(std::declval<const Budget&>()))> {
  Budget trial = budget;
  trial.set_max_work(work);
  try {
    return attempt(static_cast<const Budget&>(trial));
  } catch (const LimitExceeded& e) {
    if (e.limit() != Limit::work) throw;
    return std::nullopt;
  }
}

}  // namespace implicitizer
