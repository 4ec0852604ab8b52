#include "jobs/memory_job_store.hpp"

#include <algorithm>

namespace implicitizer::server {

bool MemoryJobStore::insert(const JobRecord& job, std::size_t max_unfinished) {
  std::lock_guard lock(mutex_);
  if (job.status == JobStatus::queued) {
    const auto unfinished = std::count_if(jobs_.begin(), jobs_.end(), [&](const auto& entry) {
      return entry.second.client == job.client && !is_finished(entry.second.status);
    });
    if (static_cast<std::size_t>(unfinished) >= max_unfinished) return false;
    queue_.push_back(job.id);
  }
  jobs_[job.id] = job;
  return true;
}

std::optional<JobRecord> MemoryJobStore::find(const std::string& id) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return std::nullopt;
  return it->second;
}

std::optional<JobRecord> MemoryJobStore::claim_next(std::int64_t now_ms) {
  std::lock_guard lock(mutex_);
  while (!queue_.empty()) {
    const std::string id = std::move(queue_.front());
    queue_.pop_front();
    const auto it = jobs_.find(id);
    if (it == jobs_.end() || it->second.status != JobStatus::queued) continue;  // cancelled meanwhile
    it->second.status = JobStatus::running;
    it->second.started_at_ms = now_ms;
    return it->second;
  }
  return std::nullopt;
}

bool MemoryJobStore::finish(const std::string& id, JobStatus status, const std::optional<JobResult>& result,
                            std::int64_t finished_at_ms) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second.status != JobStatus::running) return false;
  it->second.status = status;
  it->second.result = result;
  it->second.finished_at_ms = finished_at_ms;
  return true;
}

bool MemoryJobStore::cancel_queued(const std::string& id, std::int64_t finished_at_ms) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second.status != JobStatus::queued) return false;
  it->second.status = JobStatus::cancelled;
  it->second.finished_at_ms = finished_at_ms;
  return true;
}

bool MemoryJobStore::remove_finished(const std::string& id) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || !is_finished(it->second.status)) return false;
  jobs_.erase(it);
  return true;
}

std::size_t MemoryJobStore::count_unfinished(const std::string& client) {
  std::lock_guard lock(mutex_);
  return static_cast<std::size_t>(std::count_if(jobs_.begin(), jobs_.end(), [&](const auto& entry) {
    return entry.second.client == client && !is_finished(entry.second.status);
  }));
}

std::size_t MemoryJobStore::count_unfinished() {
  std::lock_guard lock(mutex_);
  return static_cast<std::size_t>(
      std::count_if(jobs_.begin(), jobs_.end(), [](const auto& entry) { return !is_finished(entry.second.status); }));
}

std::size_t MemoryJobStore::remove_finished_before(std::int64_t cutoff_ms) {
  std::lock_guard lock(mutex_);
  return std::erase_if(jobs_, [cutoff_ms](const auto& entry) {
    return is_finished(entry.second.status) && entry.second.finished_at_ms < cutoff_ms;
  });
}

}  // namespace implicitizer::server
