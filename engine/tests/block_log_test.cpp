#include "anchorbench/engine/block_log.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::engine {
namespace {

namespace fs = std::filesystem;

// A reader's callback that keeps every block.
std::function<void(LoggedBlock&&)> Into(std::vector<LoggedBlock>& blocks) {
  return [&blocks](LoggedBlock&& block) { blocks.push_back(std::move(block)); };
}

// Rewriting keeps the blocks asked for, in order, whatever their texts hold.
TEST(BlockLog, ARewriteKeepsTheBlocksAskedFor) {
  const testing::TempDir dir("block_log_rewrite");
  const fs::path path = dir.path() / "log.csv";
  {
    BlockLog log(path, "unit");
    for (long long key = 0; key < 5; ++key) log.Append(key, std::to_string(key), std::string(static_cast<std::size_t>(key), 'x'));
  }
  RewriteBlockLog(path, "unit", [](std::size_t ordinal) { return ordinal % 2 == 0; });
  std::vector<LoggedBlock> blocks;
  EXPECT_EQ(ReadBlockLog(path, "unit", Into(blocks)), "");
  ASSERT_EQ(blocks.size(), 3u);
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    EXPECT_EQ(blocks[i].key, static_cast<long long>(2 * i));
    EXPECT_EQ(blocks[i].tag, std::to_string(2 * i));
    EXPECT_EQ(blocks[i].text, std::string(2 * i, 'x'));
  }
}

TEST(BlockLog, ReadsBackWhatWasAppendedWithTheTagsAndLines) {
  const testing::TempDir dir("block_log");
  const fs::path path = dir.path() / "log.csv";
  {
    BlockLog log(path, "unit");
    log.Append(3, "abc", "one\ntwo\n");
    log.Append(0, "", "");
    log.Append(7, "x,y", "unit,1,2,z\n");  // a text that looks like a header is still text
  }
  std::vector<LoggedBlock> blocks;
  EXPECT_EQ(ReadBlockLog(path, "unit", Into(blocks)), "");
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(blocks[0].key, 3);
  EXPECT_EQ(blocks[0].tag, "abc");
  EXPECT_EQ(blocks[0].text, "one\ntwo\n");
  EXPECT_EQ(blocks[1].line, 4);
  EXPECT_EQ(blocks[2].tag, "x,y");
  EXPECT_EQ(blocks[2].text, "unit,1,2,z\n");
  std::vector<LoggedBlock> none;
  EXPECT_EQ(ReadBlockLog(dir.path() / "absent.csv", "unit", Into(none)), "");
  EXPECT_TRUE(none.empty());
}

// A kill while a block is written leaves it short; a stray line cannot be delimited. Reading stops
// there, keeps what came before, and says where.
TEST(BlockLog, StopsAtATornBlockOrAStrayLineAndSaysWhere) {
  const testing::TempDir dir("block_log_torn");
  const fs::path path = dir.path() / "log.csv";
  {
    BlockLog log(path, "chunk");
    log.Append(1, "", "a\n");
    log.Append(2, "", "bbbbbbbb\n");
  }
  fs::resize_file(path, fs::file_size(path) - 3);
  std::vector<LoggedBlock> torn;
  const std::string torn_damage = ReadBlockLog(path, "chunk", Into(torn));
  ASSERT_EQ(torn.size(), 1u);
  EXPECT_NE(torn_damage.find("log.csv:3: chunk 2 is torn"), std::string::npos) << torn_damage;

  RewriteBlockLog(path, "chunk", [](std::size_t) { return true; });  // the whole blocks, nothing after
  std::vector<LoggedBlock> rewritten;
  EXPECT_EQ(ReadBlockLog(path, "chunk", Into(rewritten)), "");
  ASSERT_EQ(rewritten.size(), 1u);
  std::ofstream(path, std::ios::app) << "a stray line\n";
  std::vector<LoggedBlock> stray;
  const std::string stray_damage = ReadBlockLog(path, "chunk", Into(stray));
  ASSERT_EQ(stray.size(), 1u);
  EXPECT_NE(stray_damage.find("log.csv:3: not a block's header line"), std::string::npos) << stray_damage;
  std::vector<LoggedBlock> other_kind;  // another kind's log reads as damage
  EXPECT_NE(ReadBlockLog(path, "unit", Into(other_kind)), "");
  EXPECT_TRUE(other_kind.empty());
}

TEST(BlockLog, AFolderInItsPlaceIsRefusedNamingIt) {
  const testing::TempDir dir("block_log_folder");
  fs::create_directories(dir.path() / "log.csv");
  try {
    ReadBlockLog(dir.path() / "log.csv", "chunk", [](LoggedBlock&&) {});
    FAIL() << "a folder was read";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("log.csv: is not a file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace anchorbench::engine
