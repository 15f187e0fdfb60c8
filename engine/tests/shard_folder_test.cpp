#include "anchorbench/engine/shard_folder.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::engine {
namespace {

namespace fs = std::filesystem;

// Shard 1 of 3 of a study of 7 record units: units 1 and 4, written into `folder`.
ShardInfo WriteUnits(const fs::path& folder, const std::map<int, std::string>& units) {
  fs::create_directories(folder);
  const ShardInfo info{{1, 3}, static_cast<int>(units.size()), "navigate", "small", "plan-x", "rev"};
  WriteShardUnits(
      [&folder](const std::string& name, const std::string& text) {
        std::ofstream(folder / name, std::ios::binary) << text;
      },
      info, {"seed: 1\n", {}}, units);
  return info;
}

std::string Refusal(const fs::path& folder, const ShardInfo& info) {
  try {
    ReadShardUnits(folder, info, 7);
  } catch (const schema::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ShardFolder, ARecordStudysUnitsReadBackAsWrittenWithTheirLines) {
  const testing::TempDir dir("shard_units");
  const ShardInfo info = WriteUnits(dir.path(), {{1, "a,1\nb,2\n"}, {4, "c,3\n"}});
  const std::map<int, ShardUnit> read = ReadShardUnits(dir.path(), info, 7);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read.at(1).text, "a,1\nb,2\n");
  EXPECT_EQ(read.at(4).text, "c,3\n");
  EXPECT_EQ(read.at(1).place.line, 1);  // each block's header line, for messages on its records
  EXPECT_EQ(read.at(4).place.line, 4);
  EXPECT_EQ(ReadShardInfo(dir.path()).command, "navigate");
}

TEST(ShardFolder, UnitsOfAnotherPlanOrShardOrTooFewAreRefusedNamingTheFile) {
  const testing::TempDir dir("shard_units_refused");
  ShardInfo info = WriteUnits(dir.path(), {{1, "a,1\n"}, {4, "c,3\n"}});
  ShardInfo other_plan = info;
  other_plan.plan = "plan-y";
  EXPECT_NE(Refusal(dir.path(), other_plan).find("records.csv:1: unit 1 does not match its checksum"), std::string::npos);
  ShardInfo other_shard = info;
  other_shard.shard = {2, 3};
  EXPECT_NE(Refusal(dir.path(), other_shard).find("is not a unit of shard 2/3"), std::string::npos);
  info.chunks = 3;
  EXPECT_NE(Refusal(dir.path(), info).find("holds 2 units"), std::string::npos);
  const ShardInfo unit_out_of_range = WriteUnits(dir.path() / "far", {{7, "x\n"}});
  EXPECT_NE(Refusal(dir.path() / "far", unit_out_of_range).find("unit 7 is not a unit"), std::string::npos);
  EXPECT_NE(Refusal(dir.path() / "none", info).find("records.csv: missing"), std::string::npos);
}

}  // namespace
}  // namespace anchorbench::engine
