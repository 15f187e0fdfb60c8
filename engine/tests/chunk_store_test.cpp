#include "anchorbench/engine/chunk_store.hpp"

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/components.hpp"
#include "anchorbench/testing/small_table.hpp"
#include "anchorbench/testing/temp_dir.hpp"
#include "anchorbench/engine/run_plan.hpp"

#include <algorithm>

namespace anchorbench::engine {
namespace {

using testing::AllComponents;
using testing::SmallTable;
using Mode = ChunkStore::Mode;

// Computes only the listed chunks of a plan (what a run killed part way leaves behind).
class SomeChunks final : public Executor {
 public:
  explicit SomeChunks(std::vector<int> only) : only_(std::move(only)) {}
  void Compute(const Plan& plan, const std::vector<int>&, int threads, const ChunkDone& done) override {
    LocalExecutor(AllComponents()).Compute(plan, only_, threads, done);
  }

 private:
  std::vector<int> only_;
};

// The chunks in the store of `out`, in the order they were appended.
std::vector<long long> StoredChunks(const std::filesystem::path& out) {
  std::vector<long long> keys;
  ReadBlockLog(ChunkStorePath(out) / "chunks.csv", "chunk", [&keys](LoggedBlock&& block) { keys.push_back(block.key); });
  std::sort(keys.begin(), keys.end());
  return keys;
}

TEST(ChunkStore, ResumesItsOwnPlanAndRefusesAnother) {
  const testing::TempDir dir("chunk_store");
  const std::filesystem::path out = dir.path() / "results";
  const Plan plan({SmallTable()});
  {
    ChunkStore store(out, plan, Mode::kFresh);
    SomeChunks killed({0, 5});
    RunPlan(plan, killed, {2, &store, nullptr});
  }
  EXPECT_EQ(StoredChunks(dir.path() / "results"), (std::vector<long long>{0, 5}));
  EXPECT_THROW(ChunkStore(out, plan, Mode::kFresh), schema::InputError);  // an interrupted run
  schema::ExperimentConfig other = SmallTable();
  other.seed = 99;
  const Plan other_plan({other});
  EXPECT_THROW(ChunkStore(out, other_plan, Mode::kResume), schema::InputError);

  ChunkStore store(out, plan, Mode::kResume);
  LocalExecutor executor(AllComponents());
  std::vector<int> computed;
  class Recording final : public Executor {
   public:
    Recording(Executor& inner, std::vector<int>& seen) : inner_(inner), seen_(seen) {}
    void Compute(const Plan& p, const std::vector<int>& chunks, int threads, const ChunkDone& done) override {
      seen_ = chunks;
      inner_.Compute(p, chunks, threads, done);
    }

   private:
    Executor& inner_;
    std::vector<int>& seen_;
  } recording(executor, computed);
  std::map<int, ChunkResult> chunks = RunPlan(plan, recording, {2, &store, nullptr});
  const ExperimentAttempts resumed = Join(plan, chunks).front();
  EXPECT_EQ(computed.size(), plan.chunks().size() - 2);
  EXPECT_EQ(std::count(computed.begin(), computed.end(), 5), 0);
  EXPECT_EQ(resumed.lines, RunWholePlan(plan, executor, 1).front().lines);
  EXPECT_EQ(StoredChunks(out).size(), plan.chunks().size());  // appended to what was there
  store.Remove();
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "results.chunks"));
}

