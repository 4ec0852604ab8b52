#include "metrics_registry.hpp"

#include <sstream>

namespace implicitizer::server {

const char* to_string(ComputationOutcome outcome) {
  switch (outcome) {
    case ComputationOutcome::ok:
      return "ok";
    case ComputationOutcome::input_error:
      return "input_error";
    case ComputationOutcome::no_single_equation:
      return "no_single_equation";
    case ComputationOutcome::tolerance_not_met:
      return "tolerance_not_met";
    case ComputationOutcome::time_limit:
      return "time_limit";
    case ComputationOutcome::size_limit:
      return "size_limit";
    case ComputationOutcome::memory_limit:
      return "memory_limit";
    case ComputationOutcome::cancelled:
      return "cancelled";
    case ComputationOutcome::failed:
      return "failed";
  }
  return "failed";
}

void MetricsRegistry::Histogram::observe(double seconds) {
  for (std::size_t i = 0; i < kBuckets.size(); ++i) {
    if (seconds <= kBuckets[i]) {
      ++buckets[i];
      break;
    }
  }
  ++count;
  sum += seconds;
}

void MetricsRegistry::record_request(const std::string& endpoint, unsigned status, double seconds) {
  std::lock_guard lock(mutex_);
  ++requests_[{endpoint, status}];
  latency_[endpoint].observe(seconds);
}

void MetricsRegistry::record_computation(const std::string& endpoint, ComputationOutcome outcome, double seconds) {
  std::lock_guard lock(mutex_);
  ++computations_[{endpoint, outcome}];
  computation_time_[endpoint].observe(seconds);
}

void MetricsRegistry::record_open() {
  std::lock_guard lock(mutex_);
  ++connections_opened_;
}

void MetricsRegistry::record_close() {
  std::lock_guard lock(mutex_);
  ++connections_closed_;
}

std::uint64_t MetricsRegistry::cancelled_computations() const {
  std::lock_guard lock(mutex_);
  std::uint64_t total = 0;
  for (const auto& [key, n] : computations_) {
    if (key.second == ComputationOutcome::cancelled) total += n;
  }
  return total;
}

namespace {

void write_header(std::ostringstream& out, const char* name, const char* type, const char* help) {
  out << "# HELP " << name << ' ' << help << "\n# TYPE " << name << ' ' << type << '\n';
}

template <typename Histogram>
void write_histogram(std::ostringstream& out, const char* name, const std::string& endpoint, const Histogram& h,
                     const auto& bounds) {
  std::uint64_t cumulative = 0;
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    cumulative += h.buckets[i];
    out << name << "_bucket{endpoint=\"" << endpoint << "\",le=\"" << bounds[i] << "\"} " << cumulative << '\n';
  }
  out << name << "_bucket{endpoint=\"" << endpoint << "\",le=\"+Inf\"} " << h.count << '\n';
  out << name << "_sum{endpoint=\"" << endpoint << "\"} " << h.sum << '\n';
  out << name << "_count{endpoint=\"" << endpoint << "\"} " << h.count << '\n';
}

}  // namespace

std::string MetricsRegistry::render(const MetricsGauges& g) const {
  std::ostringstream out;
  std::lock_guard lock(mutex_);
  write_header(out, "implicitizer_http_requests_total", "counter", "HTTP requests answered, by endpoint and status.");
  for (const auto& [key, n] : requests_) {
    out << "implicitizer_http_requests_total{endpoint=\"" << key.first << "\",status=\"" << key.second << "\"} " << n
        << '\n';
  }
  write_header(out, "implicitizer_http_request_duration_seconds", "histogram",
               "Time from a request read to its response written.");
  for (const auto& [endpoint, h] : latency_) {
    write_histogram(out, "implicitizer_http_request_duration_seconds", endpoint, h, kBuckets);
  }
  write_header(out, "implicitizer_computations_total", "counter",
               "Computations run by the worker pool, by endpoint and outcome.");
  for (const auto& [key, n] : computations_) {
    out << "implicitizer_computations_total{endpoint=\"" << key.first << "\",outcome=\"" << to_string(key.second)
        << "\"} " << n << '\n';
  }
  std::uint64_t cancelled = 0;
  for (const auto& [key, n] : computations_) {
    if (key.second == ComputationOutcome::cancelled) cancelled += n;
  }
  write_header(out, "implicitizer_computations_cancelled_total", "counter",
               "Computations cancelled because the client disconnected or the server shut down.");
  out << "implicitizer_computations_cancelled_total " << cancelled << '\n';
  write_header(out, "implicitizer_computation_duration_seconds", "histogram",
               "Wall time of computations on the worker pool.");
  for (const auto& [endpoint, h] : computation_time_) {
    write_histogram(out, "implicitizer_computation_duration_seconds", endpoint, h, kBuckets);
  }
  write_header(out, "implicitizer_queue_depth", "gauge", "Computations waiting for a worker.");
  out << "implicitizer_queue_depth " << g.queue_depth << '\n';
  write_header(out, "implicitizer_queue_capacity", "gauge", "Most computations that may wait for a worker.");
  out << "implicitizer_queue_capacity " << g.queue_capacity << '\n';
  write_header(out, "implicitizer_queue_rejections_total", "counter", "Computations refused with 503 (pool full).");
  out << "implicitizer_queue_rejections_total " << g.queue_rejections << '\n';
  write_header(out, "implicitizer_workers_busy", "gauge", "Worker threads running a computation.");
  out << "implicitizer_workers_busy " << g.workers_busy << '\n';
  write_header(out, "implicitizer_workers", "gauge", "Worker threads.");
  out << "implicitizer_workers " << g.workers << '\n';
  write_header(out, "implicitizer_cache_hits_total", "counter", "Result cache lookups that found an answer.");
  out << "implicitizer_cache_hits_total " << g.cache_hits << '\n';
  write_header(out, "implicitizer_cache_misses_total", "counter", "Result cache lookups that did not.");
  out << "implicitizer_cache_misses_total " << g.cache_misses << '\n';
  write_header(out, "implicitizer_cache_evictions_total", "counter", "Results dropped from the cache for room.");
  out << "implicitizer_cache_evictions_total " << g.cache_evictions << '\n';
  write_header(out, "implicitizer_jobs_unfinished", "gauge", "Jobs queued or running (POST /v1/jobs).");
  out << "implicitizer_jobs_unfinished " << g.jobs_unfinished << '\n';
  write_header(out, "implicitizer_cache_entries", "gauge", "Results held in the cache.");
  out << "implicitizer_cache_entries " << g.cache_entries << '\n';
  write_header(out, "implicitizer_cache_capacity", "gauge", "Most results the cache holds.");
  out << "implicitizer_cache_capacity " << g.cache_capacity << '\n';
  write_header(out, "implicitizer_connections_open", "gauge", "Open client connections.");
  out << "implicitizer_connections_open " << (connections_opened_ - connections_closed_) << '\n';
  write_header(out, "implicitizer_connections_total", "counter", "Client connections accepted.");
  out << "implicitizer_connections_total " << connections_opened_ << '\n';
  return out.str();
}

}  // namespace implicitizer::server
