#pragma once

#include <filesystem>
#include <string>

namespace anchorbench::io {

// Converts one case folder of the Hanyang University outdoor UWB dataset (A3.csv, A5.csv,
// A9.csv, A12.csv: one per anchor, ns timestamps, surveyed anchor position on every row;
// trajectory.csv: RTK-GNSS reference) into the project's poses.csv, ranges.csv and anchors.csv.
// - Times are seconds since the case's earliest timestamp; ranges use the measurement stamp
//   (field.stamp) and are merged across anchors in time order.
// - The tag is 1 m above the reference trajectory (the dataset's own evaluation uses z + 1.0).
// - A trajectory timestamp that does not increase is dropped (reported in the summary).
struct HanyangSummary {
  int poses = 0;
  int ranges = 0;
  int anchors = 0;
  int dropped_poses = 0;
};
HanyangSummary ConvertHanyangCase(const std::filesystem::path& case_folder, const std::filesystem::path& out);

}  // namespace anchorbench::io
