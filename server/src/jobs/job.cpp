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

std::string join_headers(const std::vector<std::pair<std::string, std::string>>& headers) {
  std::string out;
  for (const auto& [name, value] : headers) out += name + '\t' + value + '\n';
  return out;
}

std::vector<std::pair<std::string, std::string>> split_headers(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    if (const std::size_t tab = line.find('\t'); tab != std::string::npos) {
      out.emplace_back(line.substr(0, tab), line.substr(tab + 1));
    }
    start = end + 1;
  }
  return out;
}

bool is_finished(JobStatus status) { return status != JobStatus::queued && status != JobStatus::running; }

}  // namespace implicitizer::server
