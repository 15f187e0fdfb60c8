#pragma once

#include <istream>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/eval/attempt_evaluation.hpp"

namespace anchorbench::io {

// The interchange formats (README, "Data formats"):
//   poses.csv   t,tag_id,x,y,z          tag positions in the world frame (s, m)
//   ranges.csv  t,tag_id,anchor_id,range
//   anchors.csv anchor_id,x,y,z[,bias]  ground truth, optional
// ID_Tag and ID_Anchor are accepted for tag_id and anchor_id (the authors' earlier library).
// Each reader takes a stream and the name to use in messages; the Load* functions open a file.

struct PoseRecord {
  double t_s = 0.0;
  int tag_id = 0;
  Eigen::Vector3d p_world_tag = Eigen::Vector3d::Zero();
};

struct RangeRecord {
  double t_s = 0.0;
  int tag_id = 0;
  int anchor_id = 0;
  double range_m = 0.0;
  int line = 0;  // in ranges.csv, for messages
};

// A recording in the project's formats, whole: what simulate and the converters produce.
struct Recording {
  std::vector<PoseRecord> poses;
  std::vector<RangeRecord> ranges;
  std::map<int, eval::AnchorTruth> anchors;
};

// Poses in file order; time must increase strictly per tag.
std::vector<PoseRecord> ReadPoses(std::istream& in, const std::string& source);
// Ranges in non-decreasing time; negative ranges are an error.
std::vector<RangeRecord> ReadRanges(std::istream& in, const std::string& source);
std::map<int, eval::AnchorTruth> ReadAnchors(std::istream& in, const std::string& source);

std::vector<PoseRecord> LoadPoses(const std::string& path);
std::vector<RangeRecord> LoadRanges(const std::string& path);
std::map<int, eval::AnchorTruth> LoadAnchors(const std::string& path);

}  // namespace anchorbench::io
