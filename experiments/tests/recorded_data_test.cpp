#include "anchorbench/experiments/recorded_data.hpp"

#include <gtest/gtest.h>

#include "anchorbench/experiments/input_error.hpp"
#include "temp_dir.hpp"

namespace anchorbench::experiments {
namespace {

template <typename Load>
std::string ErrorFor(const std::string& csv, Load load) {
  testing::TempDir dir("csv");
  const std::string path = dir.Write("data.csv", csv);
  try {
    load(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string PosesError(const std::string& csv) { return ErrorFor(csv, PoseTracks::Load); }
std::string RangesError(const std::string& csv) { return ErrorFor(csv, LoadRanges); }
std::string AnchorsError(const std::string& csv) { return ErrorFor(csv, LoadAnchors); }

TEST(RecordedData, MissingColumnNamesIt) {
  EXPECT_NE(PosesError("t,tag_id,x,y\n0,0,1,2\n").find("data.csv:1: missing column 'z'"), std::string::npos);
  EXPECT_NE(RangesError("t,tag_id,range\n").find("missing column 'anchor_id' or 'ID_Anchor'"), std::string::npos);
}

TEST(RecordedData, BadNumbersNameFileLineAndColumn) {
  EXPECT_NE(RangesError("t,tag_id,anchor_id,range\n0,0,1,5\n0.1,0,1,abc\n")
                .find("data.csv:3: column 'range': 'abc' is not a number"),
            std::string::npos);
  EXPECT_NE(RangesError("t,tag_id,anchor_id,range\n0,0,1,nan\n").find("data.csv:2: column 'range': 'nan' is not finite"),
            std::string::npos);
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n0,0,inf,0,0\n").find("'inf' is not finite"), std::string::npos);
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n0,0.5,0,0,0\n").find("column 'tag_id': '0.5' is not an integer"),
            std::string::npos);
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n0,0,1,2\n").find("data.csv:2: expected 5 fields"), std::string::npos);
}

TEST(RecordedData, NegativeRangeAndBackwardsTimeAreErrors) {
  EXPECT_NE(RangesError("t,tag_id,anchor_id,range\n0,0,1,-0.5\n").find("data.csv:2: column 'range': negative range"),
            std::string::npos);
  EXPECT_NE(RangesError("t,tag_id,anchor_id,range\n1,0,1,5\n0.5,0,1,5\n").find("data.csv:3: time goes backwards"),
            std::string::npos);
  EXPECT_NE(PosesError("t,tag_id,x,y,z\n1,0,0,0,0\n1,0,1,0,0\n").find("data.csv:3: time goes backwards or repeats"),
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
  EXPECT_THROW(LoadRanges("/nonexistent/ranges.csv"), InputError);
}

TEST(PoseTracks, InterpolatesLinearlyPerTagAndNeverExtrapolates) {
  PoseTracks tracks;
  tracks.Add(0, 0.0, Eigen::Vector3d(0, 0, 0));
  tracks.Add(0, 1.0, Eigen::Vector3d(2, 4, 6));
  tracks.Add(1, 0.5, Eigen::Vector3d(10, 0, 0));
  tracks.Add(1, 1.5, Eigen::Vector3d(10, 10, 0));
  EXPECT_TRUE(tracks.At(0, 0.25)->isApprox(Eigen::Vector3d(0.5, 1.0, 1.5)));  // 1/4 of the way
  EXPECT_TRUE(tracks.At(1, 1.0)->isApprox(Eigen::Vector3d(10, 5, 0)));        // tag 1 on its own track
  EXPECT_TRUE(tracks.At(0, 1.0)->isApprox(Eigen::Vector3d(2, 4, 6)));         // the end point itself
  EXPECT_FALSE(tracks.At(0, 1.01).has_value());
  EXPECT_FALSE(tracks.At(1, 0.4).has_value());
  EXPECT_FALSE(tracks.At(7, 0.5).has_value());  // unknown tag
}

}  // namespace
}  // namespace anchorbench::experiments
