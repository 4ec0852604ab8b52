#include "jobs/job_store.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "jobs/memory_job_store.hpp"
#include "jobs/sqlite_job_store.hpp"

namespace implicitizer::server {
namespace {

JobRecord make_job(const std::string& id, const std::string& client) {
  JobRecord job;
  job.id = id;
  job.kind = "groebner";
  job.request = R"({"polynomials":["x"]})";
  job.client = client;
  job.created_at_ms = 1000;
  return job;
}

JobResult make_result() { return JobResult{422, "application/json", {{"X-Cache", "miss"}, {"X-A", "b c"}}, "{}"}; }

// The same contract for every store of one process.
class JobStoreTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    path_ = std::filesystem::temp_directory_path() / ("job_store_test_" + std::to_string(::getpid()) + ".sqlite3");
    std::filesystem::remove(path_);
    store_ = open();
  }
  void TearDown() override {
    store_.reset();
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path_.string() + suffix);
  }
  std::unique_ptr<JobStore> open() const {
    if (GetParam() == "sqlite") return std::make_unique<SqliteJobStore>(path_.string());
    return std::make_unique<MemoryJobStore>();
  }

  std::filesystem::path path_;
  std::unique_ptr<JobStore> store_;
};

TEST_P(JobStoreTest, ClaimsInSubmissionOrderAndSkipsCancelled) {
  for (const char* id : {"a", "b", "c"}) EXPECT_TRUE(store_->insert(make_job(id, "peer"), 3));
  EXPECT_EQ(store_->count_unfinished("peer"), 3U);
  EXPECT_TRUE(store_->cancel_queued("b", 2000));
  EXPECT_FALSE(store_->cancel_queued("b", 2000)) << "only a queued job is cancelled";
  const auto first = store_->claim_next(3000);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->id, "a");
  EXPECT_EQ(first->status, JobStatus::running);
  EXPECT_EQ(first->started_at_ms, 3000);
  const auto second = store_->claim_next(3000);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->id, "c");
  EXPECT_FALSE(store_->claim_next(3000));
  EXPECT_FALSE(store_->cancel_queued("a", 4000)) << "a running job is not cancelled by the store";
  EXPECT_EQ(store_->count_unfinished("peer"), 2U);
  EXPECT_EQ(store_->count_unfinished("other"), 0U);
}

TEST_P(JobStoreTest, InsertKeepsAClientUnderItsCap) {
  EXPECT_TRUE(store_->insert(make_job("a", "peer"), 2));
  EXPECT_TRUE(store_->insert(make_job("b", "peer"), 2));
  EXPECT_FALSE(store_->insert(make_job("c", "peer"), 2)) << "a third unfinished job";
  EXPECT_FALSE(store_->find("c"));
  EXPECT_TRUE(store_->insert(make_job("d", "other"), 2)) << "the cap is per client";
  JobRecord cached = make_job("e", "peer");
  cached.status = JobStatus::done;  // born finished (a cache hit): not counted
  cached.finished_at_ms = 5;
  EXPECT_TRUE(store_->insert(cached, 2));
  EXPECT_TRUE(store_->cancel_queued("a", 6));
  EXPECT_TRUE(store_->insert(make_job("c", "peer"), 2)) << "a place freed";
}

TEST_P(JobStoreTest, FinishKeepsTheResultUntilRemovedOrExpired) {
  store_->insert(make_job("a", "peer"), 16);
  store_->insert(make_job("b", "peer"), 16);
  ASSERT_TRUE(store_->claim_next(10));
  ASSERT_TRUE(store_->claim_next(10));
  EXPECT_TRUE(store_->finish("a", JobStatus::failed, make_result(), 100));
  EXPECT_FALSE(store_->finish("a", JobStatus::done, make_result(), 101)) << "a job finishes once";
  EXPECT_TRUE(store_->finish("b", JobStatus::done, make_result(), 200));
  const auto a = store_->find("a");
  ASSERT_TRUE(a && a->result);
  EXPECT_EQ(a->status, JobStatus::failed);
  EXPECT_EQ(a->finished_at_ms, 100);
  EXPECT_EQ(a->result->http_status, 422U);
  EXPECT_EQ(a->result->headers, make_result().headers);
  EXPECT_EQ(store_->count_unfinished(), 0U);
  EXPECT_EQ(store_->remove_finished_before(150), 1U);
  EXPECT_FALSE(store_->find("a"));
  EXPECT_TRUE(store_->remove_finished("b"));
  EXPECT_FALSE(store_->find("b"));
  EXPECT_FALSE(store_->remove_finished("b"));
}

INSTANTIATE_TEST_SUITE_P(Stores, JobStoreTest, ::testing::Values("memory", "sqlite"));

TEST(SqliteJobStoreTest, ReopeningQueuesAgainWhatWasRunningAndKeepsResults) {
  const auto path =
      std::filesystem::temp_directory_path() / ("job_store_reopen_" + std::to_string(::getpid()) + ".sqlite3");
  std::filesystem::remove(path);
  {
    SqliteJobStore store(path.string());
    for (const char* id : {"done", "running", "queued"}) store.insert(make_job(id, "peer"), 16);
    ASSERT_TRUE(store.claim_next(1));
    ASSERT_TRUE(store.finish("done", JobStatus::done, make_result(), 2));
    ASSERT_TRUE(store.claim_next(3));  // "running", left so: the process dies
  }
  SqliteJobStore reopened(path.string());
  EXPECT_EQ(reopened.requeued_at_open(), 1U);
  EXPECT_EQ(reopened.find("done")->result->body, "{}");
  EXPECT_EQ(reopened.claim_next(4)->id, "running") << "the oldest first";
  EXPECT_EQ(reopened.claim_next(4)->id, "queued");
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
}

}  // namespace
}  // namespace implicitizer::server
