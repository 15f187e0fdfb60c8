#include "anchorbench/io/scenario_files.hpp"

#include <algorithm>
#include <vector>

#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/output_folder.hpp"

namespace anchorbench::io {

void WritePoses(std::ostream& out, std::span<const PoseRecord> poses) {
  out << "t,tag_id,x,y,z\n";
  for (const PoseRecord& pose : poses) {
    const Eigen::Vector3d& p = pose.p_world_tag;
    out << FormatNumber(pose.t_s) << ',' << pose.tag_id << ',' << FormatNumber(p.x()) << ',' << FormatNumber(p.y())
        << ',' << FormatNumber(p.z()) << '\n';
  }
}

void WriteRanges(std::ostream& out, std::span<const RangeRecord> ranges) {
  out << "t,tag_id,anchor_id,range\n";
  for (const RangeRecord& r : ranges) {
    out << FormatNumber(r.t_s) << ',' << r.tag_id << ',' << r.anchor_id << ',' << FormatNumber(r.range_m) << '\n';
  }
}

void WriteAnchors(std::ostream& out, const std::map<int, eval::AnchorTruth>& anchors) {
  const bool with_bias =
      std::any_of(anchors.begin(), anchors.end(), [](const auto& entry) { return entry.second.bias_m.has_value(); });
  out << "anchor_id,x,y,z" << (with_bias ? ",bias" : "") << '\n';
  for (const auto& [id, truth] : anchors) {
    const Eigen::Vector3d& p = truth.p_world_anchor;
    out << id << ',' << FormatNumber(p.x()) << ',' << FormatNumber(p.y()) << ',' << FormatNumber(p.z());
    if (with_bias) out << ',' << FormatOptional(truth.bias_m);
    out << '\n';
  }
}

void WriteScenarioFiles(const sim::Scenario& scenario, const std::filesystem::path& folder) {
  std::vector<PoseRecord> poses;
  for (std::size_t k = 0; k < scenario.t_s.size(); ++k) {
    for (std::size_t tag = 0; tag < scenario.p_world_tag_reported.size(); ++tag) {
      poses.push_back({scenario.t_s[k], static_cast<int>(tag), scenario.p_world_tag_reported[tag][k]});
    }
  }
  std::vector<RangeRecord> ranges;
  for (const sim::SimRange& r : scenario.ranges) ranges.push_back({r.t_s, r.tag_id, r.anchor_id, r.range_m, 0});
  std::map<int, eval::AnchorTruth> anchors;
  for (const sim::SimAnchor& a : scenario.anchors) anchors[a.id] = {a.p_world_anchor, a.bias_m};

  WriteRecordingFiles(folder, poses, ranges, anchors);
}

void WriteRecordingFiles(const std::filesystem::path& folder, std::span<const PoseRecord> poses,
                         std::span<const RangeRecord> ranges, const std::map<int, eval::AnchorTruth>& anchors) {
  CreateFolder(folder);
  AtomicFile poses_file(folder / "poses.csv");
  WritePoses(poses_file.stream(), poses);
  AtomicFile ranges_file(folder / "ranges.csv");
  WriteRanges(ranges_file.stream(), ranges);
  AtomicFile anchors_file(folder / "anchors.csv");
  WriteAnchors(anchors_file.stream(), anchors);
  poses_file.Commit();
  ranges_file.Commit();
  anchors_file.Commit();
}

}  // namespace anchorbench::io
