#include "jobs/job.hpp"

#include <array>

namespace implicitizer::server {

namespace {

constexpr std::array<std::pair<JobStatus, const char*>, 5> kNames{{{JobStatus::queued, "queued"},
                                                                   {JobStatus::running, "running"},
                                                                   {JobStatus::done, "done"},
                                                                   {JobStatus::failed, "failed"},
                                                                   {JobStatus::cancelled, "cancelled"}}};

}  // namespace

const char* to_string(JobStatus status) {
  for (const auto& [value, name] : kNames) {
    if (value == status) return name;
  }
  return "unknown";
}

std::optional<JobStatus> parse_job_status(std::string_view text) {
  for (const auto& [value, name] : kNames) {
    if (text == name) return value;
  }
  return std::nullopt;
}

bool is_finished(JobStatus status) { return status != JobStatus::queued && status != JobStatus::running; }

}  // namespace implicitizer::server
