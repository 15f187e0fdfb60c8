#include "anchorbench/io/log_reader.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::io {
namespace {

std::vector<RangeRecord> Ranges(const std::string& csv, const LogPolicy& policy, LogDrops& drops,
                                const std::string& source = "r.csv") {
  std::istringstream in(csv);
  RangeStream stream(in, source, 0, policy, drops, AnchorIdFromFileName(source), 7);
  std::vector<RangeRecord> out;
  for (RangeRecord r; stream.Next(r);) out.push_back(r);
  return out;
}

std::vector<PoseRecord> Poses(const std::string& csv, const LogPolicy& policy, LogDrops& drops) {
  std::istringstream in(csv);
  PoseStream stream(in, "p.csv", policy, drops);
  std::vector<PoseRecord> out;
  for (PoseRecord p; stream.Next(p);) out.push_back(p);
  return out;
}

template <typename Read>
std::string ErrorOf(Read read) {
  try {
    read();
  } catch (const schema::InputError& e) {
    return e.what();
  }
  return "";
}

const DropTally& Tally(const LogDrops& drops, Drop reason, int id) {
  const auto& by_id = IsPoseDrop(reason) ? drops.poses_by_tag() : drops.ranges_by_anchor();
  return by_id.at(id).at(reason);
}

// Each kind of bad measurement a radio produces is dropped, counted by anchor and reason, and
// remembered by its first line; the clean rows pass unchanged.
TEST(LogReader, BadMeasurementsAreDroppedAndCountedPerAnchorAndReason) {
  LogDrops drops;
  const std::vector<RangeRecord> kept = Ranges(
      "t,tag_id,anchor_id,range\n"
      "0,0,1,5\n"          // 2 kept
      "0.1,0,1,-11.12\n"   // 3 negative
      "0.2,0,2,0\n"        // 4 zero
      "0.3,0,1,nan\n"      // 5
      "0.4,0,2,inf\n"      // 6
      "0.5,0,1,5000\n"     // 7 beyond 1000 m
      "0.6,0,1,4\n"        // 8 kept
      "0.6,0,1,4\n"        // 9 an exact repeat
      "0.6,0,2,4\n"        // 10 kept: another anchor
      "0.7,0,1,-1\n",      // 11 negative again
      LogPolicy{}, drops);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[1].line, 8);
  EXPECT_EQ(kept[2].anchor_id, 2);
  EXPECT_EQ(drops.total(), 7);
  EXPECT_EQ(Tally(drops, Drop::kRangeNotPositive, 1).count, 2);
  EXPECT_EQ(Tally(drops, Drop::kRangeNotPositive, 1).first, "r.csv:3");
  EXPECT_EQ(Tally(drops, Drop::kRangeNotPositive, 2).first, "r.csv:4");
  EXPECT_EQ(Tally(drops, Drop::kRangeNotFinite, 1).first, "r.csv:5");
  EXPECT_EQ(Tally(drops, Drop::kRangeNotFinite, 2).first, "r.csv:6");
  EXPECT_EQ(Tally(drops, Drop::kRangeBeyondMax, 1).first, "r.csv:7");
  EXPECT_EQ(Tally(drops, Drop::kDuplicateRange, 1).first, "r.csv:9");
}

TEST(LogReader, StrictTurnsEveryDropIntoAnErrorNamingFileAndLine) {
  LogPolicy strict;
  strict.strict = true;
  LogDrops drops;
  EXPECT_EQ(ErrorOf([&] { Ranges("t,tag_id,anchor_id,range\n0,0,1,5\n0.1,0,1,-11.12\n", strict, drops); }),
            "r.csv:3: range -11.12 is not positive (--strict)");
  EXPECT_EQ(ErrorOf([&] { Ranges("t,tag_id,anchor_id,range\n0,0,1,5\n0,0,1,5\n", strict, drops); }),
            "r.csv:3: a repeat of an earlier row (--strict)");
  EXPECT_EQ(ErrorOf([&] { Poses("t,tag_id,x,y,z\n0,1,1,2,3\n0,1,1,2,3\n", strict, drops); }),
            "p.csv:3: tag 1 repeats its pose of line 2 (--strict)");
  EXPECT_EQ(drops.total(), 0);
}

