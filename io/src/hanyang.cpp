#include "anchorbench/io/hanyang.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::io {
namespace {

constexpr double kTagAboveTrajectory_m = 1.0;  // the dataset's evaluation compares against z + 1.0
constexpr double kNanosecond = 1e-9;

struct StampedRange {
  double stamp_ns;
  int anchor_id;
  double range_m;
};

std::vector<std::filesystem::path> AnchorFiles(const std::filesystem::path& case_folder) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(case_folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 5 && name[0] == 'A' && entry.path().extension() == ".csv") files.push_back(entry.path());
  }
  if (error) throw schema::InputError(case_folder.string() + ": cannot read the folder: " + error.message());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw schema::InputError(case_folder.string() + ": no anchor files (A<id>.csv)");
  return files;
}

// Every anchor file's ranges, merged in stamp order, and each anchor's surveyed position.
std::vector<StampedRange> ReadAnchorFiles(const std::vector<std::filesystem::path>& files,
                                          std::map<int, schema::AnchorTruth>& anchors) {
  std::vector<StampedRange> ranges;
  for (const auto& path : files) {
    std::ifstream in = OpenForReading(path.string());
    CsvReader csv(in, path.string());
    const int stamp = csv.Column({"field.stamp"}), id = csv.Column({"field.id"});
    const int x = csv.Column({"field.x"}), y = csv.Column({"field.y"}), z = csv.Column({"field.z"});
    const int distance = csv.Column({"field.distanceFromTag"});
    while (csv.Next()) {
      const int anchor_id = csv.Integer(id);
      const Eigen::Vector3d p(csv.Number(x), csv.Number(y), csv.Number(z));
      const auto [it, inserted] = anchors.emplace(anchor_id, schema::AnchorTruth{p, std::nullopt});
      if (!inserted && (it->second.p_world_anchor - p).norm() > 1e-9) {
        csv.Fail("anchor " + std::to_string(anchor_id) + " moved");
      }
      const double range_m = csv.Number(distance);
      if (range_m < 0.0) csv.Fail("column 'field.distanceFromTag': negative range");
      ranges.push_back({csv.Number(stamp), anchor_id, range_m});
    }
  }
  std::stable_sort(ranges.begin(), ranges.end(),
                   [](const StampedRange& a, const StampedRange& b) { return a.stamp_ns < b.stamp_ns; });
  return ranges;
}

// The reference trajectory as tag poses (ns stamps, tag 1 m above it); non-increasing stamps dropped.
std::vector<PoseRecord> ReadTrajectory(const std::filesystem::path& path, int* dropped) {
  std::ifstream in = OpenForReading(path.string());
  CsvReader csv(in, path.string());
  const int t = csv.Column({"timestamp"});
  const int x = csv.Column({"x"}), y = csv.Column({"y"}), z = csv.Column({"z"});
  std::vector<PoseRecord> poses;
  while (csv.Next()) {
    const double stamp_ns = csv.Number(t);
    if (!poses.empty() && stamp_ns <= poses.back().t_s) {
      ++*dropped;
      continue;
    }
    poses.push_back({stamp_ns, 0, Eigen::Vector3d(csv.Number(x), csv.Number(y), csv.Number(z) + kTagAboveTrajectory_m)});
  }
  return poses;
}

}  // namespace

HanyangCase ConvertHanyangCase(const std::filesystem::path& case_folder) {
  HanyangCase converted;
  Recording& recording = converted.recording;
  const std::vector<StampedRange> stamped = ReadAnchorFiles(AnchorFiles(case_folder), recording.anchors);
  recording.poses = ReadTrajectory(case_folder / "trajectory.csv", &converted.dropped_poses);
  if (recording.poses.empty() || stamped.empty()) throw schema::InputError(case_folder.string() + ": no poses or no ranges");

  // Seconds since the case's earliest stamp.
  const double t0_ns = std::min(recording.poses.front().t_s, stamped.front().stamp_ns);
  for (PoseRecord& pose : recording.poses) pose.t_s = (pose.t_s - t0_ns) * kNanosecond;
  for (const StampedRange& r : stamped) {
    recording.ranges.push_back({(r.stamp_ns - t0_ns) * kNanosecond, 0, r.anchor_id, r.range_m, 0});
  }
  return converted;
}

}  // namespace anchorbench::io
