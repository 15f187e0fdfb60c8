#include "anchorbench/engine/block_log.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::engine {
namespace {

namespace fs = std::filesystem;

TEST(BlockLog, ReadsBackWhatWasAppendedWithTheTagsAndLines) {
  const testing::TempDir dir("block_log");
  const fs::path path = dir.path() / "log.csv";
  {
    BlockLog log(path, "unit");
    log.Append(3, "abc", "one\ntwo\n");
    log.Append(0, "", "");
    log.Append(7, "x,y", "unit,1,2,z\n");  // a text that looks like a header is still text
  }
  const BlockLogContents contents = ReadBlockLog(path, "unit");
  EXPECT_TRUE(contents.clean);
  ASSERT_EQ(contents.blocks.size(), 3u);
  EXPECT_EQ(contents.blocks[0].key, 3);
  EXPECT_EQ(contents.blocks[0].tag, "abc");
  EXPECT_EQ(contents.blocks[0].text, "one\ntwo\n");
  EXPECT_EQ(contents.blocks[1].line, 4);
  EXPECT_EQ(contents.blocks[2].tag, "x,y");
  EXPECT_EQ(contents.blocks[2].text, "unit,1,2,z\n");
  EXPECT_TRUE(ReadBlockLog(dir.path() / "absent.csv", "unit").blocks.empty());
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
  BlockLogContents torn = ReadBlockLog(path, "chunk");
  EXPECT_FALSE(torn.clean);
  ASSERT_EQ(torn.blocks.size(), 1u);
  EXPECT_NE(torn.damage.find("log.csv:3: chunk 2 is torn"), std::string::npos) << torn.damage;

  RewriteBlockLog(path, "chunk", torn.blocks);
  std::ofstream(path, std::ios::app) << "a stray line\n";
  const BlockLogContents stray = ReadBlockLog(path, "chunk");
  ASSERT_EQ(stray.blocks.size(), 1u);
  EXPECT_NE(stray.damage.find("log.csv:3: not a block's header line"), std::string::npos) << stray.damage;
  EXPECT_TRUE(ReadBlockLog(path, "unit").blocks.empty());  // another kind's log reads as damage
}

TEST(BlockLog, AFolderInItsPlaceIsRefusedNamingIt) {
  const testing::TempDir dir("block_log_folder");
  fs::create_directories(dir.path() / "log.csv");
  try {
    ReadBlockLog(dir.path() / "log.csv", "chunk");
    FAIL() << "a folder was read";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("log.csv: is not a file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace anchorbench::engine
