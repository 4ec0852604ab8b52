#pragma once
/// \file
/// Counters and histograms of the server, rendered in Prometheus' text exposition
/// format (version 0.0.4) by GET /metrics. Labels are bounded: endpoints are route
/// names ("/v1/implicitize", "static", "other"), never raw paths.

#include <array>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>

namespace implicitizer::server {

/// What happened to one computation handed to the worker pool.
enum class ComputationOutcome {
  ok,
  input_error,
  no_single_equation,
  tolerance_not_met,
  time_limit,
  size_limit,
  memory_limit,
  cancelled,
  failed
};

/// Values read at scrape time from the pool and the cache.
struct MetricsGauges {
  std::size_t queue_depth = 0;         ///< computations waiting for a worker
  std::size_t queue_capacity = 0;      ///< most computations waiting
  std::size_t workers_busy = 0;        ///< computations running
  std::size_t workers = 0;             ///< worker threads
  std::uint64_t queue_rejections = 0;  ///< computations refused with 503
  std::size_t cache_entries = 0;       ///< results in the cache
  std::size_t cache_capacity = 0;      ///< most results in the cache
  std::uint64_t cache_hits = 0;        ///< lookups answered from the cache
  std::uint64_t cache_misses = 0;      ///< lookups that were not
  std::uint64_t cache_evictions = 0;   ///< results dropped for room
  std::size_t jobs_unfinished = 0;     ///< jobs queued or running (POST /v1/jobs)
};

/// Thread-safe registry of the server's counters and histograms.
class MetricsRegistry {
 public:
  /// Upper bounds (seconds) of the latency and computation-time histogram buckets.
  static constexpr std::array<double, 12> kBuckets = {0.001, 0.0025, 0.005, 0.01, 0.025, 0.05,
                                                      0.1,   0.25,   0.5,   1,    5,     30};

  /// One answered request: its endpoint label, status code and time from the end of
  /// reading to the end of writing.
  void record_request(const std::string& endpoint, unsigned status, double seconds);
  /// One computation run by a worker, with its wall time.
  void record_computation(const std::string& endpoint, ComputationOutcome outcome, double seconds);
  /// A connection accepted (for the open-connections gauge, paired with record_close).
  void record_open();
  /// A connection closed.
  void record_close();

  /// Computations that ended cancelled (client gone, or shutdown).
  std::uint64_t cancelled_computations() const;

  /// The whole exposition text.
  std::string render(const MetricsGauges& gauges) const;

 private:
  struct Histogram {
    std::array<std::uint64_t, kBuckets.size()> buckets{};  // non-cumulative counts
    std::uint64_t count = 0;
    double sum = 0;
    void observe(double seconds);
  };

  mutable std::mutex mutex_;
  std::map<std::pair<std::string, unsigned>, std::uint64_t> requests_;
  std::map<std::string, Histogram> latency_;
  std::map<std::pair<std::string, ComputationOutcome>, std::uint64_t> computations_;
  std::map<std::string, Histogram> computation_time_;
  std::uint64_t connections_opened_ = 0;
  std::uint64_t connections_closed_ = 0;
};

/// "ok", "input_error", "no_single_equation", "tolerance_not_met", "time_limit", "size_limit", "cancelled", "failed".
const char* to_string(ComputationOutcome outcome);

}  // namespace implicitizer::server
