#include "jobs/job_store.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
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
    for (const char* suffix : {"", "-wal", "-shm", ".lock"}) std::filesystem::remove(path_.string() + suffix);
  }
  // The store again, with `limits` (the old one closed first: one store per file).
  void reopen(JobStorageLimits limits) {
    store_.reset();
    store_ = open(limits);
  }
  std::unique_ptr<JobStore> open(JobStorageLimits limits = {}) const {
    if (GetParam() == "sqlite") return std::make_unique<SqliteJobStore>(path_.string(), limits);
    return std::make_unique<MemoryJobStore>(limits);
  }
  // Runs the queued job `id` of `client` to its end at `at` with a result of `body_bytes` bytes.
  void run_to_end(const std::string& id, const std::string& client, std::int64_t at, std::size_t body_bytes) {
    ASSERT_EQ(store_->insert(make_job(id, client), 16), JobAdmission::admitted);
    const auto claimed = store_->claim_next(at);
    ASSERT_TRUE(claimed && claimed->id == id);
    ASSERT_TRUE(store_->finish(id, JobStatus::failed, JobResult{400, "", {}, std::string(body_bytes, 'e')}, at));
  }

  std::filesystem::path path_;
  std::unique_ptr<JobStore> store_;
};

TEST_P(JobStoreTest, ClaimsInSubmissionOrderAndSkipsCancelled) {
  for (const char* id : {"a", "b", "c"}) EXPECT_EQ(store_->insert(make_job(id, "peer"), 3), JobAdmission::admitted);
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
  EXPECT_EQ(store_->insert(make_job("a", "peer"), 2), JobAdmission::admitted);
  EXPECT_EQ(store_->insert(make_job("b", "peer"), 2), JobAdmission::admitted);
  EXPECT_EQ(store_->insert(make_job("c", "peer"), 2), JobAdmission::client_job_cap) << "a third unfinished job";
  EXPECT_FALSE(store_->find("c"));
  EXPECT_EQ(store_->insert(make_job("d", "other"), 2), JobAdmission::admitted) << "the cap is per client";
  JobRecord cached = make_job("e", "peer");
  cached.status = JobStatus::done;  // born finished (a cache hit): not counted
  cached.finished_at_ms = 5;
  EXPECT_EQ(store_->insert(cached, 2), JobAdmission::admitted);
  EXPECT_TRUE(store_->cancel_queued("a", 6));
  EXPECT_EQ(store_->insert(make_job("c", "peer"), 2), JobAdmission::admitted) << "a place freed";
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

// The reproducer of issue 41: finished jobs, each kept with its 1 MB request, grew
// memory without bound; only queued and running jobs were capped.
TEST_P(JobStoreTest, FinishedJobsPastACountCapGoOldestFirst) {
  reopen(JobStorageLimits{2, 3, JobStorageLimits::kNone, JobStorageLimits::kNone});
  ASSERT_EQ(store_->insert(make_job("waiting", "peer"), 16), JobAdmission::admitted);
  ASSERT_TRUE(store_->claim_next(1));  // "waiting" runs: never evicted, however old
  for (int i = 1; i <= 4; ++i) run_to_end("a" + std::to_string(i), "peer", 10 * i, 10);
  EXPECT_FALSE(store_->find("a1"));
  EXPECT_FALSE(store_->find("a2"));
  EXPECT_TRUE(store_->find("a3") && store_->find("a4")) << "the client's two newest stay";
  EXPECT_EQ(store_->find("waiting")->status, JobStatus::running);
  run_to_end("b1", "other", 50, 10);
  EXPECT_TRUE(store_->find("a3")) << "three finished in all: still within both caps";
  run_to_end("b2", "other", 60, 10);
  EXPECT_FALSE(store_->find("a3")) << "past the total cap the oldest of anyone's goes";
  EXPECT_TRUE(store_->find("a4") && store_->find("b1") && store_->find("b2"));
  JobRecord cached = make_job("cached", "other");  // born finished (a cache hit)
  cached.status = JobStatus::done;
  cached.finished_at_ms = 70;
  cached.result = make_result();
  EXPECT_EQ(store_->insert(cached, 16), JobAdmission::admitted);
  EXPECT_FALSE(store_->find("b1")) << "an insert evicts as a finish does";
  EXPECT_TRUE(store_->find("cached"));
  EXPECT_EQ(store_->find("cached")->request, "") << "a finished job keeps no request";
  ASSERT_EQ(store_->insert(make_job("queued", "other"), 16), JobAdmission::admitted);
  EXPECT_TRUE(store_->cancel_queued("queued", 80));
  EXPECT_FALSE(store_->find("b2")) << "a cancel counts a finished job too";
  EXPECT_EQ(store_->find("queued")->request, "");
}

TEST_P(JobStoreTest, ByteCapsEvictFinishedJobsAndRefuseOnlyUnfinishedOnes) {
  reopen(JobStorageLimits{JobStorageLimits::kNone, JobStorageLimits::kNone, 1000, 1500});
  for (int i = 1; i <= 3; ++i) run_to_end("a" + std::to_string(i), "peer", 10 * i, 300);
  EXPECT_EQ(store_->find("a1")->request, "") << "the request went with the finish";
  EXPECT_EQ(job_stored_bytes(*store_->find("a1")), 300U);
  JobRecord big = make_job("big", "peer");
  big.request = std::string(200, 'r');
  ASSERT_EQ(store_->insert(big, 16), JobAdmission::admitted);
  EXPECT_FALSE(store_->find("a1")) << "200 queued + 900 finished passed 1000: the oldest went";
  EXPECT_TRUE(store_->find("a2") && store_->find("a3"));
  JobRecord huge = make_job("huge", "peer");
  huge.request = std::string(801, 'r');
  EXPECT_EQ(store_->insert(huge, 16), JobAdmission::client_bytes_cap) << "200 + 801 unfinished bytes";
  EXPECT_FALSE(store_->find("huge"));
  EXPECT_TRUE(store_->find("a2") && store_->find("a3")) << "a refusal evicts nothing";
  huge.request.resize(800);
  EXPECT_EQ(store_->insert(huge, 16), JobAdmission::admitted) << "exactly at the cap";
  EXPECT_FALSE(store_->find("a2") || store_->find("a3")) << "1000 unfinished bytes leave no room for results";
  JobRecord other = make_job("other", "other");
  other.request = std::string(501, 'r');
  EXPECT_EQ(store_->insert(other, 16), JobAdmission::store_bytes_cap) << "1000 + 501 unfinished bytes in all";
  other.request.resize(500);
  EXPECT_EQ(store_->insert(other, 16), JobAdmission::admitted);
}

TEST_P(JobStoreTest, AResultLargerThanTheCapEvictsTheOthersButStays) {
  reopen(JobStorageLimits{JobStorageLimits::kNone, JobStorageLimits::kNone, 100, JobStorageLimits::kNone});
  run_to_end("small", "peer", 10, 50);
  run_to_end("large", "peer", 20, 500);
  EXPECT_FALSE(store_->find("small"));
  ASSERT_TRUE(store_->find("large")) << "the job just finished is never its own victim";
  EXPECT_EQ(store_->find("large")->result->body.size(), 500U);
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
  for (const char* suffix : {"", "-wal", "-shm", ".lock"}) std::filesystem::remove(path.string() + suffix);
}

class SqliteFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (std::filesystem::temp_directory_path() / ("job_store_file_" + std::to_string(::getpid()) + ".sqlite3"))
                .string();
    remove_files();
  }
  void TearDown() override { remove_files(); }
  void remove_files() const {
    for (const char* suffix : {"", "-wal", "-shm", ".lock"}) std::filesystem::remove(path_ + suffix);
  }
  std::string path_;
};

