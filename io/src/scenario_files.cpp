#include "anchorbench/io/scenario_files.hpp"

#include <algorithm>
#include <vector>

#include "anchorbench/io/format.hpp"

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

void WriteAnchors(std::ostream& out, const std::map<int, schema::AnchorTruth>& anchors) {
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

Recording RecordingOf(const sim::Scenario& scenario) {
  Recording recording;
  for (std::size_t k = 0; k < scenario.t_s.size(); ++k) {
    for (std::size_t tag = 0; tag < scenario.p_world_tag_reported.size(); ++tag) {
      recording.poses.push_back({scenario.t_s[k], static_cast<int>(tag), scenario.p_world_tag_reported[tag][k]});
    }
  }
  for (const sim::SimRange& r : scenario.ranges) recording.ranges.push_back({r.t_s, r.tag_id, r.anchor_id, r.range_m, 0});
  for (const sim::SimAnchor& a : scenario.anchors) recording.anchors[a.id] = {a.p_world_anchor, a.bias_m};
  return recording;
}

void WriteRecording(ResultFolder& folder, const Recording& recording) {
  folder.Write("poses.csv", [&](std::ostream& out) { WritePoses(out, recording.poses); });
  folder.Write("ranges.csv", [&](std::ostream& out) { WriteRanges(out, recording.ranges); });
  folder.Write("anchors.csv", [&](std::ostream& out) { WriteAnchors(out, recording.anchors); });
}

void WriteRecordingFolder(const std::filesystem::path& folder, const Recording& recording, bool overwrite,
                          const std::vector<std::filesystem::path>& inputs) {
  ResultFolder::Options options;
  options.overwrite = overwrite;
  options.expected_bytes = 80 * (recording.poses.size() + recording.ranges.size()) + (1 << 16);  // ~60 B a row
  options.inputs = inputs;
  ResultFolder out(folder, options);
  WriteRecording(out, recording);
  out.Commit();
}

}  // namespace anchorbench::io
