#include "computation_runner.hpp"

#include "implicitizer/approximation/patch_approximation.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/stopwatch.hpp"

namespace implicitizer::server {

namespace {

ComputationOutcome classify(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const InputError&) {
    return ComputationOutcome::input_error;
  } catch (const NoSingleEquation&) {
    return ComputationOutcome::no_single_equation;
  } catch (const ToleranceNotMet&) {
    return ComputationOutcome::tolerance_not_met;
  } catch (const LimitExceeded& e) {
    switch (e.limit()) {
      case Limit::time:
        return ComputationOutcome::time_limit;
      case Limit::memory:
        return ComputationOutcome::memory_limit;
      case Limit::cancelled:
        return ComputationOutcome::cancelled;
      case Limit::size:
      case Limit::work:
        return ComputationOutcome::size_limit;
    }
    return ComputationOutcome::failed;
  } catch (const std::bad_alloc&) {
    return ComputationOutcome::memory_limit;
  } catch (...) {
    return ComputationOutcome::failed;
  }
}

}  // namespace

ComputationRun run_computation(const std::function<Response()>& run, const Budget& budget, MetricsRegistry& metrics,
                               const std::string& endpoint) {
  const Stopwatch timer;
  ComputationRun result;
  try {
    budget.check("the wait for a worker");  // timed out or cancelled while queued
    // The worker's allocations, and those of the threads it starts, count against
    // the budget's memory account.
    result.response = compute_charging(budget, [&run] { return run(); });
  } catch (...) {
    result.outcome = classify(std::current_exception());
    result.response = make_exception_response(std::current_exception());
  }
  metrics.record_computation(endpoint, result.outcome, timer.elapsed_seconds());
  return result;
}

}  // namespace implicitizer::server
