#include "anchorbench/engine/chunk.hpp"

#include <sstream>

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/testing/components.hpp"
#include "anchorbench/testing/small_table.hpp"
#include "anchorbench/engine/run_plan.hpp"

namespace anchorbench::engine {
namespace {

using testing::AllComponents;
using testing::SmallTable;

std::string AttemptsCsv(const std::vector<schema::Attempt>& attempts, const std::vector<schema::RowConfig>& rows) {
  std::ostringstream csv;
  report::WriteAttempts(csv, attempts, rows);
  return csv.str();
}

// The units one after another on this thread, without a plan or an executor.
std::vector<schema::Attempt> UnitByUnit(const schema::ExperimentConfig& config) {
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  std::vector<schema::Attempt> attempts;
  std::vector<estimator::RangeSample> samples;
  for (std::size_t row = 0; row < rows.size(); ++row) {
    for (int realization = 0; realization < config.realizations; ++realization) {
      for (schema::Attempt& a : RunRealization(rows[row], static_cast<int>(row), config.seed, realization,
                                               AllComponents(), samples)) {
        attempts.push_back(std::move(a));
      }
    }
  }
  return attempts;
}

// Chunk by chunk on any thread count, the run is the units' run one after another, byte for byte.
TEST(RunPlan, IsTheWholeRunForAnyThreadCount) {
  const schema::ExperimentConfig config = SmallTable();
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  const std::string whole = AttemptsCsv(UnitByUnit(config), rows);
  const Plan plan({config});
  LocalExecutor executor(AllComponents());
  for (int threads : {1, 2, 3}) {
    long long last_done = -1;
    std::map<int, ChunkResult> chunks =
        RunPlan(plan, executor, {threads, nullptr, [&](long long done, long long total) {
                                   EXPECT_GT(done, last_done);
                                   EXPECT_EQ(total, plan.units());
                                   last_done = done;
                                 }});
    const ExperimentAttempts run = Join(plan, chunks).front();
    EXPECT_EQ(last_done, plan.units());
    EXPECT_EQ(AttemptsCsv(run.attempts, rows), whole) << threads << " threads";
    std::ostringstream from_lines;
    report::WriteAttemptLines(from_lines, run.lines);
    EXPECT_EQ(from_lines.str(), whole);
  }
}

// A chunk's text reads back to its lines and what the summaries use, compute_s included.
TEST(Chunk, ItsTextReadsBackToTheSameLines) {
  const Plan plan({SmallTable()});
  std::vector<estimator::RangeSample> samples;
  const ChunkResult computed = ComputeChunk(plan, 3, AllComponents(), samples);
  ASSERT_FALSE(computed.attempts.empty());
  const ChunkResult read = ParseChunk(plan, 3, ChunkText(plan, 3, computed), "chunk 3");
  EXPECT_EQ(read.lines, computed.lines);
  ASSERT_EQ(read.attempts.size(), computed.attempts.size());
  for (std::size_t i = 0; i < read.attempts.size(); ++i) {
    EXPECT_EQ(read.attempts[i].row, computed.attempts[i].row);
    EXPECT_EQ(read.attempts[i].realization, computed.attempts[i].realization);
    EXPECT_EQ(read.attempts[i].compute_s, computed.attempts[i].compute_s);
    EXPECT_EQ(read.attempts[i].t_init_s, computed.attempts[i].t_init_s);
  }
}

// An MPI worker's records with the chunk's text give rank 0 what parsing the text gives, on every
// chunk of a plan with several rows (none initialized as well as initialized attempts).
TEST(Chunk, ItsRecordsGiveWhatItsTextReadsBackTo) {
  const Plan plan({SmallTable()});
  std::vector<estimator::RangeSample> samples;
  for (int chunk = 0; chunk < static_cast<int>(plan.chunks().size()); ++chunk) {
    const ChunkResult computed = ComputeChunk(plan, chunk, AllComponents(), samples);
    const std::string text = ChunkText(plan, chunk, computed);
    const ChunkResult parsed = ParseChunk(plan, chunk, text, "text");
    const ChunkResult recorded = FromRecords(plan, chunk, text, ChunkRecords(plan, chunk, computed), "records");
    EXPECT_EQ(recorded.lines, parsed.lines) << chunk;
    ASSERT_EQ(recorded.attempts.size(), parsed.attempts.size()) << chunk;
    const std::vector<schema::RowConfig> rows = schema::RowsOf(SmallTable());
    std::ostringstream from_text, from_records;  // every field the summaries read, as written
    report::WriteAttempts(from_text, parsed.attempts, rows);
    report::WriteAttempts(from_records, recorded.attempts, rows);
    EXPECT_EQ(from_records.str(), from_text.str()) << chunk;
    for (std::size_t i = 0; i < parsed.attempts.size(); ++i) {
      EXPECT_EQ(recorded.attempts[i].compute_s, parsed.attempts[i].compute_s);
    }
  }
}

// Records of another chunk, cut short, or not matching the text's lines are refused.
TEST(Chunk, RecordsOfAnotherChunkOrCutShortAreRefused) {
  const Plan plan({SmallTable()});
  std::vector<estimator::RangeSample> samples;
  const ChunkResult three = ComputeChunk(plan, 3, AllComponents(), samples);
  const ChunkResult four = ComputeChunk(plan, 4, AllComponents(), samples);
  const std::string text = ChunkText(plan, 3, three), records = ChunkRecords(plan, 3, three);
  EXPECT_NO_THROW(FromRecords(plan, 3, text, records, "whole"));
  EXPECT_THROW(FromRecords(plan, 3, text, ChunkRecords(plan, 4, four), "another chunk's"), schema::InputError);
  EXPECT_THROW(FromRecords(plan, 3, text, records.substr(0, records.size() - 1), "cut"), schema::InputError);
  EXPECT_THROW(FromRecords(plan, 3, text.substr(0, text.rfind('\n', text.size() - 2) + 1), records, "a line short"),
               schema::InputError);
}

// A chunk cut short, one given for another, or one with a line too many is refused.
TEST(Chunk, ACutForeignOrLongChunkIsRefused) {
  const Plan plan({SmallTable()});
  std::vector<estimator::RangeSample> samples;
  const std::string text = ChunkText(plan, 3, ComputeChunk(plan, 3, AllComponents(), samples));
  const std::string cut = text.substr(0, text.rfind('\n', text.size() - 2) + 1);
  EXPECT_THROW(ParseChunk(plan, 3, cut, "cut"), schema::InputError);
  EXPECT_THROW(ParseChunk(plan, 4, text, "foreign"), schema::InputError);
  const std::string last_line = text.substr(cut.size());
  EXPECT_THROW(ParseChunk(plan, 3, text + last_line, "long"), schema::InputError);
  EXPECT_NO_THROW(ParseChunk(plan, 3, text, "whole"));
}

// A chunk names its index and plan and carries a checksum of its lines: an edited value, two
// lines swapped, a blank line, or the same chunk of a run with another seed is refused with the
// line that says why, before any field is read.
TEST(Chunk, AnEditedSwappedOrForeignChunkIsRefused) {
  const Plan plan({SmallTable()});
  schema::ExperimentConfig other_seed = SmallTable();
  other_seed.seed = 4294967301ull;  // 2^32 + 5: a seed cut to int would make it 5 and the plans equal
  const Plan other({other_seed});
  ASSERT_NE(plan.identity(), other.identity());
  std::vector<estimator::RangeSample> samples;
  const std::string text = ChunkText(plan, 3, ComputeChunk(plan, 3, AllComponents(), samples));
  ASSERT_EQ(text.rfind("# anchorbench chunk 3 of plan " + plan.identity() + ", fnv1a64 ", 0), 0u);
  const auto refusal = [&](const std::string& bad) {
    try {
      ParseChunk(plan, 3, bad, "c");
    } catch (const schema::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = text.find('\n', at);
    lines.push_back(text.substr(at, end + 1 - at));
    at = end + 1;
  }
  ASSERT_GE(lines.size(), 4u);
  std::string swapped;
  for (std::size_t i = 0; i < lines.size(); ++i) swapped += lines[i == 2 ? 3 : i == 3 ? 2 : i];
  std::string edited = text;
  edited[edited.rfind(',') - 1] = edited[edited.rfind(',') - 1] == '1' ? '2' : '1';
  std::string blank = text;
  blank.insert(lines[0].size() + lines[1].size(), "\n");
  for (const std::string& bad : {swapped, edited, blank}) {
    EXPECT_EQ(refusal(bad), "c:1: its lines do not match its checksum (edited or torn)");
  }
  EXPECT_NE(refusal(ChunkText(other, 3, ComputeChunk(other, 3, AllComponents(), samples))).find("is not chunk 3 of plan"),
            std::string::npos);
  EXPECT_NE(refusal(text.substr(lines[0].size())).find("not a chunk file"), std::string::npos);
}

// The shards of a plan hold its chunks round robin; joined, they are the whole run to the last
// byte (the merge command relies on it), for more shards than chunks too.
TEST(RunPlan, ShardsHoldEveryChunkOnceAndJoinToTheWholeRun) {
  const Plan plan({SmallTable()});  // 12 units, 12 chunks
  LocalExecutor executor(AllComponents());
  const std::string whole = RunWholePlan(plan, executor, 2).front().lines;
  for (int count : {1, 5, 12, 13}) {
    std::map<int, ChunkResult> joined;
    for (int index = 0; index < count; ++index) {
      const Shard shard{index, count};
      std::map<int, ChunkResult> part = RunPlan(plan, executor, {1 + index % 2, nullptr, nullptr, shard});
      EXPECT_EQ(static_cast<int>(part.size()), shard.ChunksOf(static_cast<int>(plan.chunks().size())));
      for (const auto& [chunk, result] : part) EXPECT_TRUE(shard.Holds(chunk));
      joined.merge(part);
    }
    EXPECT_EQ(Join(plan, joined).front().lines, whole) << count << " shards";
  }
}

TEST(Shard, IsParsedStrictly) {
  EXPECT_EQ(ParseShard("2/5", "--shard").index, 2);
  EXPECT_EQ(ParseShard("2/5", "--shard").count, 5);
  for (const char* bad : {"5/5", "-1/3", "1/0", "x", "1/", "/2", "1/2/3", "1 /2"}) {
    EXPECT_THROW(ParseShard(bad, "--shard"), schema::InputError) << bad;
  }
}

}  // namespace
}  // namespace anchorbench::engine
