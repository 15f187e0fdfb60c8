#include "anchorbench/io/hanyang.hpp"

#include <filesystem>

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/io/scenario_files.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::io {
namespace {

constexpr const char* kAnchorHeader =
    "%time,field.stamp,field.id,field.x,field.y,field.z,field.distanceFromTag,field.rssi,field.rssi_fp\n";

TEST(Hanyang, ConvertsACaseIntoTheProjectFormats) {
  testing::TempDir dir("hanyang");
  std::filesystem::create_directories(dir.path() / "case");
  dir.Write("case/A3.csv", std::string(kAnchorHeader) + "2000000100,2000000000,3,2.5,0.87,1.97,7.25,-79,-80\n" +
                               "2100000100,2100000000,3,2.5,0.87,1.97,7.5,-79,-80\n");
  dir.Write("case/A5.csv", std::string(kAnchorHeader) + "2050000100,2050000000,5,2.5,-0.87,0.5,6.0,-79,-80\n");
  // The trajectory starts 0.5 s before the first range; a repeated timestamp is dropped.
  dir.Write("case/trajectory.csv",
            "timestamp,x,y,z,heading_degrees\n1.5e9,0,0,0,0\n2.5e9,1,0,0.25,0\n2.5e9,9,9,9,0\n3.5e9,2,0,0.5,0\n");
  const HanyangCase converted = ConvertHanyangCase(dir.path() / "case");
  EXPECT_EQ(converted.recording.poses.size(), 3u);
  EXPECT_EQ(converted.recording.ranges.size(), 3u);
  EXPECT_EQ(converted.recording.anchors.size(), 2u);
  EXPECT_EQ(converted.dropped_poses, 1);
  ResultFolder out(dir.path() / "out", {});
  WriteRecording(out, converted.recording);
  out.Commit();

  const std::vector<RangeRecord> ranges = LoadRanges((dir.path() / "out" / "ranges.csv").string());
  ASSERT_EQ(ranges.size(), 3u);
  // Seconds since the earliest timestamp (the trajectory's 1.5 s), merged in time order.
  EXPECT_NEAR(ranges[0].t_s, 0.5, 1e-9);
  EXPECT_EQ(ranges[0].anchor_id, 3);
  EXPECT_NEAR(ranges[1].t_s, 0.55, 1e-9);
  EXPECT_EQ(ranges[1].anchor_id, 5);
  EXPECT_NEAR(ranges[2].range_m, 7.5, 1e-12);
  const std::vector<PoseRecord> poses = LoadPoses((dir.path() / "out" / "poses.csv").string());
  // Seconds since the earliest stamp; the tag is 1 m above the trajectory.
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_NEAR(poses[1].t_s, 1.0, 1e-9);
  EXPECT_TRUE(poses[1].p_world_tag.isApprox(Eigen::Vector3d(1.0, 0.0, 1.25)));
  const auto anchors = LoadAnchors((dir.path() / "out" / "anchors.csv").string());
  EXPECT_TRUE(anchors.at(5).p_world_anchor.isApprox(Eigen::Vector3d(2.5, -0.87, 0.5)));
}

TEST(Hanyang, MissingFilesAreInputErrors) {
  testing::TempDir dir("hanyang_bad");
  EXPECT_THROW(ConvertHanyangCase(dir.path()), schema::InputError);  // no anchor files
  dir.Write("A3.csv", std::string(kAnchorHeader) + "1,1,3,0,0,0,5,-79,-80\n");
  EXPECT_THROW(ConvertHanyangCase(dir.path()), schema::InputError);  // no trajectory.csv
}

}  // namespace
}  // namespace anchorbench::io