// The reproducer of issue 41: a second server on the same file requeued the first
// one's running job and claimed it, and both ran it.
TEST_F(SqliteFileTest, ASecondStoreOnTheFileRefusesToOpenAndNamesTheOwner) {
  auto first = std::make_unique<SqliteJobStore>(path_);
  ASSERT_EQ(first->insert(make_job("a", "peer"), 16), JobAdmission::admitted);
  ASSERT_TRUE(first->claim_next(1));
  try {
    SqliteJobStore second(path_);
    FAIL() << "a second store opened the file";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path_), std::string::npos) << message;
    EXPECT_NE(message.find("pid " + std::to_string(::getpid())), std::string::npos) << message;
  }
  EXPECT_EQ(first->find("a")->status, JobStatus::running) << "the refused store requeued nothing";
  EXPECT_FALSE(first->claim_next(2)) << "and the job is claimed once";
  first.reset();
  SqliteJobStore after(path_);
  EXPECT_EQ(after.requeued_at_open(), 1U) << "the owner gone, the next one takes the file over";
}

// The reproducer of issue 41: deleting the file and its -wal/-shm went unnoticed
// until a restart lost every job.
TEST_F(SqliteFileTest, ADeletedFileMakesEveryOperationFail) {
  SqliteJobStore store(path_);
  ASSERT_EQ(store.insert(make_job("a", "peer"), 16), JobAdmission::admitted);
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path_ + suffix);
  EXPECT_THROW(store.find("a"), std::runtime_error);
  EXPECT_THROW(store.insert(make_job("b", "peer"), 16), std::runtime_error);
  EXPECT_THROW(store.claim_next(1), std::runtime_error);
  EXPECT_THROW(store.count_unfinished(), std::runtime_error);
}

TEST_F(SqliteFileTest, AReplacedFileIsNoticedToo) {
  SqliteJobStore store(path_);
  ASSERT_EQ(store.insert(make_job("a", "peer"), 16), JobAdmission::admitted);
  std::filesystem::copy_file(path_, path_ + ".copy");
  std::filesystem::rename(path_ + ".copy", path_);  // same name, another inode
  EXPECT_THROW(store.find("a"), std::runtime_error);
}

TEST_F(SqliteFileTest, AFileOverwrittenInPlaceIsNoticed) {
  SqliteJobStore store(path_);
  ASSERT_EQ(store.insert(make_job("a", "peer"), 16), JobAdmission::admitted);
  ASSERT_TRUE(store.find("a"));
  {
    std::FILE* f = std::fopen(path_.c_str(), "r+b");  // same inode, other bytes
    ASSERT_TRUE(f);
    const std::string garbage(4096, 'x');
    std::fwrite(garbage.data(), 1, garbage.size(), f);
    std::fclose(f);
  }
  EXPECT_THROW(store.find("a"), std::runtime_error);
  EXPECT_THROW(store.insert(make_job("b", "peer"), 16), std::runtime_error);
}

TEST_F(SqliteFileTest, AFileThatIsNotADatabaseIsRefusedAtOpen) {
  {
    std::FILE* f = std::fopen(path_.c_str(), "wb");
    ASSERT_TRUE(f);
    const std::string garbage(8192, 'x');
    std::fwrite(garbage.data(), 1, garbage.size(), f);
    std::fclose(f);
  }
  EXPECT_THROW(SqliteJobStore store(path_), std::runtime_error);
}

}  // namespace
}  // namespace implicitizer::server
