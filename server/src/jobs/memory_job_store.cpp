#include "jobs/memory_job_store.hpp"

#include <algorithm>
#include <limits>
#include <tuple>
#include <vector>

namespace implicitizer::server {

namespace {

long long budget_after(std::size_t cap, std::size_t used) {
  if (cap == JobStorageLimits::kNone) return std::numeric_limits<long long>::max();
  return static_cast<long long>(cap) - static_cast<long long>(used);
}

}  // namespace

JobAdmission MemoryJobStore::insert(const JobRecord& job, std::size_t max_unfinished) {
  std::lock_guard lock(mutex_);
  if (job.status == JobStatus::queued) {
    std::size_t unfinished = 0, client_bytes = 0, all_bytes = 0;
    for (const auto& [id, entry] : jobs_) {
      if (is_finished(entry.job.status)) continue;
      all_bytes += job_stored_bytes(entry.job);
      if (entry.job.client == job.client) {
        ++unfinished;
        client_bytes += job_stored_bytes(entry.job);
      }
    }
    if (unfinished >= max_unfinished) return JobAdmission::client_job_cap;
    const std::size_t bytes = job_stored_bytes(job);
    if (budget_after(limits_.max_bytes_per_client, client_bytes) < static_cast<long long>(bytes)) {
      return JobAdmission::client_bytes_cap;
    }
    if (budget_after(limits_.max_bytes, all_bytes) < static_cast<long long>(bytes)) {
      return JobAdmission::store_bytes_cap;
    }
    queue_.push_back(job.id);
  }
  Entry& entry = jobs_[job.id];
  entry.job = job;
  if (is_finished(job.status)) std::string().swap(entry.job.request);
  entry.order = next_order_++;
  evict_over_limits(job.client, job.id);
  return JobAdmission::admitted;
}

void MemoryJobStore::evict_over_limits(const std::string& client, const std::string& keep) {
  evict_within(&client, keep, limits_.max_bytes_per_client, limits_.max_finished_per_client);
  evict_within(nullptr, keep, limits_.max_bytes, limits_.max_finished);
}

void MemoryJobStore::evict_within(const std::string* client, const std::string& keep, std::size_t max_bytes,
                                  std::size_t max_finished) {
  if (max_bytes == JobStorageLimits::kNone && max_finished == JobStorageLimits::kNone) return;
  std::size_t held = 0;  // bytes that stay whatever is evicted: unfinished jobs and `keep`
  std::size_t kept_finished = 0;
  std::vector<const Entry*> finished;
  for (const auto& [id, entry] : jobs_) {
    if (client != nullptr && entry.job.client != *client) continue;
    if (!is_finished(entry.job.status) || id == keep) {
      held += job_stored_bytes(entry.job);
      if (is_finished(entry.job.status)) ++kept_finished;
    } else {
      finished.push_back(&entry);
    }
  }
  std::size_t finished_bytes = 0;
  for (const Entry* entry : finished) finished_bytes += job_stored_bytes(entry->job);
  if (budget_after(max_bytes, held) >= static_cast<long long>(finished_bytes) &&
      budget_after(max_finished, kept_finished) >= static_cast<long long>(finished.size())) {
    return;  // within both caps: nothing to order
  }
  std::sort(finished.begin(), finished.end(), [](const Entry* a, const Entry* b) {
    return std::tie(a->job.finished_at_ms, a->order) > std::tie(b->job.finished_at_ms, b->order);
  });
  std::vector<std::size_t> bytes;
  for (const Entry* entry : finished) bytes.push_back(job_stored_bytes(entry->job));
  const std::size_t first =
      first_evicted(bytes, budget_after(max_bytes, held), budget_after(max_finished, kept_finished));
  std::vector<std::string> evicted;
  for (std::size_t i = first; i < finished.size(); ++i) evicted.push_back(finished[i]->job.id);
  for (const std::string& id : evicted) jobs_.erase(id);
}

std::optional<JobRecord> MemoryJobStore::find(const std::string& id) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return std::nullopt;
  return it->second.job;
}

std::optional<JobRecord> MemoryJobStore::claim_next(std::int64_t now_ms) {
  std::lock_guard lock(mutex_);
  while (!queue_.empty()) {
    const std::string id = std::move(queue_.front());
    queue_.pop_front();
    const auto it = jobs_.find(id);
    if (it == jobs_.end() || it->second.job.status != JobStatus::queued) continue;  // cancelled meanwhile
    it->second.job.status = JobStatus::running;
    it->second.job.started_at_ms = now_ms;
    return it->second.job;
  }
  return std::nullopt;
}

bool MemoryJobStore::finish(const std::string& id, JobStatus status, const std::optional<JobResult>& result,
                            std::int64_t finished_at_ms) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second.job.status != JobStatus::running) return false;
  JobRecord& job = it->second.job;
  job.status = status;
  job.result = result;
  job.finished_at_ms = finished_at_ms;
  std::string().swap(job.request);  // frees its buffer, which clear() and assigning "" keep
  evict_over_limits(job.client, id);
  return true;
}

bool MemoryJobStore::cancel_queued(const std::string& id, std::int64_t finished_at_ms) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second.job.status != JobStatus::queued) return false;
  JobRecord& job = it->second.job;
  job.status = JobStatus::cancelled;
  job.finished_at_ms = finished_at_ms;
  std::string().swap(job.request);
  evict_over_limits(job.client, id);
  return true;
}

bool MemoryJobStore::remove_finished(const std::string& id) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || !is_finished(it->second.job.status)) return false;
  jobs_.erase(it);
  return true;
}

std::size_t MemoryJobStore::count_unfinished(const std::string& client) {
  std::lock_guard lock(mutex_);
  return static_cast<std::size_t>(std::count_if(jobs_.begin(), jobs_.end(), [&](const auto& entry) {
    return entry.second.job.client == client && !is_finished(entry.second.job.status);
  }));
}

std::size_t MemoryJobStore::count_unfinished() {
  std::lock_guard lock(mutex_);
  return static_cast<std::size_t>(std::count_if(
      jobs_.begin(), jobs_.end(), [](const auto& entry) { return !is_finished(entry.second.job.status); }));
}

std::size_t MemoryJobStore::remove_finished_before(std::int64_t cutoff_ms) {
  std::lock_guard lock(mutex_);
  return std::erase_if(jobs_, [cutoff_ms](const auto& entry) {
    return is_finished(entry.second.job.status) && entry.second.job.finished_at_ms < cutoff_ms;
  });
}

}  // namespace implicitizer::server
