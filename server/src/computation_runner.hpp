#pragma once
/// \file
/// How every computation is run on a worker, whether a synchronous request's or a
/// job's: under its budget's memory account, with what the library throws mapped to
/// the contract's error response, and its outcome counted in the metrics.

#include <functional>
#include <string>

#include "http_message.hpp"
#include "implicitizer/core/budget.hpp"
#include "metrics_registry.hpp"

namespace implicitizer::server {

/// What run_computation() learned besides the response.
struct ComputationRun {
  Response response;                                    ///< the answer, or the error it became
  ComputationOutcome outcome = ComputationOutcome::ok;  ///< for metrics and job states
};

/// Runs `run` on the calling thread charging `budget`'s memory account, after a
/// last budget check (a computation cancelled or timed out while it waited never
/// starts). Never throws: a library error becomes make_exception_response()'s
/// answer. Records the outcome and time under `endpoint` in `metrics`.
ComputationRun run_computation(const std::function<Response()>& run, const Budget& budget, MetricsRegistry& metrics,
                               const std::string& endpoint);

}  // namespace implicitizer::server
