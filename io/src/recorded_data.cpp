#include "anchorbench/io/recorded_data.hpp"

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/input_error.hpp"

namespace anchorbench::io {

std::vector<PoseRecord> ReadPoses(std::istream& in, const std::string& source) {
  CsvReader csv(in, source);
  const int t = csv.Column({"t"});
  const int tag = csv.Column({"tag_id", "ID_Tag"});
  const int x = csv.Column({"x"}), y = csv.Column({"y"}), z = csv.Column({"z"});
  std::vector<PoseRecord> poses;
  std::map<int, double> last_t_s;
  while (csv.Next()) {
    const double t_s = csv.Number(t);
    const int tag_id = csv.Integer(tag);
    const auto last = last_t_s.find(tag_id);
    if (last != last_t_s.end() && t_s <= last->second) {
      csv.Fail("time goes backwards or repeats for tag " + std::to_string(tag_id) + " (t=" + FormatNumber(t_s) +
               " after t=" + FormatNumber(last->second) + ")");
    }
    last_t_s[tag_id] = t_s;
    poses.push_back({t_s, tag_id, Eigen::Vector3d(csv.Number(x), csv.Number(y), csv.Number(z))});
  }
  if (poses.empty()) throw InputError(source + ": no poses");
  return poses;
}

std::vector<RangeRecord> ReadRanges(std::istream& in, const std::string& source) {
  CsvReader csv(in, source);
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

std::map<int, eval::AnchorTruth> ReadAnchors(std::istream& in, const std::string& source) {
  CsvReader csv(in, source);
  const int id = csv.Column({"anchor_id", "ID_Anchor"});
  const int x = csv.Column({"x"}), y = csv.Column({"y"}), z = csv.Column({"z"});
  const int bias = csv.OptionalColumn({"bias"});
  std::map<int, eval::AnchorTruth> anchors;
  while (csv.Next()) {
    const int anchor_id = csv.Integer(id);
    eval::AnchorTruth truth{Eigen::Vector3d(csv.Number(x), csv.Number(y), csv.Number(z)), std::nullopt};
    if (bias >= 0 && !csv.Empty(bias)) truth.bias_m = csv.Number(bias);
    if (!anchors.emplace(anchor_id, truth).second) csv.Fail("anchor " + std::to_string(anchor_id) + " listed twice");
  }
  return anchors;
}

std::vector<PoseRecord> LoadPoses(const std::string& path) {
  std::ifstream in = OpenForReading(path);
  return ReadPoses(in, path);
}

std::vector<RangeRecord> LoadRanges(const std::string& path) {
  std::ifstream in = OpenForReading(path);
  return ReadRanges(in, path);
}

std::map<int, eval::AnchorTruth> LoadAnchors(const std::string& path) {
  std::ifstream in = OpenForReading(path);
  return ReadAnchors(in, path);
}

}  // namespace anchorbench::io
