#include "config.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <functional>
#include <map>
#include <thread>

#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer::server {

const char* const kServerUsage =
    "usage: implicitizer-server [flags]\n"
    "  --host ADDR                 address to bind (127.0.0.1)\n"
    "  --port N                    TCP port; 0 picks a free one (8080)\n"
    "  --threads N                 computation workers; 0 = one per core (0)\n"
    "  --io-threads N              network threads (1)\n"
    "  --static DIR                serve DIR at / (none)\n"
    "  --queue-size N              computations waiting for a worker before 503 (256)\n"
    "  --retry-after S             Retry-After seconds of a 503 (1)\n"
    "  --cache-size N              results kept in the LRU cache; 0 disables (256)\n"
    "  --max-body-bytes N          larger request bodies get 413 (1048576)\n"
    "  --max-header-bytes N        larger request headers get 431 (8192)\n"
    "  --read-timeout-ms N         per read: slower clients are dropped (10000)\n"
    "  --write-timeout-ms N        per response write (10000)\n"
    "  --keep-alive-requests N     requests per connection before it closes (100)\n"
    "  --max-static-file-bytes N   larger static files are not served (16777216)\n"
    "  --default-timeout-ms N      computation budget without timeout_ms (10000)\n"
    "  --max-timeout-ms N          cap of timeout_ms; 0 and larger values get it (60000)\n"
    "  --max-terms N               largest intermediate polynomial; beyond is 413 (200000)\n"
    "  --max-memory-mb N           memory of one computation; beyond is 413; 0 = 3/4 of RAM\n"
    "                              shared by the workers (0)\n"
    "  --max-variables N           variables of one request; more is 413 (64)\n"
    "  --max-polynomials N         polynomials of one ideal; more is 413 (1000)\n"
    "  --json-max-depth N          deepest JSON nesting accepted (32)\n"
    "  --shutdown-grace-ms N       on SIGTERM/SIGINT, time in-flight work may finish (5000)\n"
    "  --max-job-seconds N         time limit of one job (3600)\n"
    "  --job-ttl N                 seconds a finished job's result is kept (3600)\n"
    "  --max-jobs-per-client N     queued or running jobs per client before 429 (16)\n"
    "  --max-finished-jobs-per-client N\n"
    "                              finished jobs kept per client; the oldest go first (256)\n"
    "  --max-finished-jobs N       finished jobs kept of all clients (4096)\n"
    "  --max-job-bytes-per-client N\n"
    "                              bytes of one client's stored jobs: the oldest finished go\n"
    "                              first; unfinished ones past it get 507 (67108864)\n"
    "  --max-job-bytes N           bytes of all stored jobs, likewise (268435456)\n"
    "  --job-threads N             threads running jobs, apart from --threads (1)\n"
    "  --store STORE               where jobs are kept: memory, sqlite[:PATH] (sqlite alone:\n"
    "                              ./implicitizer-jobs.sqlite3) or redis://HOST:PORT (memory)\n"
    "  --client-ip-header NAME     behind a proxy: the header naming the client, for the job cap\n"
    "  --job-lease-seconds N       with redis: a dead replica's job is taken over after this (15)\n"
    "  --cors-origins LIST         comma-separated allowed origins, * for any, '' for none (*)\n"
    "  --quiet                     no JSON-lines access log on stderr\n"
    "  --help                      this text\n";

unsigned ServerConfig::effective_worker_threads() const {
  if (worker_threads > 0) return worker_threads;
  const unsigned cores = std::thread::hardware_concurrency();
  return cores > 0 ? cores : 1;
}

std::size_t ServerConfig::effective_max_memory_bytes() const {
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  if (max_memory_mb > 0) return max_memory_mb * kMiB;
  // Read once: every request's budget asks, and the machine's memory does not change.
  static const std::size_t ram = [] {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGESIZE);
    // Unknown memory: a limit that still stops a runaway on any machine this runs on.
    return pages > 0 && page_size > 0 ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(page_size)
                                      : 4096 * kMiB;
  }();
  return std::max(kMiB, ram / 4 * 3 / effective_worker_threads());
}

namespace {

std::uint64_t parse_unsigned(const std::string& flag, const std::string& text, std::uint64_t min, std::uint64_t max) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || value < min || value > max) {
    throw UsageError("--" + flag + " needs an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                     "], not '" + text + "'");
  }
  return value;
}

