#include "jobs/redis_job_store.hpp"

#include <chrono>
#include <map>
#include <stdexcept>

namespace implicitizer::server {

namespace {

constexpr const char* kPrefix = "implicitizer:";
const std::string kQueue = std::string(kPrefix) + "jobs:queue";
const std::string kRunning = std::string(kPrefix) + "jobs:running";
const std::string kFinished = std::string(kPrefix) + "jobs:finished";

std::string job_key(const std::string& id) { return std::string(kPrefix) + "job:" + id; }
std::string client_key(const std::string& client) { return std::string(kPrefix) + "client:" + client; }

// ARGV: prefix, id, queued ("1"/"0"), finished_at_ms, client, max_unfinished, then
// field/value pairs. Returns 0 (nothing written) when a queued job's client is at its cap.
constexpr const char* kInsert = R"(
local key = ARGV[1] .. 'job:' .. ARGV[2]
local client = ARGV[1] .. 'client:' .. ARGV[5]
if ARGV[3] == '1' and redis.call('SCARD', client) >= tonumber(ARGV[6]) then return 0 end
redis.call('HSET', key, unpack(ARGV, 7))
if ARGV[3] == '1' then
  redis.call('LPUSH', KEYS[1], ARGV[2])
  redis.call('SADD', client, ARGV[2])
else
  redis.call('ZADD', KEYS[2], ARGV[4], ARGV[2])
end
return 1)";

// KEYS: queue, running. ARGV: prefix, now_ms, lease_until_ms. Returns the id or nil.
constexpr const char* kClaim = R"(
while true do
  local id = redis.call('RPOPLPUSH', KEYS[1], KEYS[2])
  if not id then return false end
  local key = ARGV[1] .. 'job:' .. id
  if redis.call('HGET', key, 'status') == 'queued' then
    redis.call('HSET', key, 'status', 'running', 'started_at_ms', ARGV[2], 'lease_until_ms', ARGV[3],
               'cancel_requested', '0')
    return id
  end
  redis.call('LREM', KEYS[2], 0, id)
end)";

// Lua shared by the scripts that end a job: moves `id` (hash `key`) from the list
// `from` to the finished set as `status` at `at`, and out of its client's set; drops
// its request (a result never needs it again).
const std::string kSettle = R"(
local function settle(prefix, key, id, from, finished, status, at)
  redis.call('HSET', key, 'status', status, 'finished_at_ms', at, 'request', '')
  redis.call('LREM', from, 0, id)
  redis.call('SREM', prefix .. 'client:' .. redis.call('HGET', key, 'client'), id)
  redis.call('ZADD', finished, at, id)
end
)";

// KEYS: running, finished. ARGV: prefix, id, status, finished_at_ms, has_result,
// http_status, content_type, headers, body.
const std::string kFinish = kSettle + R"(
local key = ARGV[1] .. 'job:' .. ARGV[2]
if redis.call('HGET', key, 'status') ~= 'running' then return 0 end
if ARGV[5] == '1' then
  redis.call('HSET', key, 'http_status', ARGV[6], 'content_type', ARGV[7], 'headers', ARGV[8], 'body', ARGV[9])
end
settle(ARGV[1], key, ARGV[2], KEYS[1], KEYS[2], ARGV[3], ARGV[4])
return 1)";

// KEYS: queue, finished. ARGV: prefix, id, finished_at_ms.
const std::string kCancelQueued = kSettle + R"(
local key = ARGV[1] .. 'job:' .. ARGV[2]
if redis.call('HGET', key, 'status') ~= 'queued' then return 0 end
settle(ARGV[1], key, ARGV[2], KEYS[1], KEYS[2], 'cancelled', ARGV[3])
return 1)";

// KEYS: finished. ARGV: prefix, id.
constexpr const char* kRemoveFinished = R"(
local key = ARGV[1] .. 'job:' .. ARGV[2]
local status = redis.call('HGET', key, 'status')
if status ~= 'done' and status ~= 'failed' and status ~= 'cancelled' then return 0 end
redis.call('DEL', key)
redis.call('ZREM', KEYS[1], ARGV[2])
return 1)";

// KEYS: finished. ARGV: prefix, cutoff_ms.
constexpr const char* kRemoveBefore = R"(
local ids = redis.call('ZRANGEBYSCORE', KEYS[1], '-inf', '(' .. ARGV[2])
for _, id in ipairs(ids) do redis.call('DEL', ARGV[1] .. 'job:' .. id) end
redis.call('ZREMRANGEBYSCORE', KEYS[1], '-inf', '(' .. ARGV[2])
return #ids)";

