#include "anchorbench/io/recorded_data.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::io {
namespace {

template <typename Load>
std::string ErrorFor(const std::string& csv, Load load) {
  testing::TempDir dir("csv");
  const std::string path = dir.Write("data.csv", csv);
  try {
    load(path);
  } catch (const schema::InputError& e) {
    return e.what();
  }
  return "";
}

// Without a tally the whole-file readers are strict: every drop is an error.
std::string PosesError(const std::string& csv) {
  return ErrorFor(csv, [](const std::string& path) { return LoadPoses(path); });
}
std::string RangesError(const std::string& csv) {
  return ErrorFor(csv, [](const std::string& path) { return LoadRanges(path); });
}
std::string AnchorsError(const std::string& csv) { return ErrorFor(csv, LoadAnchors); }

TEST(RecordedData, MissingColumnNamesIt) {
  EXPECT_NE(PosesError("t,tag_id,x,y\n0,0,1,2\n").find("data.csv:1: missing column 'z'"), std::string::npos);
  EXPECT_NE(RangesError("t,tag_id,range\n").find("missing column 'anchor_id' (or 'ID_Anchor', 'anchor')"),
            std::string::npos);
  EXPECT_NE(RangesError("when,tag_id,anchor_id,range\n").find("data.csv:1: missing a time column"), std::string::npos);
}

TEST(RecordedData, BadNumbersNameFileLineAndColumn) {
  EXPECT_NE(RangesError("t,tag_id,anchor_id,range\n0,0,1,5\n0.1,0,1,abc\n")
                .find("data.csv:3: column 'range': 'abc' is not a number"),
            std::string::npos);
  EXPECT_NE(RangesError("t,tag_id,anchor_id,range\nnan,0,1,5\n").find("data.csv:2: column 't': 'nan' is not finite"),
            std::string::npos);
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n0,0.5,0,0,0\n").find("column 'tag_id': '0.5' is not an integer"),
            std::string::npos);
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n0,0,1,2\n").find("data.csv:2: expected 5 fields"), std::string::npos);
}

TEST(RecordedData, WithoutATallyEveryDropIsAnError) {
  EXPECT_NE(RangesError("t,tag_id,anchor_id,range\n0,0,1,-0.5\n").find("data.csv:2: range -0.5 is not positive (--strict)"),
            std::string::npos);
  EXPECT_NE(RangesError("t,tag_id,anchor_id,range\n0,0,1,nan\n").find("data.csv:2: range nan is not finite"),
            std::string::npos);
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n0,0,inf,0,0\n").find("data.csv:2: position (inf, 0, 0) is not finite"),
            std::string::npos);
  EXPECT_NE(RangesError("t,tag_id,anchor_id,range\n1,0,1,5\n0.5,0,1,5\n").find("data.csv:3: t=0.5 comes after t=1"),
            std::string::npos);
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n1,0,0,0,0\n1,0,1,0,0\n").find("data.csv:3: tag 0 has another pose at t=1"),
            std::string::npos);
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n1,0,0,0,0\n1,0,0,0,0\n").find("data.csv:3: tag 0 repeats its pose of line 2"),
            std::string::npos);
  EXPECT_NE(AnchorsError("anchor_id,x,y,z\n1,0,0,0\n1,1,1,1\n").find("data.csv:3: anchor 1 listed twice"),
            std::string::npos);
}

TEST(RecordedData, AcceptsTheEarlierLibrarysColumnNames) {
  EXPECT_EQ(RangesError("t,ID_Tag,ID_Anchor,range\n0,0,3,5\n"), "");
  EXPECT_EQ(PosesError("t,ID_Tag,x,y,z\n0,0,1,2,3\n"), "");
}

TEST(RecordedData, EmptyAndMissingFiles) {
  EXPECT_NE(PosesError("").find("data.csv:1: empty file"), std::string::npos);
  EXPECT_THROW(LoadRanges("/nonexistent/ranges.csv"), schema::InputError);
}

// The readers take any stream: a fuzzer or a test needs no file.
TEST(RecordedData, ReadsFromAStreamNamingItInMessages) {
  std::istringstream good("t,tag_id,anchor_id,range\n# a comment\n\n0.5,1,3,4.25\n");
  const std::vector<RangeRecord> ranges = ReadRanges(good, "<buffer>");
  ASSERT_EQ(ranges.size(), 1u);
  EXPECT_EQ(ranges[0].line, 4);
  EXPECT_EQ(ranges[0].range_m, 4.25);
  std::istringstream bad("t,tag_id,x,y,z\n0,0,1,2,\x01\n");
  try {
    ReadPoses(bad, "<buffer>");
    FAIL() << "no error";
  } catch (const schema::InputError& e) {
    // control bytes are escaped, so the message stays one printable line
    EXPECT_EQ(std::string(e.what()), "<buffer>:2: column 'z': '\\x01' is not a number");
  }
}

// Poses of several tags come interleaved in time, as a recorder writes them; a file with one
// tag's poses after another's is out of order.
TEST(RecordedData, PosesOfSeveralTagsAreInTimeOrder) {
  std::istringstream in("t,tag_id,x,y,z\n0,0,0,0,0\n0,1,1,1,1\n0.5,1,3,3,3\n1,0,2,2,2\n");
  const std::vector<PoseRecord> poses = ReadPoses(in, "<buffer>");
  ASSERT_EQ(poses.size(), 4u);
  EXPECT_EQ(poses[2].tag_id, 1);
  EXPECT_EQ(poses[2].p_world_tag, Eigen::Vector3d(3, 3, 3));
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n0,0,0,0,0\n1,0,2,2,2\n0,1,1,1,1\n").find("data.csv:4: t=0 comes after t=1"),
            std::string::npos);
}

}  // namespace
}  // namespace anchorbench::io
