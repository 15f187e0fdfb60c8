#include "anchorbench/experiments/recorded_data.hpp"

#include <algorithm>

#include "anchorbench/experiments/csv_reader.hpp"
#include "anchorbench/experiments/input_error.hpp"

namespace anchorbench::experiments {

void PoseTracks::Add(int tag_id, double t_s, const Eigen::Vector3d& p_world_tag) {
  Track& track = tracks_[tag_id];
  track.t_s.push_back(t_s);
  track.p_world_tag.push_back(p_world_tag);
}

PoseTracks PoseTracks::Load(const std::string& path) {
  CsvReader csv(path);
  const int t = csv.Column({"t"});
  const int tag = csv.Column({"tag_id", "ID_Tag"});
  const int x = csv.Column({"x"}), y = csv.Column({"y"}), z = csv.Column({"z"});
  PoseTracks poses;
  while (csv.Next()) {
    const double t_s = csv.Number(t);
    const int tag_id = csv.Integer(tag);
    const auto found = poses.tracks_.find(tag_id);
    if (found != poses.tracks_.end() && t_s <= found->second.t_s.back()) {
      csv.Fail("time goes backwards or repeats for tag " + std::to_string(tag_id) + " (t=" + FormatNumber(t_s) +
               " after t=" + FormatNumber(found->second.t_s.back()) + ")");
    }
    poses.Add(tag_id, t_s, Eigen::Vector3d(csv.Number(x), csv.Number(y), csv.Number(z)));
  }
  if (poses.tracks_.empty()) throw InputError(path + ": no poses");
  return poses;
}

std::optional<Eigen::Vector3d> PoseTracks::At(int tag_id, double t_s) const {
  const auto found = tracks_.find(tag_id);
  if (found == tracks_.end()) return std::nullopt;
  const Track& track = found->second;
  if (t_s < track.t_s.front() || t_s > track.t_s.back()) return std::nullopt;
  const auto after = std::upper_bound(track.t_s.begin(), track.t_s.end(), t_s);
  if (after == track.t_s.end()) return track.p_world_tag.back();  // exactly the last pose
  const std::size_t i = static_cast<std::size_t>(after - track.t_s.begin());
  const double fraction = (t_s - track.t_s[i - 1]) / (track.t_s[i] - track.t_s[i - 1]);
  return track.p_world_tag[i - 1] + fraction * (track.p_world_tag[i] - track.p_world_tag[i - 1]);
}

std::vector<RangeRecord> LoadRanges(const std::string& path) {
  CsvReader csv(path);
  const int t = csv.Column({"t"});
  const int tag = csv.Column({"tag_id", "ID_Tag"});
  const int anchor = csv.Column({"anchor_id", "ID_Anchor"});
  const int range = csv.Column({"range"});
  std::vector<RangeRecord> ranges;
  while (csv.Next()) {
    RangeRecord r{csv.Number(t), csv.Integer(tag), csv.Integer(anchor), csv.Number(range), csv.line()};
    if (r.range_m < 0.0) csv.Fail("column 'range': negative range " + FormatNumber(r.range_m));
    if (!ranges.empty() && r.t_s < ranges.back().t_s) {
      csv.Fail("time goes backwards (t=" + FormatNumber(r.t_s) + " after t=" + FormatNumber(ranges.back().t_s) + ")");
    }
    ranges.push_back(r);
  }
  return ranges;
}

std::map<int, AnchorTruth> LoadAnchors(const std::string& path) {
  CsvReader csv(path);
  const int id = csv.Column({"anchor_id", "ID_Anchor"});
  const int x = csv.Column({"x"}), y = csv.Column({"y"}), z = csv.Column({"z"});
  const int bias = csv.OptionalColumn({"bias"});
  std::map<int, AnchorTruth> anchors;
  while (csv.Next()) {
    const int anchor_id = csv.Integer(id);
    AnchorTruth truth{Eigen::Vector3d(csv.Number(x), csv.Number(y), csv.Number(z)), std::nullopt};
    if (bias >= 0 && !csv.Empty(bias)) truth.bias_m = csv.Number(bias);
    if (!anchors.emplace(anchor_id, truth).second) csv.Fail("anchor " + std::to_string(anchor_id) + " listed twice");
  }
  return anchors;
}

}  // namespace anchorbench::experiments