// ARGV: prefix, id.
constexpr const char* kRequestCancel = R"(
local key = ARGV[1] .. 'job:' .. ARGV[2]
if redis.call('HGET', key, 'status') ~= 'running' then return 0 end
redis.call('HSET', key, 'cancel_requested', '1')
return 1)";

// ARGV: prefix, id, lease_until_ms, then the p_* field/value pairs. Returns 1 when a
// cancel was requested.
constexpr const char* kHeartbeat = R"(
local key = ARGV[1] .. 'job:' .. ARGV[2]
if redis.call('HGET', key, 'status') ~= 'running' then return 0 end
redis.call('HSET', key, 'lease_until_ms', ARGV[3], unpack(ARGV, 4))
if redis.call('HGET', key, 'cancel_requested') == '1' then return 1 end
return 0)";

// KEYS: running, queue, finished. ARGV: prefix, now_ms. A job whose lease ran out
// goes back to the head of the queue (or is cancelled, if that was asked).
const std::string kRequeueExpired = kSettle + R"(
local n = 0
for _, id in ipairs(redis.call('LRANGE', KEYS[1], 0, -1)) do
  local key = ARGV[1] .. 'job:' .. id
  if redis.call('HGET', key, 'status') ~= 'running' then
    redis.call('LREM', KEYS[1], 0, id)
  elseif tonumber(redis.call('HGET', key, 'lease_until_ms') or '0') < tonumber(ARGV[2]) then
    if redis.call('HGET', key, 'cancel_requested') == '1' then
      settle(ARGV[1], key, id, KEYS[1], KEYS[3], 'cancelled', ARGV[2])
    else
      redis.call('LREM', KEYS[1], 0, id)
      redis.call('HSET', key, 'status', 'queued', 'lease_until_ms', '0')
      redis.call('RPUSH', KEYS[2], id)
    end
    n = n + 1
  end
end
return n)";

std::int64_t to_int(const std::map<std::string, std::string>& fields, const char* name) {
  const auto it = fields.find(name);
  if (it == fields.end() || it->second.empty()) return 0;
  try {
    return std::stoll(it->second);
  } catch (const std::exception&) {
    return 0;
  }
}

std::string field(const std::map<std::string, std::string>& fields, const char* name) {
  const auto it = fields.find(name);
  return it == fields.end() ? std::string() : it->second;
}

JobProgressView progress_of(const std::map<std::string, std::string>& fields) {
  JobProgressView p;
  p.phase = field(fields, "p_phase");
  if (const std::string f = field(fields, "p_fraction"); !f.empty()) p.fraction = std::stod(f);
  p.done = static_cast<std::uint64_t>(to_int(fields, "p_done"));
  p.total = static_cast<std::uint64_t>(to_int(fields, "p_total"));
  p.stage = field(fields, "p_stage");
  p.stage_done = static_cast<std::uint64_t>(to_int(fields, "p_stage_done"));
  p.stage_total = static_cast<std::uint64_t>(to_int(fields, "p_stage_total"));
  return p;
}

JobRecord job_of(const std::string& id, const std::map<std::string, std::string>& fields) {
  JobRecord job;
  job.id = id;
  job.kind = field(fields, "kind");
  job.request = field(fields, "request");
  job.client = field(fields, "client");
  job.status = parse_job_status(field(fields, "status")).value_or(JobStatus::failed);
  job.created_at_ms = to_int(fields, "created_at_ms");
  job.started_at_ms = to_int(fields, "started_at_ms");
  job.finished_at_ms = to_int(fields, "finished_at_ms");
  if (fields.count("http_status") != 0) {
    job.result = JobResult{static_cast<unsigned>(to_int(fields, "http_status")), field(fields, "content_type"),
                           split_headers(field(fields, "headers")), field(fields, "body")};
  }
  job.progress = progress_of(fields);
  job.cancel_requested = field(fields, "cancel_requested") == "1";
  return job;
}

}  // namespace

RedisJobStore::RedisJobStore(std::string host, int port, std::chrono::milliseconds lease)
    : lease_ms_(lease.count()), redis_(std::move(host), port) {}

JobAdmission RedisJobStore::insert(const JobRecord& job, std::size_t max_unfinished) {
  const bool queued = job.status == JobStatus::queued;
  std::vector<std::string> args{kPrefix,
                                job.id,
                                queued ? "1" : "0",
                                std::to_string(job.finished_at_ms),
                                job.client,
                                std::to_string(max_unfinished),
                                "kind",
                                job.kind,
                                "request",
                                queued ? job.request : std::string(),
                                "client",
                                job.client,
                                "status",
                                to_string(job.status),
                                "created_at_ms",
                                std::to_string(job.created_at_ms),
                                "started_at_ms",
                                std::to_string(job.started_at_ms),
                                "finished_at_ms",
                                std::to_string(job.finished_at_ms)};
  if (job.result) {
    const std::vector<std::string> result{
        "http_status", std::to_string(job.result->http_status), "content_type", job.result->content_type,
        "headers",     join_headers(job.result->headers),       "body",         job.result->body};
    args.insert(args.end(), result.begin(), result.end());
  }
  return redis_.eval_integer(kInsert, {kQueue, kFinished}, args) == 1 ? JobAdmission::admitted
                                                                       : JobAdmission::client_job_cap;
}