// A chunk edited in the store, one of another plan, a second copy and a torn last block are
// all computed again; the store keeps what reads back and grows from there.
TEST(ChunkStore, WhatDoesNotReadBackIsComputedAgainAndTheRestKept) {
  const testing::TempDir dir("chunk_store_damage");
  const std::filesystem::path out = dir.path() / "results";
  const Plan plan({SmallTable()});
  schema::ExperimentConfig other = SmallTable();
  other.seed = 99;
  const Plan other_plan({other});
  LocalExecutor executor(AllComponents());
  std::map<int, std::string> texts;
  executor.Compute(plan, {0, 1, 2}, 1, [&](int chunk, ChunkResult&&, const std::string& text) { texts[chunk] = text; });
  std::string foreign;
  executor.Compute(other_plan, {3}, 1, [&](int, ChunkResult&&, const std::string& text) { foreign = text; });
  std::string edited = texts.at(1);
  edited[edited.size() - 3] = edited[edited.size() - 3] == '1' ? '2' : '1';
  {
    ChunkStore store(out, plan, Mode::kFresh);
    store.Save(0, texts.at(0));
    store.Save(1, edited);
    store.Save(3, foreign);
    store.Save(0, texts.at(0));
    store.Save(2, texts.at(2));
  }
  const std::filesystem::path file = ChunkStorePath(out) / "chunks.csv";
  std::filesystem::resize_file(file, std::filesystem::file_size(file) - 5);  // chunk 2 torn by a kill
  {
    ChunkStore resumed(out, plan, Mode::kResume);
    EXPECT_EQ(resumed.unreadable(), 4);
    EXPECT_NE(resumed.first_unreadable().find("chunks.csv:"), std::string::npos) << resumed.first_unreadable();
    const std::map<int, ChunkResult> finished = resumed.TakeFinished();
    ASSERT_EQ(finished.size(), 1u);
    EXPECT_EQ(finished.count(0), 1u);
    EXPECT_EQ(StoredChunks(out), (std::vector<long long>{0}));  // rewritten with what read back
    resumed.Save(2, texts.at(2));
  }
  ChunkStore again(out, plan, Mode::kResume);
  EXPECT_EQ(again.unreadable(), 0);
  EXPECT_EQ(again.TakeFinished().size(), 2u);
}

TEST(ChunkStore, ATornChunkIsComputedAgainAndOverwriteDiscards) {
  const testing::TempDir dir("chunk_store_overwrite");
  const std::filesystem::path out = dir.path() / "results";
  const Plan plan({SmallTable()});
  {
    ChunkStore store(out, plan, Mode::kFresh);
    store.Save(1, "not a chunk");
  }
  {
    ChunkStore resumed(out, plan, Mode::kResume);  // a torn chunk is not trusted: computed again
    EXPECT_EQ(resumed.unreadable(), 1);
    EXPECT_EQ(resumed.TakeFinished().count(1), 0u);
  }
  ChunkStore(out, plan, Mode::kOverwrite);
  EXPECT_TRUE(StoredChunks(out).empty());
  // Killed between creating the folder and writing its plan: nothing to keep, a fresh start.
  std::filesystem::remove(dir.path() / "results.chunks" / "plan.csv");
  EXPECT_NO_THROW(ChunkStore(out, plan, Mode::kFresh));
}

}  // namespace
}  // namespace anchorbench::engine

namespace anchorbench::engine {
namespace {

// An error in the callback that keeps a chunk (a full disk, a folder in the way) leaves the
// threads' critical section and the parallel region as the executor's exception, not as
// std::terminate; the chunks that finished before it were handed over.
TEST(LocalExecutor, AnErrorWhileKeepingAChunkEndsTheCall) {
  const Plan plan({testing::SmallTable()});
  std::vector<int> chunks(plan.chunks().size());
  for (std::size_t i = 0; i < chunks.size(); ++i) chunks[i] = static_cast<int>(i);
  for (int threads : {1, 2}) {
    int kept = 0;
    LocalExecutor executor(testing::AllComponents());
    const auto keep = [&](int, ChunkResult&&, const std::string&) {
      if (++kept == 3) throw schema::InputError("chunk-000002.csv: cannot write the chunk: No space left on device");
    };
    EXPECT_THROW(executor.Compute(plan, chunks, threads, keep), schema::InputError) << threads << " threads";
    EXPECT_GE(kept, 3);
    EXPECT_LT(kept, static_cast<int>(chunks.size()) + 1);
  }
}

// A store claims the space of the chunks still to come before any work, and gives it back as
// chunks are saved; a disk without it is an error naming the store, and leaves no store behind.
TEST(ChunkStore, ClaimsItsSpaceBeforeAnyWork) {
  const testing::TempDir dir("chunk_store_space");
  const Plan plan({testing::SmallTable()});
  {
    ChunkStore store(dir.path() / "results", plan, Mode::kFresh, 1 << 20);
    EXPECT_GE(std::filesystem::file_size(dir.path() / "results.chunks" / ".reserved"), 1u << 20);
    store.Save(0, ChunkText(plan, 0, ChunkResult{}));
    EXPECT_LT(std::filesystem::file_size(dir.path() / "results.chunks" / ".reserved"), 1u << 20);
  }
  try {
    ChunkStore store(dir.path() / "huge", plan, Mode::kFresh, std::uintmax_t(1) << 62);
    FAIL() << "an exabyte was reserved";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("huge.chunks: the chunks of this run need about"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "huge.chunks"));
}

}  // namespace
}  // namespace anchorbench::engine
