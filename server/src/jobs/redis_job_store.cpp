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

// Lua shared by the scripts that change what the store holds. Byte counters per
// client and in total, of unfinished (`ubytes:`) and finished (`fbytes:`) jobs, each
// job's own count in its `bytes` field; `finished:PEER` is a client's finished ids
// by finishing time. evict() applies JobStorageLimits: the oldest finished jobs but
// `keep` go while a client's, then everyone's, finished jobs or bytes pass a cap
// (`limits`: finished per client, bytes per client, finished, bytes).
const std::string kStorage = R"(
local function num(v) return tonumber(v) or 0 end
local function drop(prefix, finished, id)
  local key = prefix .. 'job:' .. id
  local client = redis.call('HGET', key, 'client')
  local bytes = num(redis.call('HGET', key, 'bytes'))
  if client then
    redis.call('DECRBY', prefix .. 'fbytes:' .. client, bytes)
    redis.call('ZREM', prefix .. 'finished:' .. client, id)
  end
  redis.call('DECRBY', prefix .. 'jobs:fbytes', bytes)
  redis.call('ZREM', finished, id)
  redis.call('DEL', key)
end
local function evict_from(prefix, finished, set, keep, ukey, fkey, max_count, max_bytes)
  while true do
    local count = redis.call('ZCARD', set)
    local bytes = num(redis.call('GET', ukey)) + num(redis.call('GET', fkey))
    if count <= max_count and bytes <= max_bytes then return end
    local oldest = redis.call('ZRANGE', set, 0, 1)
    local victim = oldest[1]
    if victim == keep then victim = oldest[2] end
    if not victim then return end
    drop(prefix, finished, victim)
  end
end
local function evict(prefix, finished, client, keep, limits)
  evict_from(prefix, finished, prefix .. 'finished:' .. client, keep, prefix .. 'ubytes:' .. client,
             prefix .. 'fbytes:' .. client, limits[1], limits[2])
  evict_from(prefix, finished, finished, keep, prefix .. 'jobs:ubytes', prefix .. 'jobs:fbytes', limits[3], limits[4])
end
local function limits_at(i)
  return {tonumber(ARGV[i]), tonumber(ARGV[i + 1]), tonumber(ARGV[i + 2]), tonumber(ARGV[i + 3])}
end
-- Moves `id` (hash `key`) from the list `from` to the finished sets as `status` at
-- `at`, out of its client's unfinished set, its request dropped (a result never
-- needs it again) and its bytes now `bytes`; returns its client.
local function settle(prefix, key, id, from, finished, status, at, bytes)
  local client = redis.call('HGET', key, 'client')
  local old = num(redis.call('HGET', key, 'bytes'))
  redis.call('HSET', key, 'status', status, 'finished_at_ms', at, 'request', '', 'bytes', bytes)
  redis.call('LREM', from, 0, id)
  redis.call('SREM', prefix .. 'client:' .. client, id)
  redis.call('DECRBY', prefix .. 'ubytes:' .. client, old)
  redis.call('DECRBY', prefix .. 'jobs:ubytes', old)
  redis.call('INCRBY', prefix .. 'fbytes:' .. client, bytes)
  redis.call('INCRBY', prefix .. 'jobs:fbytes', bytes)
  redis.call('ZADD', finished, at, id)
  redis.call('ZADD', prefix .. 'finished:' .. client, at, id)
  return client
end
)";

// KEYS: queue, finished. ARGV: prefix, id, queued ("1"/"0"), finished_at_ms, client,
// max_unfinished, bytes, the four limits, then field/value pairs. Returns 1 when
// inserted; else nothing is written and 0 (the client's job cap), 2 (its byte cap)
// or 3 (the store's byte cap).
const std::string kInsert = kStorage + R"(
local prefix, id, client, bytes = ARGV[1], ARGV[2], ARGV[5], tonumber(ARGV[7])
local key = prefix .. 'job:' .. id
local limits = limits_at(8)
if ARGV[3] == '1' then
  if redis.call('SCARD', prefix .. 'client:' .. client) >= tonumber(ARGV[6]) then return 0 end
  if num(redis.call('GET', prefix .. 'ubytes:' .. client)) + bytes > limits[2] then return 2 end
  if num(redis.call('GET', prefix .. 'jobs:ubytes')) + bytes > limits[4] then return 3 end
end
redis.call('HSET', key, 'bytes', bytes, unpack(ARGV, 12))
if ARGV[3] == '1' then
  redis.call('LPUSH', KEYS[1], id)
  redis.call('SADD', prefix .. 'client:' .. client, id)
  redis.call('INCRBY', prefix .. 'ubytes:' .. client, bytes)
  redis.call('INCRBY', prefix .. 'jobs:ubytes', bytes)
else
  redis.call('ZADD', KEYS[2], ARGV[4], id)
  redis.call('ZADD', prefix .. 'finished:' .. client, ARGV[4], id)
  redis.call('INCRBY', prefix .. 'fbytes:' .. client, bytes)
  redis.call('INCRBY', prefix .. 'jobs:fbytes', bytes)
end
evict(prefix, KEYS[2], client, id, limits)
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

// KEYS: running, finished. ARGV: prefix, id, status, finished_at_ms, has_result,
// http_status, content_type, headers, body, the result's bytes, the four limits.
const std::string kFinish = kStorage + R"(
local key = ARGV[1] .. 'job:' .. ARGV[2]
if redis.call('HGET', key, 'status') ~= 'running' then return 0 end
if ARGV[5] == '1' then
  redis.call('HSET', key, 'http_status', ARGV[6], 'content_type', ARGV[7], 'headers', ARGV[8], 'body', ARGV[9])