std::optional<JobRecord> RedisJobStore::find(const std::string& id) {
  const RedisConnection::Reply reply = redis_.command({"HGETALL", job_key(id)});
  if (reply->type != REDIS_REPLY_ARRAY || reply->elements == 0) return std::nullopt;
  std::map<std::string, std::string> fields;
  for (std::size_t i = 0; i + 1 < reply->elements; i += 2) {
    fields[std::string(reply->element[i]->str, reply->element[i]->len)] =
        std::string(reply->element[i + 1]->str, reply->element[i + 1]->len);
  }
  return job_of(id, fields);
}

std::optional<JobRecord> RedisJobStore::claim_next(std::int64_t now_ms) {
  const RedisConnection::Reply reply = redis_.command(
      {"EVAL", kClaim, "2", kQueue, kRunning, kPrefix, std::to_string(now_ms), std::to_string(now_ms + lease_ms_)});
  if (reply->type != REDIS_REPLY_STRING) return std::nullopt;
  return find(std::string(reply->str, reply->len));
}

bool RedisJobStore::finish(const std::string& id, JobStatus status, const std::optional<JobResult>& result,
                           std::int64_t finished_at_ms) {
  std::vector<std::string> args{kPrefix, id, to_string(status), std::to_string(finished_at_ms), result ? "1" : "0"};
  if (result) {
    args.insert(args.end(), {std::to_string(result->http_status), result->content_type, join_headers(result->headers),
                             result->body});
  }
  return redis_.eval_integer(kFinish, {kRunning, kFinished}, args) == 1;
}

bool RedisJobStore::cancel_queued(const std::string& id, std::int64_t finished_at_ms) {
  return redis_.eval_integer(kCancelQueued, {kQueue, kFinished}, {kPrefix, id, std::to_string(finished_at_ms)}) == 1;
}

bool RedisJobStore::remove_finished(const std::string& id) {
  return redis_.eval_integer(kRemoveFinished, {kFinished}, {kPrefix, id}) == 1;
}

std::size_t RedisJobStore::count_unfinished(const std::string& client) {
  const RedisConnection::Reply reply = redis_.command({"SCARD", client_key(client)});
  return reply->type == REDIS_REPLY_INTEGER ? static_cast<std::size_t>(reply->integer) : 0;
}

std::size_t RedisJobStore::count_unfinished() {
  const RedisConnection::Reply queued = redis_.command({"LLEN", kQueue});
  const RedisConnection::Reply running = redis_.command({"LLEN", kRunning});
  return static_cast<std::size_t>(queued->integer + running->integer);
}

std::size_t RedisJobStore::remove_finished_before(std::int64_t cutoff_ms) {
  return static_cast<std::size_t>(
      redis_.eval_integer(kRemoveBefore, {kFinished}, {kPrefix, std::to_string(cutoff_ms)}));
}

void RedisJobStore::request_cancel(const std::string& id) { redis_.eval_integer(kRequestCancel, {}, {kPrefix, id}); }

bool RedisJobStore::heartbeat(const std::string& id, const JobProgressView& progress, std::int64_t lease_until_ms) {
  const std::vector<std::string> args{kPrefix,
                                      id,
                                      std::to_string(lease_until_ms),
                                      "p_phase",
                                      progress.phase,
                                      "p_fraction",
                                      progress.fraction ? std::to_string(*progress.fraction) : std::string(),
                                      "p_done",
                                      std::to_string(progress.done),
                                      "p_total",
                                      std::to_string(progress.total),
                                      "p_stage",
                                      progress.stage,
                                      "p_stage_done",
                                      std::to_string(progress.stage_done),
                                      "p_stage_total",
                                      std::to_string(progress.stage_total)};
  return redis_.eval_integer(kHeartbeat, {}, args) == 1;
}

std::size_t RedisJobStore::requeue_expired(std::int64_t now_ms) {
  return static_cast<std::size_t>(
      redis_.eval_integer(kRequeueExpired, {kRunning, kQueue, kFinished}, {kPrefix, std::to_string(now_ms)}));
}

}  // namespace implicitizer::server