std::vector<std::string> split_origins(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::size_t stop = comma == std::string::npos ? text.size() : comma;
    if (stop > start) out.push_back(text.substr(start, stop - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

// `memory`, `sqlite`, `sqlite:PATH` or `redis://HOST:PORT`, with the default path filled in.
std::string checked_store(const std::string& text) {
  if (text == "memory") return text;
  if (text == "sqlite") return std::string("sqlite:") + kDefaultSqlitePath;
  if (text.rfind("sqlite:", 0) == 0 && text.size() > 7) return text;
  if (text.rfind("redis://", 0) == 0) {
    const std::string address = text.substr(8);
    const std::size_t colon = address.rfind(':');
    if (colon != std::string::npos && colon > 0) {
      parse_unsigned("store", address.substr(colon + 1), 1, 65535);
      return text;
    }
  }
  throw UsageError("--store needs memory, sqlite, sqlite:PATH or redis://HOST:PORT, not '" + text + "'");
}

using FlagSetter = std::function<void(const std::string& flag, const std::string& value)>;

// The flags that take a value, each with what it sets in `config`.
std::map<std::string, FlagSetter> make_flag_setters(ServerConfig& config) {
  constexpr std::uint64_t kBig = std::uint64_t{1} << 40;
  auto millis = [](std::chrono::milliseconds& field, std::uint64_t min) {
    return [&field, min](const std::string& flag, const std::string& v) {
      field = std::chrono::milliseconds(parse_unsigned(flag, v, min, 24ULL * 3600 * 1000));
    };
  };
  auto seconds = [](std::chrono::seconds& field) {
    return [&field](const std::string& flag, const std::string& v) {
      field = std::chrono::seconds(parse_unsigned(flag, v, 1, 30ULL * 24 * 3600));
    };
  };
  auto count = [](auto& field, std::uint64_t min, std::uint64_t max) {
    return [&field, min, max](const std::string& flag, const std::string& v) {
      field = static_cast<std::remove_reference_t<decltype(field)>>(parse_unsigned(flag, v, min, max));
    };
  };
  return {
      {"host", [&](const std::string&, const std::string& v) { config.host = v; }},
      {"port", count(config.port, 0, 65535)},
      {"threads", count(config.worker_threads, 0, 1024)},
      {"io-threads", count(config.io_threads, 1, 64)},
      {"static", [&](const std::string&, const std::string& v) { config.static_dir = v; }},
      {"queue-size", count(config.queue_capacity, 0, 1'000'000)},
      {"retry-after", count(config.retry_after_seconds, 0, 3600)},
      {"cache-size", count(config.cache_capacity, 0, 1'000'000)},
      {"max-body-bytes", count(config.max_body_bytes, 1, kBig)},
      {"max-header-bytes", count(config.max_header_bytes, 256, 1 << 20)},
      {"read-timeout-ms", millis(config.read_timeout, 1)},
      {"write-timeout-ms", millis(config.write_timeout, 1)},
      {"keep-alive-requests", count(config.max_requests_per_connection, 1, 1'000'000)},
      {"max-static-file-bytes", count(config.max_static_file_bytes, 0, kBig)},
      {"default-timeout-ms", millis(config.default_timeout, 1)},
      {"max-timeout-ms", millis(config.max_timeout, 1)},
      {"max-terms", count(config.max_terms, 0, kBig)},
      {"max-memory-mb", count(config.max_memory_mb, 0, std::uint64_t{1} << 30)},
      {"max-variables", count(config.max_variables, 1, kMaxVariables)},
      {"max-polynomials", count(config.max_polynomials, 1, 1'000'000)},
      {"json-max-depth", count(config.json_max_depth, 1, 4096)},
      {"shutdown-grace-ms", millis(config.shutdown_grace, 0)},
      {"max-job-seconds", seconds(config.max_job_time)},
      {"job-ttl", seconds(config.job_ttl)},
      {"max-jobs-per-client", count(config.max_jobs_per_client, 1, 1'000'000)},
      {"max-finished-jobs-per-client", count(config.max_finished_jobs_per_client, 1, 1'000'000'000)},
      {"max-finished-jobs", count(config.max_finished_jobs, 1, 1'000'000'000)},
      {"max-job-bytes-per-client", count(config.max_job_bytes_per_client, 1, kBig)},
      {"max-job-bytes", count(config.max_job_bytes, 1, kBig)},
      {"job-threads", count(config.job_threads, 1, 1024)},
      {"job-lease-seconds", seconds(config.job_lease)},
      {"client-ip-header", [&](const std::string&, const std::string& v) { config.client_ip_header = v; }},
      {"store", [&](const std::string&, const std::string& v) { config.store = checked_store(v); }},
      {"cors-origins", [&](const std::string&, const std::string& v) { config.cors_origins = split_origins(v); }},
  };
}

}  // namespace

std::optional<ServerConfig> parse_server_flags(const std::vector<std::string>& args) {
  ServerConfig config;
  const std::map<std::string, FlagSetter> valued = make_flag_setters(config);
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0) throw UsageError("unexpected argument '" + arg + "'");
    std::string name = arg.substr(2);
    std::optional<std::string> value;
    if (const std::size_t eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name.resize(eq);
    }
    if (name == "help" && !value) return std::nullopt;
    if (name == "quiet" && !value) {
      config.quiet = true;
      continue;
    }
    const auto it = valued.find(name);
    if (it == valued.end()) throw UsageError("unknown flag '--" + name + "'");
    if (!value) {
      if (i + 1 >= args.size()) throw UsageError("--" + name + " needs a value");
      value = args[++i];
    }
    it->second(name, *value);
  }
  if (config.default_timeout > config.max_timeout) config.default_timeout = config.max_timeout;
  return config;
}

}  // namespace implicitizer::server