end
local client = settle(ARGV[1], key, ARGV[2], KEYS[1], KEYS[2], ARGV[3], ARGV[4], tonumber(ARGV[10]))
evict(ARGV[1], KEYS[2], client, ARGV[2], limits_at(11))
return 1)";

// KEYS: queue, finished. ARGV: prefix, id, finished_at_ms, the four limits.
const std::string kCancelQueued = kStorage + R"(
local key = ARGV[1] .. 'job:' .. ARGV[2]
if redis.call('HGET', key, 'status') ~= 'queued' then return 0 end
local client = settle(ARGV[1], key, ARGV[2], KEYS[1], KEYS[2], 'cancelled', ARGV[3], 0)
evict(ARGV[1], KEYS[2], client, ARGV[2], limits_at(4))
return 1)";

// KEYS: finished. ARGV: prefix, id.
const std::string kRemoveFinished = kStorage + R"(
local status = redis.call('HGET', ARGV[1] .. 'job:' .. ARGV[2], 'status')
if status ~= 'done' and status ~= 'failed' and status ~= 'cancelled' then return 0 end
drop(ARGV[1], KEYS[1], ARGV[2])
return 1)";

// KEYS: finished. ARGV: prefix, cutoff_ms.
const std::string kRemoveBefore = kStorage + R"(
local ids = redis.call('ZRANGEBYSCORE', KEYS[1], '-inf', '(' .. ARGV[2])
for _, id in ipairs(ids) do drop(ARGV[1], KEYS[1], id) end
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

// KEYS: running, queue, finished. ARGV: prefix, now_ms, the four limits. A job whose
// lease ran out goes back to the head of the queue (or is cancelled, if that was asked).
const std::string kRequeueExpired = kStorage + R"(
local n = 0
for _, id in ipairs(redis.call('LRANGE', KEYS[1], 0, -1)) do
  local key = ARGV[1] .. 'job:' .. id
  if redis.call('HGET', key, 'status') ~= 'running' then
    redis.call('LREM', KEYS[1], 0, id)
  elseif tonumber(redis.call('HGET', key, 'lease_until_ms') or '0') < tonumber(ARGV[2]) then
    if redis.call('HGET', key, 'cancel_requested') == '1' then
      local client = settle(ARGV[1], key, id, KEYS[1], KEYS[3], 'cancelled', ARGV[2], 0)
      evict(ARGV[1], KEYS[3], client, id, limits_at(3))
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

RedisJobStore::RedisJobStore(std::string host, int port, std::chrono::milliseconds lease, JobStorageLimits limits)
    : lease_ms_(lease.count()), limits_(limits), redis_(std::move(host), port) {}

std::vector<std::string> RedisJobStore::append_limits(std::vector<std::string> args) const {
  for (const std::size_t cap :
       {limits_.max_finished_per_client, limits_.max_bytes_per_client, limits_.max_finished, limits_.max_bytes}) {
    args.push_back(std::to_string(cap));
  }
  return args;
}

JobAdmission RedisJobStore::insert(const JobRecord& job, std::size_t max_unfinished) {
  const bool queued = job.status == JobStatus::queued;
  JobRecord stored = job;
  if (!queued) stored.request.clear();  // a finished job keeps no request
  std::vector<std::string> args{kPrefix,
                                job.id,
                                queued ? "1" : "0",
                                std::to_string(job.finished_at_ms),
                                job.client,
                                std::to_string(max_unfinished),
                                std::to_string(job_stored_bytes(stored)),
                                std::to_string(limits_.max_finished_per_client),
                                std::to_string(limits_.max_bytes_per_client),
                                std::to_string(limits_.max_finished),
                                std::to_string(limits_.max_bytes),
                                "kind",
                                job.kind,
                                "request",
                                stored.request,
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
  switch (redis_.eval_integer(kInsert, {kQueue, kFinished}, args)) {
    case 1:
      return JobAdmission::admitted;
    case 2:
      return JobAdmission::client_bytes_cap;
    case 3:
      return JobAdmission::store_bytes_cap;
    default:
      return JobAdmission::client_job_cap;
  }
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
  JobRecord settled;
  settled.result = result;
  std::vector<std::string> args{kPrefix, id, to_string(status), std::to_string(finished_at_ms), result ? "1" : "0"};
  if (result) {
    args.insert(args.end(), {std::to_string(result->http_status), result->content_type, join_headers(result->headers),
                             result->body});
  } else {
    args.insert(args.end(), 4, std::string());
  }
  args.push_back(std::to_string(job_stored_bytes(settled)));
  args = append_limits(std::move(args));
  return redis_.eval_integer(kFinish, {kRunning, kFinished}, args) == 1;
}

bool RedisJobStore::cancel_queued(const std::string& id, std::int64_t finished_at_ms) {
  std::vector<std::string> args{kPrefix, id, std::to_string(finished_at_ms)};
  args = append_limits(std::move(args));
  return redis_.eval_integer(kCancelQueued, {kQueue, kFinished}, args) == 1;
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
  return static_cast<std::size_t>(redis_.eval_integer(kRequeueExpired, {kRunning, kQueue, kFinished},
                                                      append_limits({kPrefix, std::to_string(now_ms)})));
}

}  // namespace implicitizer::server
