#include "config.hpp"

#include <gtest/gtest.h>

namespace implicitizer::server {
namespace {

TEST(ServerFlags, DefaultsAreTheDocumentedOnes) {
  const auto config = parse_server_flags({});
  ASSERT_TRUE(config);
  EXPECT_EQ(config->host, "127.0.0.1");
  EXPECT_EQ(config->port, 8080);
  EXPECT_EQ(config->max_body_bytes, 1u << 20);
  EXPECT_EQ(config->default_timeout.count(), 10'000);
  EXPECT_EQ(config->max_timeout.count(), 60'000);
  EXPECT_EQ(config->cors_origins, std::vector<std::string>{"*"});
  EXPECT_GE(config->effective_worker_threads(), 1u);
}

TEST(ServerFlags, ReadsValuesInBothSpellings) {
  const auto config =
      parse_server_flags({"--host", "0.0.0.0", "--port=0", "--threads", "3", "--static", "web", "--cors-origins",
                          "https://a,https://b", "--quiet", "--max-body-bytes", "1000"});
  ASSERT_TRUE(config);
  EXPECT_EQ(config->host, "0.0.0.0");
  EXPECT_EQ(config->port, 0);
  EXPECT_EQ(config->worker_threads, 3u);
  EXPECT_EQ(config->effective_worker_threads(), 3u);
  EXPECT_EQ(config->static_dir, "web");
  EXPECT_EQ(config->cors_origins, (std::vector<std::string>{"https://a", "https://b"}));
  EXPECT_TRUE(config->quiet);
  EXPECT_EQ(config->max_body_bytes, 1000u);
}

TEST(ServerFlags, MemoryAndCountLimits) {
  const auto defaults = parse_server_flags({});
  ASSERT_TRUE(defaults);
  EXPECT_EQ(defaults->max_memory_mb, 0u);
  EXPECT_EQ(defaults->max_variables, 64u);
  EXPECT_EQ(defaults->max_polynomials, 1000u);
  // The derived memory limit: three quarters of the machine's memory, shared by the
  // workers, so it shrinks with more workers and is never zero.
  const auto one = parse_server_flags({"--threads", "1"});
  const auto four = parse_server_flags({"--threads", "4"});
  ASSERT_TRUE(one && four);
  EXPECT_GT(four->effective_max_memory_bytes(), 0u);
  EXPECT_EQ(four->effective_max_memory_bytes(), one->effective_max_memory_bytes() / 4);
  const auto set = parse_server_flags({"--max-memory-mb", "256", "--max-variables", "8", "--max-polynomials", "10"});
  ASSERT_TRUE(set);
  EXPECT_EQ(set->effective_max_memory_bytes(), std::size_t{256} << 20);
  EXPECT_EQ(set->max_variables, 8u);
  EXPECT_EQ(set->max_polynomials, 10u);
  // A ring never has more than kMaxVariables variables, so neither may a request.
  EXPECT_THROW(parse_server_flags({"--max-variables", "0"}), UsageError);
  EXPECT_THROW(parse_server_flags({"--max-variables", "1025"}), UsageError);
  EXPECT_THROW(parse_server_flags({"--max-polynomials", "0"}), UsageError);
}

TEST(ServerFlags, JobFlags) {
  const auto defaults = parse_server_flags({});
  ASSERT_TRUE(defaults);
  EXPECT_EQ(defaults->max_job_time.count(), 3600);
  EXPECT_EQ(defaults->job_ttl.count(), 3600);
  EXPECT_EQ(defaults->max_jobs_per_client, 16u);
  EXPECT_EQ(defaults->job_threads, 1u);
  EXPECT_EQ(defaults->store, "memory");
  EXPECT_EQ(defaults->job_lease.count(), 15);
  EXPECT_EQ(defaults->client_ip_header, "");
  EXPECT_EQ(defaults->max_finished_jobs_per_client, 256u);
  EXPECT_EQ(defaults->max_finished_jobs, 4096u);
  EXPECT_EQ(defaults->max_job_bytes_per_client, std::size_t{64} << 20);
  EXPECT_EQ(defaults->max_job_bytes, std::size_t{256} << 20);
  const auto storage = parse_server_flags({"--max-finished-jobs-per-client", "3", "--max-finished-jobs", "9",
                                           "--max-job-bytes-per-client", "1000", "--max-job-bytes=5000"});
  ASSERT_TRUE(storage);
  EXPECT_EQ(storage->max_finished_jobs_per_client, 3u);
  EXPECT_EQ(storage->max_finished_jobs, 9u);
  EXPECT_EQ(storage->max_job_bytes_per_client, 1000u);
  EXPECT_EQ(storage->max_job_bytes, 5000u);
  EXPECT_THROW(parse_server_flags({"--max-job-bytes", "0"}), UsageError);

  const auto config =
      parse_server_flags({"--max-job-seconds", "7200", "--job-ttl=60", "--max-jobs-per-client", "2", "--job-threads",
                          "3", "--job-lease-seconds", "5", "--client-ip-header", "X-Real-IP", "--store", "sqlite"});
  ASSERT_TRUE(config);
  EXPECT_EQ(config->max_job_time.count(), 7200);
  EXPECT_EQ(config->job_ttl.count(), 60);
  EXPECT_EQ(config->max_jobs_per_client, 2u);
  EXPECT_EQ(config->job_threads, 3u);
  EXPECT_EQ(config->job_lease.count(), 5);
  EXPECT_EQ(config->client_ip_header, "X-Real-IP");
  EXPECT_EQ(config->store, std::string("sqlite:") + kDefaultSqlitePath);
  EXPECT_EQ(parse_server_flags({"--store", "sqlite:/tmp/j.db"})->store, "sqlite:/tmp/j.db");
  EXPECT_EQ(parse_server_flags({"--store", "redis://10.0.0.5:6379"})->store, "redis://10.0.0.5:6379");
  for (const char* bad : {"redis", "redis://host", "redis://host:0", "redis://:6379", "sqlite:", "postgres://x:1"}) {
    EXPECT_THROW(parse_server_flags({"--store", bad}), UsageError) << bad;
  }
  EXPECT_THROW(parse_server_flags({"--max-job-seconds", "0"}), UsageError);
  EXPECT_THROW(parse_server_flags({"--job-threads", "0"}), UsageError);
}

TEST(ServerFlags, HelpReturnsNothing) { EXPECT_FALSE(parse_server_flags({"--help"})); }

TEST(ServerFlags, RefusesBadFlagsAndValues) {
  EXPECT_THROW(parse_server_flags({"--nope"}), UsageError);
  EXPECT_THROW(parse_server_flags({"--port"}), UsageError);
  EXPECT_THROW(parse_server_flags({"--port", "70000"}), UsageError);
  EXPECT_THROW(parse_server_flags({"--threads", "-1"}), UsageError);
  EXPECT_THROW(parse_server_flags({"--read-timeout-ms", "0"}), UsageError);
  EXPECT_THROW(parse_server_flags({"stray"}), UsageError);
}

TEST(ServerFlags, DefaultTimeoutNeverExceedsTheCap) {
  const auto config = parse_server_flags({"--default-timeout-ms", "90000", "--max-timeout-ms", "2000"});
  ASSERT_TRUE(config);
  EXPECT_EQ(config->default_timeout.count(), 2000);
}

}  // namespace
}  // namespace implicitizer::server
