#include "anchorbench/io/recorded_data.hpp"

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/log_reader.hpp"

namespace anchorbench::io {

namespace {

LogPolicy Effective(LogPolicy policy, const LogDrops* drops) {
  if (drops == nullptr) policy.strict = true;
  return policy;
}

}  // namespace

std::vector<PoseRecord> ReadPoses(std::istream& in, const std::string& source, const LogPolicy& policy,
                                  LogDrops* drops) {
  LogDrops unused;
  PoseStream stream(in, source, Effective(policy, drops), drops ? *drops : unused);
  std::vector<PoseRecord> poses;
  for (PoseRecord pose; stream.Next(pose);) poses.push_back(pose);
  if (poses.empty()) throw schema::InputError(source + ": no poses");
  return poses;
}

std::vector<RangeRecord> ReadRanges(std::istream& in, const std::string& source, const LogPolicy& policy,
                                    LogDrops* drops) {
  LogDrops unused;
  RangeStream stream(in, source, 0, Effective(policy, drops), drops ? *drops : unused,
                     AnchorIdFromFileName(source), std::nullopt);
  std::vector<RangeRecord> ranges;
  for (RangeRecord range; stream.Next(range);) ranges.push_back(range);
  return ranges;
}

std::map<int, schema::AnchorTruth> ReadAnchors(std::istream& in, const std::string& source) {
  CsvReader csv(in, source);
  const int id = csv.Column({"anchor_id", "ID_Anchor"});
  const int x = csv.Column({"x"}), y = csv.Column({"y"}), z = csv.Column({"z"});
  const int bias = csv.OptionalColumn({"bias"});
  std::map<int, schema::AnchorTruth> anchors;
  while (csv.Next()) {
    const int anchor_id = csv.Integer(id);
    schema::AnchorTruth truth{Eigen::Vector3d(csv.Number(x), csv.Number(y), csv.Number(z)), std::nullopt};
    if (bias >= 0 && !csv.Empty(bias)) truth.bias_m = csv.Number(bias);
    if (!anchors.emplace(anchor_id, truth).second) csv.Fail("anchor " + std::to_string(anchor_id) + " listed twice");
  }
  if (anchors.empty()) throw schema::InputError(source + ": no anchors (a header alone?)");
  return anchors;
}

std::vector<PoseRecord> LoadPoses(const std::string& path, const LogPolicy& policy, LogDrops* drops) {
  std::ifstream in = OpenForReading(path);
  return ReadPoses(in, path, policy, drops);
}

std::vector<RangeRecord> LoadRanges(const std::string& path, const LogPolicy& policy, LogDrops* drops) {
  std::ifstream in = OpenForReading(path);
  return ReadRanges(in, path, policy, drops);
}

std::map<int, schema::AnchorTruth> LoadAnchors(const std::string& path) {
  std::ifstream in = OpenForReading(path);
  return ReadAnchors(in, path);
}

}  // namespace anchorbench::io
