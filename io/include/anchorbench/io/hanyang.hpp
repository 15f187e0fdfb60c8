#pragma once

#include <filesystem>
#include <string>

#include "anchorbench/io/recorded_data.hpp"

namespace anchorbench::io {

// Converts one case folder of the Hanyang University outdoor UWB dataset (A3.csv, A5.csv,
// A9.csv, A12.csv: one per anchor, ns timestamps, surveyed anchor position on every row;
// trajectory.csv: RTK-GNSS reference) into a recording in the project's formats (WriteRecording).
// - Times are seconds since the case's earliest timestamp; ranges use the measurement stamp
//   (field.stamp) and are merged across anchors in time order.
// - The tag is 1 m above the reference trajectory (the dataset's own evaluation uses z + 1.0).
// - A trajectory timestamp that does not increase is dropped (counted).
struct HanyangCase {
  Recording recording;
  int dropped_poses = 0;  // trajectory rows whose timestamp did not increase
};
HanyangCase ConvertHanyangCase(const std::filesystem::path& case_folder);

}  // namespace anchorbench::io
