#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace anchorbench::experiments {

// The interchange formats (README, "Data formats"):
//   poses.csv   t,tag_id,x,y,z          tag positions in the world frame (s, m)
//   ranges.csv  t,tag_id,anchor_id,range
//   anchors.csv anchor_id,x,y,z[,bias]  ground truth, optional
// ID_Tag and ID_Anchor are accepted for tag_id and anchor_id (the authors' earlier library).

struct RangeRecord {
  double t_s = 0.0;
  int tag_id = 0;
  int anchor_id = 0;
  double range_m = 0.0;
  int line = 0;  // in ranges.csv, for messages
};

struct AnchorTruth {
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  std::optional<double> bias_m;
};

// Tag positions per tag, strictly increasing in time, linearly interpolated at range times.
class PoseTracks {
 public:
  static PoseTracks Load(const std::string& path);
  void Add(int tag_id, double t_s, const Eigen::Vector3d& p_world_tag);  // in time order per tag

  // Interpolated position; nullopt outside the tag's time span (never extrapolated) or for a tag
  // without poses.
  std::optional<Eigen::Vector3d> At(int tag_id, double t_s) const;

 private:
  struct Track {
    std::vector<double> t_s;
    std::vector<Eigen::Vector3d> p_world_tag;
  };
  std::map<int, Track> tracks_;
};

// Ranges in non-decreasing time; negative ranges are an error.
std::vector<RangeRecord> LoadRanges(const std::string& path);
std::map<int, AnchorTruth> LoadAnchors(const std::string& path);

}  // namespace anchorbench::experiments