TEST(LogReader, AMalformedFileStaysAnErrorWhateverThePolicy) {
  LogPolicy lenient;
  lenient.out_of_order = LogPolicy::OutOfOrder::kDrop;
  lenient.repeated_poses = LogPolicy::RepeatedPoses::kAverage;
  LogDrops drops;
  EXPECT_EQ(ErrorOf([&] { Ranges("t,tag_id,anchor_id,range\n0,0,1,abc\n", lenient, drops); }),
            "r.csv:2: column 'range': 'abc' is not a number");
  EXPECT_EQ(ErrorOf([&] { Ranges("t,tag_id,anchor_id,range\n0,0,1\n", lenient, drops); }),
            "r.csv:2: expected 4 fields as in the header, found 3");
  EXPECT_EQ(ErrorOf([&] { Poses("t,tag_id,x,y\n", lenient, drops); }), "p.csv:1: missing column 'z' or 'pz' or 'p_z' or "
                                                                       "'pos_z' or 'position_z'");
}

// A recorder that writes one pose row per range taken at that instant repeats the pose: the
// repeats are dropped and counted. Two different positions at one time follow the policy.
TEST(LogReader, RepeatedPosesAreDroppedAndConflictsFollowThePolicy) {
  const std::string repeated = "t,tag_id,x,y,z\n0,1,0,0,0\n1,1,1,2,3\n1,1,1,2,3\n1,1,1,2,3\n2,1,2,0,0\n";
  LogDrops drops;
  EXPECT_EQ(Poses(repeated, LogPolicy{}, drops).size(), 3u);
  EXPECT_EQ(Tally(drops, Drop::kRepeatedPose, 1).count, 2);
  EXPECT_EQ(Tally(drops, Drop::kRepeatedPose, 1).first, "p.csv:4");

  const std::string conflicting = "t,tag_id,x,y,z\n0,1,0,0,0\n0,2,5,5,5\n0,1,2,0,0\n1,1,1,1,1\n";
  EXPECT_EQ(ErrorOf([&] { Poses(conflicting, LogPolicy{}, drops); }),
            "p.csv:4: tag 1 has another pose at t=0: (2, 0, 0) here, (0, 0, 0) at line 2 (2 m apart, beyond "
            "--average-poses-within-m 0.05); --repeated-poses first or average accepts it");
  LogPolicy first;
  first.repeated_poses = LogPolicy::RepeatedPoses::kFirst;
  LogDrops first_drops;
  const std::vector<PoseRecord> kept_first = Poses(conflicting, first, first_drops);
  ASSERT_EQ(kept_first.size(), 3u);
  EXPECT_EQ(kept_first[0].p_world_tag, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(kept_first[1].tag_id, 2);
  EXPECT_EQ(Tally(first_drops, Drop::kConflictingPose, 1).first, "p.csv:4");
  LogPolicy average;
  average.repeated_poses = LogPolicy::RepeatedPoses::kAverage;
  LogDrops average_drops;
  const std::vector<PoseRecord> kept_average = Poses(conflicting, average, average_drops);
  ASSERT_EQ(kept_average.size(), 3u);
  EXPECT_EQ(kept_average[0].p_world_tag, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(Tally(average_drops, Drop::kAveragedPose, 1).count, 1);
}

// Two stamps of one pose a few centimetres apart (a tracker and a recorder each writing it) are
// averaged and counted by default; the bound is a setting.
TEST(LogReader, PosesWithinFiveCentimetresAtOneTimeAreAveragedByDefault) {
  const std::string close = "t,tag_id,x,y,z\n0,1,0,0,0\n0,1,0.04,0,0\n1,1,1,0,0\n";
  LogDrops drops;
  const std::vector<PoseRecord> kept = Poses(close, LogPolicy{}, drops);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_DOUBLE_EQ(kept[0].p_world_tag.x(), 0.02);
  EXPECT_EQ(Tally(drops, Drop::kAveragedPose, 1).count, 1);
  LogPolicy tight;
  tight.average_within_m = 0.01;
  EXPECT_NE(ErrorOf([&] { Poses(close, tight, drops); }).find("beyond --average-poses-within-m 0.01"), std::string::npos);
}

TEST(LogReader, OutOfOrderRowsAreAnErrorOrDroppedOrSortedWithinTheWindow) {
  const std::string late = "t,tag_id,anchor_id,range\n0,0,1,5\n1,0,1,6\n0.5,0,1,7\n2,0,1,8\n";
  LogDrops drops;
  EXPECT_EQ(ErrorOf([&] { Ranges(late, LogPolicy{}, drops); }),  // the default sorts within 0.1 s
            "r.csv:4: t=0.5 comes after t=1, more than --sort-window-s 0.1 late (a larger --sort-window-s, or "
            "--out-of-order drop, accepts it)");
  LogPolicy error;
  error.out_of_order = LogPolicy::OutOfOrder::kError;
  EXPECT_EQ(ErrorOf([&] { Ranges(late, error, drops); }),
            "r.csv:4: time goes backwards (t=0.5 after t=1); --out-of-order drop or sort accepts such rows");
  LogPolicy drop;
  drop.out_of_order = LogPolicy::OutOfOrder::kDrop;
  EXPECT_EQ(Ranges(late, drop, drops).size(), 3u);
  EXPECT_EQ(Tally(drops, Drop::kLateRange, 1).first, "r.csv:4");
  LogPolicy sort;
  sort.out_of_order = LogPolicy::OutOfOrder::kSort;
  sort.sort_window_s = 0.6;
  const std::vector<RangeRecord> sorted = Ranges(late, sort, drops);
  ASSERT_EQ(sorted.size(), 4u);
  for (std::size_t i = 1; i < sorted.size(); ++i) EXPECT_LE(sorted[i - 1].t_s, sorted[i].t_s);
  EXPECT_EQ(sorted[1].line, 4);
  sort.sort_window_s = 0.4;
  EXPECT_EQ(ErrorOf([&] { Ranges(late, sort, drops); }),
            "r.csv:4: t=0.5 comes after t=1, more than --sort-window-s 0.4 late (a larger --sort-window-s, or "
            "--out-of-order drop, accepts it)");
}

TEST(LogReader, TimeColumnsInSecondsMillisecondsNanosecondsAndIsoDates) {
  LogDrops drops;
  EXPECT_DOUBLE_EQ(Ranges("timestamp,tag,anchor,distance\n12.5,0,1,5\n", LogPolicy{}, drops)[0].t_s, 12.5);
  EXPECT_DOUBLE_EQ(Ranges("t_ms,tag,anchor,range_m\n12500,0,1,5\n", LogPolicy{}, drops)[0].t_s, 12.5);
  EXPECT_DOUBLE_EQ(Ranges("t_us,tag,anchor,range_m\n12500000,0,1,5\n", LogPolicy{}, drops)[0].t_s, 12.5);
  const RangeRecord ns = Ranges("t_ns,tag,anchor,range\n1714564803250000000,0,1,5\n", LogPolicy{}, drops)[0];
  EXPECT_DOUBLE_EQ(ns.t_s, 1714564803.25);
  const RangeRecord iso = Ranges("time,tag,anchor,range\n2024-05-01T12:00:03.25Z,0,1,5\n", LogPolicy{}, drops)[0];
  EXPECT_DOUBLE_EQ(iso.t_s, 1714564803.25);
  EXPECT_DOUBLE_EQ(*ParseIsoTime("2024-05-01 14:00:03.25+02:00"), 1714564803.25);
  EXPECT_DOUBLE_EQ(*ParseIsoTime("1970-01-01T00:00:00"), 0.0);
  EXPECT_FALSE(ParseIsoTime("2024-13-01T00:00:00"));
  EXPECT_FALSE(ParseIsoTime("2024-05-01"));
  EXPECT_FALSE(ParseIsoTime("12.5"));
  EXPECT_EQ(ErrorOf([&] { Ranges("time,tag,anchor,range\n2024-05-01T25:00:00,0,1,5\n", LogPolicy{}, drops); }),
            "r.csv:2: column 'time': '2024-05-01T25:00:00' is not a number");
}

TEST(LogReader, ColumnAliasesAndOneFilePerAnchor) {
  LogDrops drops;
  // No anchor column: the number the file's name ends in; no tag column: the default tag.
  const std::vector<RangeRecord> a3 = Ranges("\"t\",\"distance\"\n0,5\n", LogPolicy{}, drops, "logs/anchor_3.csv");
  EXPECT_EQ(a3[0].anchor_id, 3);
  EXPECT_EQ(a3[0].tag_id, 7);
  EXPECT_EQ(ErrorOf([&] { Ranges("t,distance\n0,5\n", LogPolicy{}, drops, "log_3_a.csv"); }),
            "log_3_a.csv:1: missing column 'anchor_id' (or 'ID_Anchor', 'anchor'), and the file's name does not end in "
            "an anchor number");
  EXPECT_EQ(AnchorIdFromFileName("A12.csv"), 12);
  EXPECT_FALSE(AnchorIdFromFileName("ranges.csv"));
  const std::vector<PoseRecord> poses = Poses("stamp,px,py,pz\n0,1,2,3\n", LogPolicy{}, drops);
  EXPECT_EQ(poses[0].tag_id, 0);
  EXPECT_EQ(poses[0].p_world_tag, Eigen::Vector3d(1, 2, 3));
}

// Several ranges files merge by time; poses come before ranges at equal times; the survey finds
// what the replay will see, so errors come before any work.
TEST(LogReader, RecordedLogMergesFilesInTimeOrder) {
  testing::TempDir dir("log");
  const LogFiles files{dir.Write("poses.csv", "t,x,y,z\n0,0,0,0\n1,1,0,0\n1,1,0,0\n2,2,0,0\n"),
                       {dir.Write("A3.csv", "t,range\n0.5,3\n1.5,-2\n"), dir.Write("A4.csv", "t,range\n0.2,4\n1,4\n1.7,4\n")}};
  const LogSurvey survey = SurveyLog(files, LogPolicy{});
  EXPECT_EQ(survey.tag_ids, std::set<int>({0}));
  EXPECT_EQ(survey.anchor_ids, std::set<int>({3, 4}));
  EXPECT_EQ(survey.pose_rows, 4);
  EXPECT_EQ(survey.range_rows, 5);
  EXPECT_EQ(survey.drops.total(), 2);  // a repeated pose, a negative range

  LogDrops drops;
  RecordedLog log(files, LogPolicy{}, survey.default_tag_id, drops);
  std::string order;
  RecordedLog::Kind kind;
  PoseRecord pose;
  RangeRecord range;
  while (log.Next(kind, pose, range)) {
    order += kind == RecordedLog::Kind::kPose ? 'p' : 'r';  // appended piecewise: GCC 12 -Wrestrict
    order += std::to_string(kind == RecordedLog::Kind::kPose ? static_cast<int>(pose.t_s) : range.anchor_id);
    order += ' ';
  }
  EXPECT_EQ(order, "p0 r4 r3 p1 r4 r4 p2 ");
  EXPECT_EQ(drops.total(), 2);
}

}  // namespace
}  // namespace anchorbench::io
