-- wrk script: counts the answers by HTTP status and by X-Cache header, and prints
-- one machine-readable summary that run_load.sh parses. Used alone for GET
-- endpoints (`wrk -s status_counts.lua URL`) and loaded by the POST scripts.
--
-- wrk runs `response` in each thread's own Lua state and `done` in the main one,
-- so each thread keeps its own tables and `done` adds them up through thread:get
-- (which copies tables between states).

local threads = {}

-- Main state, once per thread before it starts: remembers the thread and gives it
-- a 1-based index (the POST scripts use it to make bodies unique across threads).
function setup(thread)
  threads[#threads + 1] = thread
  thread:set("thread_index", #threads)
end

statuses = {}
cache = {}

function response(status, headers, body)
  local key = tostring(status)
  statuses[key] = (statuses[key] or 0) + 1
  local hit = headers["X-Cache"] or headers["x-cache"]
  if hit then cache[hit] = (cache[hit] or 0) + 1 end
end

local function add_into(total, part)
  for k, v in pairs(part or {}) do total[k] = (total[k] or 0) + v end
end

local function format_counts(counts)
  local keys = {}
  for k in pairs(counts) do keys[#keys + 1] = k end
  table.sort(keys)
  local parts = {}
  for _, k in ipairs(keys) do parts[#parts + 1] = k .. "=" .. counts[k] end
  return #parts > 0 and table.concat(parts, " ") or "none"
end

function done(summary, latency, requests)
  local all_statuses, all_cache = {}, {}
  for _, thread in ipairs(threads) do
    add_into(all_statuses, thread:get("statuses"))
    add_into(all_cache, thread:get("cache"))
  end
  local seconds = summary.duration / 1e6
  local e = summary.errors
  io.write(string.format(
    "LOAD requests=%d seconds=%.2f rps=%.1f p50_ms=%.3f p90_ms=%.3f p99_ms=%.3f max_ms=%.3f\n",
    summary.requests, seconds, summary.requests / seconds,
    latency:percentile(50) / 1000, latency:percentile(90) / 1000,
    latency:percentile(99) / 1000, latency.max / 1000))
  io.write("LOAD_STATUS " .. format_counts(all_statuses) .. "\n")
  io.write("LOAD_XCACHE " .. format_counts(all_cache) .. "\n")
  io.write(string.format("LOAD_SOCKET_ERRORS connect=%d read=%d write=%d timeout=%d\n",
                         e.connect, e.read, e.write, e.timeout))
end
