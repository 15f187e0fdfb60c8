#include "anchorbench/experiments/hanyang.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/experiments/atomic_file.hpp"
#include "anchorbench/experiments/csv_reader.hpp"
#include "anchorbench/experiments/input_error.hpp"
#include "anchorbench/experiments/output_folder.hpp"

namespace anchorbench::experiments {
namespace {

constexpr double kTagAboveTrajectory_m = 1.0;  // the dataset's evaluation compares against z + 1.0
constexpr double kNanosecond = 1e-9;

struct Range {
  double stamp_ns;
  int anchor_id;
  double range_m;
};

}  // namespace

HanyangSummary ConvertHanyangCase(const std::filesystem::path& case_folder, const std::filesystem::path& out) {
  std::vector<std::filesystem::path> anchor_files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(case_folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 5 && name[0] == 'A' && entry.path().extension() == ".csv") anchor_files.push_back(entry.path());
  }
  if (error) throw InputError(case_folder.string() + ": cannot read the folder: " + error.message());
  std::sort(anchor_files.begin(), anchor_files.end());
  if (anchor_files.empty()) throw InputError(case_folder.string() + ": no anchor files (A<id>.csv)");

  std::vector<Range> ranges;
  std::map<int, Eigen::Vector3d> anchors;
  for (const auto& path : anchor_files) {
    CsvReader csv(path.string());
    const int stamp = csv.Column({"field.stamp"}), id = csv.Column({"field.id"});
    const int x = csv.Column({"field.x"}), y = csv.Column({"field.y"}), z = csv.Column({"field.z"});
    const int distance = csv.Column({"field.distanceFromTag"});
    while (csv.Next()) {
      const int anchor_id = csv.Integer(id);
      const Eigen::Vector3d p(csv.Number(x), csv.Number(y), csv.Number(z));
      const auto [it, inserted] = anchors.emplace(anchor_id, p);
      if (!inserted && (it->second - p).norm() > 1e-9) csv.Fail("anchor " + std::to_string(anchor_id) + " moved");
      const double range_m = csv.Number(distance);
      if (range_m < 0.0) csv.Fail("column 'field.distanceFromTag': negative range");
      ranges.push_back({csv.Number(stamp), anchor_id, range_m});
    }
  }
  std::stable_sort(ranges.begin(), ranges.end(), [](const Range& a, const Range& b) { return a.stamp_ns < b.stamp_ns; });

  CsvReader trajectory((case_folder / "trajectory.csv").string());
  const int t = trajectory.Column({"timestamp"});
  const int x = trajectory.Column({"x"}), y = trajectory.Column({"y"}), z = trajectory.Column({"z"});
  std::vector<std::pair<double, Eigen::Vector3d>> poses;
  HanyangSummary summary;
  while (trajectory.Next()) {
    const double stamp_ns = trajectory.Number(t);
    if (!poses.empty() && stamp_ns <= poses.back().first) {
      ++summary.dropped_poses;
      continue;
    }
    poses.emplace_back(stamp_ns, Eigen::Vector3d(trajectory.Number(x), trajectory.Number(y),
                                                 trajectory.Number(z) + kTagAboveTrajectory_m));
  }
  if (poses.empty() || ranges.empty()) throw InputError(case_folder.string() + ": no poses or no ranges");
  const double t0_ns = std::min(poses.front().first, ranges.front().stamp_ns);

  CreateFolder(out);
  AtomicFile poses_file(out / "poses.csv");
  poses_file.stream() << "t,tag_id,x,y,z\n";
  for (const auto& [stamp_ns, p] : poses) {
    poses_file.stream() << FormatNumber((stamp_ns - t0_ns) * kNanosecond) << ",0," << FormatNumber(p.x()) << ','
                        << FormatNumber(p.y()) << ',' << FormatNumber(p.z()) << '\n';
  }
  AtomicFile ranges_file(out / "ranges.csv");
  ranges_file.stream() << "t,tag_id,anchor_id,range\n";
  for (const Range& r : ranges) {
    ranges_file.stream() << FormatNumber((r.stamp_ns - t0_ns) * kNanosecond) << ",0," << r.anchor_id << ','
                         << FormatNumber(r.range_m) << '\n';
  }
  AtomicFile anchors_file(out / "anchors.csv");
  anchors_file.stream() << "anchor_id,x,y,z\n";
  for (const auto& [id, p] : anchors) {
    anchors_file.stream() << id << ',' << FormatNumber(p.x()) << ',' << FormatNumber(p.y()) << ','
                          << FormatNumber(p.z()) << '\n';
  }
  poses_file.Commit();
  ranges_file.Commit();
  anchors_file.Commit();
  summary.poses = static_cast<int>(poses.size());
  summary.ranges = static_cast<int>(ranges.size());
  summary.anchors = static_cast<int>(anchors.size());
  return summary;
}

}  // namespace anchorbench::experiments
