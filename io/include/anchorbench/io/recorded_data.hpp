#pragma once

#include <istream>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/schema/attempt.hpp"
#include "anchorbench/io/log_policy.hpp"

namespace anchorbench::io {

// The interchange formats (README, "Data formats"):
//   poses.csv   t,tag_id,x,y,z          tag positions in the world frame (s, m)
//   ranges.csv  t,tag_id,anchor_id,range
//   anchors.csv anchor_id,x,y,z[,bias]  ground truth, optional
// ID_Tag and ID_Anchor are accepted for tag_id and anchor_id (the authors' earlier library); the
// other column aliases and time units are in log_reader.hpp and docs/real_data.md.
// Each reader takes a stream and the name to use in messages; the Load* functions open a file.

struct PoseRecord {
  double t_s = 0.0;
  int tag_id = 0;
  Eigen::Vector3d p_world_tag = Eigen::Vector3d::Zero();
  int line = 0;  // in poses.csv, for messages
};

struct RangeRecord {
  double t_s = 0.0;
  int tag_id = 0;
  int anchor_id = 0;
  double range_m = 0.0;
  int line = 0;  // in its ranges file, for messages
  int file = 0;  // which ranges file (LogFiles::ranges), for messages
};

// A recording in the project's formats, whole: what simulate and the converters produce.
struct Recording {
  std::vector<PoseRecord> poses;
  std::vector<RangeRecord> ranges;
  std::map<int, schema::AnchorTruth> anchors;
};

// Whole files read through the streaming readers (log_reader.hpp) into memory, for tests, tools
// and examples; a replay streams instead. Rows come in time order under `policy`; with no `drops`
// to count them in, every drop is an error (policy.strict), so nothing is lost unseen.
std::vector<PoseRecord> ReadPoses(std::istream& in, const std::string& source, const LogPolicy& policy = {},
                                  LogDrops* drops = nullptr);
std::vector<RangeRecord> ReadRanges(std::istream& in, const std::string& source, const LogPolicy& policy = {},
                                    LogDrops* drops = nullptr);
std::map<int, schema::AnchorTruth> ReadAnchors(std::istream& in, const std::string& source);

std::vector<PoseRecord> LoadPoses(const std::string& path, const LogPolicy& policy = {}, LogDrops* drops = nullptr);
std::vector<RangeRecord> LoadRanges(const std::string& path, const LogPolicy& policy = {}, LogDrops* drops = nullptr);
std::map<int, schema::AnchorTruth> LoadAnchors(const std::string& path);

}  // namespace anchorbench::io
