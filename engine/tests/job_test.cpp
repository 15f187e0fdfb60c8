#include "anchorbench/engine/job.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/engine/commit.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/components.hpp"
#include "anchorbench/testing/small_table.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::engine {
namespace {

namespace fs = std::filesystem;
using testing::AllComponents;
using testing::SmallTable;

std::string Read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::unique_ptr<io::ResultFolder> Folder(const fs::path& path, bool overwrite = false) {
  io::ResultFolder::Options options;
  options.overwrite = overwrite;
  return std::make_unique<io::ResultFolder>(path, options);
}

Job RunJob(const Plan& plan) { return {plan, "run", "small", "test", {config::ToYaml(plan.experiments().front()), {}}}; }

TEST(ComputeJob, AWholePlanComesBackJoinedAndCommitsToTheFiveFilesOfARun) {
  const testing::TempDir dir("job_whole");
  const Plan plan({SmallTable()});
  LocalExecutor executor(AllComponents());
  std::unique_ptr<io::ResultFolder> out = Folder(dir.path() / "run");
  const auto joined = ComputeJob(RunJob(plan), executor, {}, *out);
  ASSERT_TRUE(joined.has_value());
  const std::vector<ExperimentAttempts> expected = RunWholePlan(plan, executor, 2);
  ASSERT_EQ(joined->size(), 1u);
  EXPECT_EQ(joined->front().lines, expected.front().lines);
  EXPECT_TRUE(fs::exists(ChunkStorePath(out->target())));  // until the results are in place

  report::RunInfo info;
  info.config_path = "small.yaml";
  const std::string markdown = CommitRun(*out, plan.experiments().front(), joined->front(), info);
  RemoveStore(*out);
  EXPECT_FALSE(fs::exists(ChunkStorePath(out->target())));
  for (const char* file : {"attempts.csv", "summary.csv", "summary.md", "timing.csv", "manifest.json"}) {
    EXPECT_TRUE(fs::is_regular_file(dir.path() / "run" / file)) << file;
  }
  EXPECT_EQ(Read(dir.path() / "run" / "summary.md"), markdown);
  std::size_t lines = 0;
  for (char c : Read(dir.path() / "run" / "attempts.csv")) lines += c == '\n';
  EXPECT_EQ(lines, expected.front().attempts.size() + 1);  // the header and a line per attempt
}

TEST(ComputeJob, ShardsCommitTheirFoldersAndTogetherHoldEveryChunk) {
  const testing::TempDir dir("job_shards");
  const Plan plan({SmallTable()});
  LocalExecutor executor(AllComponents());
  std::map<int, ChunkResult> merged;
  for (int index = 0; index < 2; ++index) {  // --shard 1/2 and 2/2
    const fs::path folder = dir.path() / ("shard" + std::to_string(index));
    std::unique_ptr<io::ResultFolder> out = Folder(folder);
    JobOptions options;
    options.shard = Shard{index, 2};
    EXPECT_FALSE(ComputeJob(RunJob(plan), executor, options, *out).has_value());
    EXPECT_FALSE(fs::exists(ChunkStorePath(folder)));  // the shard folder holds the chunks now
    const ShardInfo info = ReadShardInfo(folder);
    EXPECT_EQ(info.plan, plan.identity());
    EXPECT_EQ(info.revision, "test");
    merged.merge(ReadShardChunks(folder, info, plan));
  }
  EXPECT_EQ(merged.size(), plan.chunks().size());
  EXPECT_EQ(Join(plan, merged).front().lines, RunWholePlan(plan, executor, 1).front().lines);
}

TEST(ComputeJob, ADamagedStoreIsToldAndItsChunksComputedAgain) {
  const testing::TempDir dir("job_damaged");
  const Plan plan({SmallTable()});
  LocalExecutor executor(AllComponents());
  const fs::path target = dir.path() / "run";
  {
    std::unique_ptr<io::ResultFolder> out = Folder(target);
    ComputeJob(RunJob(plan), executor, {}, *out);  // never committed: the store stays, as after a kill
  }
  const fs::path chunks = ChunkStorePath(target) / "chunks.csv";
  ASSERT_TRUE(fs::exists(chunks));
  std::ofstream(chunks, std::ios::app) << "chunk,0,99999,\na torn block\n";

  std::vector<std::string> notes;
  JobOptions options;
  options.store_mode = ChunkStore::Mode::kResume;
  options.note = [&](const std::string& note) { notes.push_back(note); };
  std::unique_ptr<io::ResultFolder> out = Folder(target);
  const auto joined = ComputeJob(RunJob(plan), executor, options, *out);
  out.reset();  // not committed: the store stays
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes.front().find("1 stored chunk(s) do not read back"), std::string::npos) << notes.front();
  EXPECT_EQ(joined->front().lines, RunWholePlan(plan, executor, 1).front().lines);

  JobOptions refusing;  // kFresh over the interrupted store of `target` is refused
  std::unique_ptr<io::ResultFolder> again = Folder(target);
  EXPECT_THROW(ComputeJob(RunJob(plan), executor, refusing, *again), schema::InputError);
}

TEST(CommitSweep, WritesALinePerPointRowAndTrigger) {
  const testing::TempDir dir("commit_sweep");
  const std::vector<schema::SweepAxis> axes = {{"seed", {"3", "4"}}};
  std::vector<schema::ExperimentConfig> points;
  for (std::uint64_t seed : {3u, 4u}) {
    schema::ExperimentConfig config = SmallTable();
    config.seed = seed;
    config.realizations = 2;
    config.bootstrap_resamples = 0;
    points.push_back(config);
  }
  const Plan plan(points);
  LocalExecutor executor(AllComponents());
  const std::vector<ExperimentAttempts> attempts = RunWholePlan(plan, executor, 2);
  std::unique_ptr<io::ResultFolder> out = Folder(dir.path() / "sweep");
  const std::string markdown = CommitSweep(*out, "small", axes, plan, attempts, {});
  EXPECT_EQ(Read(dir.path() / "sweep" / "sweep.md"), markdown);
  const std::string csv = Read(dir.path() / "sweep" / "sweep.csv");
  std::size_t lines = 0;
  for (char c : csv) lines += c == '\n';
  const std::size_t triggers = SmallTable().estimator.triggers.size();
  EXPECT_EQ(lines, 1 + 2 * 2 * triggers);  // header, then 2 points x 2 rows x the triggers
  EXPECT_NE(Read(dir.path() / "sweep" / "manifest.json").find("seed=3,4"), std::string::npos);
}

}  // namespace
}  // namespace anchorbench::engine
