#include "jobs/job_storage_limits.hpp"

namespace implicitizer::server {

std::size_t job_stored_bytes(const JobRecord& job) {
  std::size_t bytes = job.request.size();
  if (!job.result) return bytes;
  bytes += job.result->content_type.size() + job.result->body.size();
  // join_headers()'s length without building it: a tab and a newline per header.
  for (const auto& [name, value] : job.result->headers) bytes += name.size() + value.size() + 2;
  return bytes;
}

std::size_t first_evicted(const std::vector<std::size_t>& bytes_newest_first, long long bytes_budget,
                          long long count_budget) {
  long long sum = 0;
  for (std::size_t i = 0; i < bytes_newest_first.size(); ++i) {
    sum += static_cast<long long>(bytes_newest_first[i]);
    if (sum > bytes_budget || static_cast<long long>(i) + 1 > count_budget) return i;
  }
  return bytes_newest_first.size();
}

}  // namespace implicitizer::server
